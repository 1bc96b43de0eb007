package org.fclcert.iut.spi;

import java.util.Objects;
import java.util.OptionalInt;

/** The answer to {@link FclImplementation#load}: a loaded program, or a rejection with its reason. */
public sealed interface FclLoadResult {

    /** The program was accepted. */
    record Loaded(FclProgram program) implements FclLoadResult {
        public Loaded {
            Objects.requireNonNull(program, "program");
        }
    }

    /** The program was refused; {@code line} is the 1-based line of the first error, when known. */
    record Rejected(String message, OptionalInt line) implements FclLoadResult {
        public Rejected {
            Objects.requireNonNull(message, "message");
            Objects.requireNonNull(line, "line");
        }
    }

    static FclLoadResult loaded(FclProgram program) {
        return new Loaded(program);
    }

    /** A rejection at a 1-based line of the text given to {@code load}. */
    static FclLoadResult rejected(String message, int line) {
        return new Rejected(message, line > 0 ? OptionalInt.of(line) : OptionalInt.empty());
    }

    /** A rejection without a line. */
    static FclLoadResult rejected(String message) {
        return new Rejected(message, OptionalInt.empty());
    }
}
