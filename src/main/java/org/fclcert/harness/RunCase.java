package org.fclcert.harness;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.corpus.ExpectedError;
import org.fclcert.corpus.Vector;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.dialect.Dialect;

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
        String source,
        Dialect dialect) {

    public RunCase {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(dialect, "dialect");
        features = List.copyOf(features);
        tests = List.copyOf(tests);
        flags = List.copyOf(flags);
        vectors = List.copyOf(vectors);
    }

    /** A case in standard FCL ({@link Dialect#STRICT}). */
    public RunCase(String id, String title, ConformanceLevel level, List<String> features, List<String> tests,
            List<String> flags, Optional<String> block, List<Vector> vectors, Optional<ExpectedError> expectedError,
            OutputTolerance tolerance, String program, String source) {
        this(id, title, level, features, tests, flags, block, vectors, expectedError, tolerance, program, source,
                Dialect.STRICT);
    }

    /** The reader of the case's program (the corpus's one reading of a dialect, {@link CorpusCase#reader(Dialect)}). */
    public FclReader reader() {
        return CorpusCase.reader(dialect);
    }

    /** Whether the program is written in a library's dialect ({@code dialect:} in the case's metadata). */
    public boolean inDialect() {
        return dialect != Dialect.STRICT;
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
