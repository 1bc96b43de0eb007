package org.fclcert.probe;

import java.util.List;
import java.util.Map;

/**
 * One generated program and the evaluations that judge it: the vectors are sent in order to one
 * instance (inputs not named keep their values), and every output must agree with what the reference
 * evaluator computes for the same sequence. {@code expectedFrom} is the program whose reference
 * evaluation gives the expected outputs: the program itself, or a comment-free twin when the program
 * is about a form the reference does not read.
 */
record ProbeProgram(String fcl, List<Map<String, Double>> vectors, String expectedFrom) {
    ProbeProgram {
        vectors = List.copyOf(vectors);
    }

    ProbeProgram(String fcl, List<Map<String, Double>> vectors) {
        this(fcl, vectors, fcl);
    }
}
