package org.fclcert.iut.spi;

import java.util.List;
import java.util.Map;

/**
 * A Java FCL implementation. One object serves one certification run; fclcert calls it from one
 * thread at a time (not necessarily always the same thread).
 */
public interface FclImplementation {

    /** The product name shown in reports. */
    String name();

    /** The product version shown in reports. */
    String version();

    /**
     * The feature ids of clause 6 (for example {@code B-COGS}, {@code E-OR-BSUM}, {@code O-MANY-POINTS})
     * the implementation says it realises. The report sets these claims against the measured results.
     */
    default List<String> claims() {
        return List.of();
    }

    /**
     * Limits the implementation declares, by the ids of the Table 11 data check list (for example
     * {@code max-rules-per-block}, {@code max-points-per-input-term}, {@code max-nesting-depth}; every id is
     * listed in {@code docs/data-check-list.md}, matched ignoring case). {@code fclcert probe} and
     * {@code certify} put each declared limit next to the measured one and flag a measured limit below it;
     * a limit under any other name is kept in the report's header but compared with nothing.
     */
    default Map<String, Long> limits() {
        return Map.of();
    }

    /**
     * Reads and prepares a program. A program the implementation does not accept must come back as
     * {@link FclLoadResult#rejected(String, int)} with the line of the first error; throwing is reported
     * as a crash.
     *
     * <p>Many libraries signal every refusal by throwing. An adapter for one must turn into a rejection only
     * the exceptions the library throws on purpose (its own exception type, its parser's exceptions) and let
     * everything else propagate: catching {@code Exception} wholesale would make a {@code NullPointerException}
     * or an {@code ArrayIndexOutOfBoundsException} inside the library — a bug — look like a clean rejection,
     * and a negative case would pass for the wrong reason. fclcert's own adapters show how
     * ({@code docs/iut-protocol.md}, "jfuzzylite" and "jFuzzyLogic").
     */
    FclLoadResult load(String fcl);
}
