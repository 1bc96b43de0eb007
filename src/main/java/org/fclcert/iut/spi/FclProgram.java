package org.fclcert.iut.spi;

import java.util.List;
import java.util.Optional;

/** A loaded FCL program. */
public interface FclProgram {

    /** The function block names, in the order they are written. */
    List<String> blocks();

    /**
     * A fresh instance of one function block (its name as written, or in any letter case), with every
     * variable at its initial state. Throwing is reported as a crash.
     */
    FclInstance newInstance(String block);

    /** The program written back as FCL text, when the implementation can do so (clause 6 e). */
    default Optional<String> export() {
        return Optional.empty();
    }
}
