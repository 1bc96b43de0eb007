package org.fclcert.harness;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fclcert.corpus.ExpectedError;
import org.fclcert.corpus.Vector;
import org.fclcert.model.ConformanceLevel;

/**
 * One corpus case as the runner needs it: the program text without its metadata comment (line numbers
 * kept), either the expected rejection or the ordered steps, and the tolerance resolved for this program.
 * {@link RunCases#from} builds it from a corpus case.
 */
public record RunCase(
        String id,
        String title,
        ConformanceLevel level,
        List<String> features,
        List<String> tests,
        List<String> flags,
        Optional<String> block,
        List<Vector> vectors,
        Optional<ExpectedError> expectedError,
        OutputTolerance tolerance,
        String program,
        String source) {

    public RunCase {
        Objects.requireNonNull(id, "id");
        features = List.copyOf(features);
        tests = List.copyOf(tests);
        flags = List.copyOf(flags);
        vectors = List.copyOf(vectors);
    }

    /** A negative case: the program must be rejected. */
    public boolean expectReject() {
        return expectedError.isPresent();
    }

    /** Stateful cases depend on the order of their steps, so the reverse-order rerun does not apply. */
    public boolean stateful() {
        return Flags.stateful(flags);
    }

    /** Cases that depend on a reading of the standard ({@code interpretation:<point>}) count against no verdict. */
    public boolean interpretation() {
        return Flags.interpretation(flags).isPresent();
    }

    /** What the report needs to know about a case before (or without) running it. */
    public PlannedCase plan() {
        return new PlannedCase(id, title, level.word(), tests, flags);
    }
}
