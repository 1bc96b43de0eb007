package org.fclcert.corpus;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * One step of a case: the inputs to set, then either the outputs expected after one evaluation, or the evaluation
 * error the step must end in ({@link #error()}: an {@code FCL-Vnnn} code, e.g. a value that does not fit its integer
 * output's type; conformance/README.md, "Steps that must be refused"). Both maps keep the order in which the case
 * file lists the names.
 */
public record Vector(Map<String, Double> in, Map<String, Double> out, Optional<String> error) {
    public Vector {
        in = Collections.unmodifiableMap(new LinkedHashMap<>(in));
        out = Collections.unmodifiableMap(new LinkedHashMap<>(out));
        Objects.requireNonNull(error, "error");
        if (error.isPresent() && !out.isEmpty()) {
            throw new IllegalArgumentException("a step that must be refused expects no outputs");
        }
    }

    /** A step with expected outputs. */
    public Vector(Map<String, Double> in, Map<String, Double> out) {
        this(in, out, Optional.empty());
    }

    /** A step the evaluation must refuse with {@code code}. */
    public static Vector refused(Map<String, Double> in, String code) {
        return new Vector(in, Map.of(), Optional.of(code));
    }

    /** Whether the step must end in an evaluation error rather than outputs. */
    public boolean refused() {
        return error.isPresent();
    }
}
