package org.fclcert.iut.spi;

import java.util.List;
import java.util.Optional;

/** A loaded FCL program. */
public interface FclProgram {

    /** The function block names, in the order they are written. */
    List<String> blocks();

    /**
     * A fresh instance of one function block (its name as written, or in any letter case). It starts as the
     * standard says a new instance does: every input and output at its declared initial value ({@code x : REAL
     * := 1.5}), or else at the initial value of its data type (0 for REAL and the integer types), and every
     * {@code DEFAULT NC} output at that value until a rule first fires. The harness may evaluate without setting
     * every input, so a library that starts its variables elsewhere (jfuzzylite and jFuzzyLogic start at NaN)
     * shows as wrong values, as it should. Throwing is reported as a crash.
     */
    FclInstance newInstance(String block);

    /** The program written back as FCL text, when the implementation can do so (clause 6 e). */
    default Optional<String> export() {
        return Optional.empty();
    }
}
