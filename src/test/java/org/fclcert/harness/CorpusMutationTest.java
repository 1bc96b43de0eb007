package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusException;
import org.fclcert.iut.CompiledReference;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The conformance corpus as a test of the reference evaluator: every case of {@code conformance/} is run on
 * {@code reference} by the harness's own {@link Runner} with the reference export check, exactly as
 * {@code fclcert certify --iut reference} judges it (tolerance, knife edges not judged, the reverse-order rerun,
 * negative cases), and must pass. It is the only test of the {@code mutation} profile (pom.xml, PIT): a
 * mutant of {@code org.fclcert.eval} is killed only when the corpus alone tells it apart.
 *
 * <p>Each positive case is judged a second time on instances that take the compiled kernel ({@code KernelCompiler})
 * from their first evaluation ({@code LoadedProgram.newCompiledInstance}): certify's reference takes it only at an
 * instance's 65th evaluation, which only the two 65-step cases (B-DEFAULT-VALUE-141, E-COG-141) reach, so without this
 * judgement almost no kernel mutant could fail a case. A block the kernel does not cover stays interpreted there (the
 * judgement then repeats the first).
 *
 * <p>The export check is not run ({@link #EXPORT_NOT_JUDGED}): its verdict is not part of the status asserted here,
 * and it evaluates the exported text on the exact path, so it made every case cover {@code ExactInstance} and each
 * surviving mutant cost the exact evaluation of every case's vectors on top of the judged ones.
 */
class CorpusMutationTest {
    private static final Path CORPUS = Path.of("conformance");
    private static final ExportCheck EXPORT_NOT_JUDGED =
            (text, c) -> new ExportCheck.Verdict(ExportStatus.NOT_RUN, "not judged by the mutation test");

    /**
     * The corpus, read once per JVM. PIT runs every case as a test of its own, and JUnit builds the whole argument list
     * again for each; reading the 387 case files each time cost a surviving mutant, run against some 700 judgements,
     * over a minute of reading alone. The cases are immutable. Reading them uses one class of {@code org.fclcert.eval},
     * {@code EvaluationCode} (the codes a refused step may name): its mutants are then judged by the cases' evaluations
     * only, not by a corpus that no longer reads.
     */
    private static List<RunCase> read;

    private static synchronized List<RunCase> cases() throws CorpusException {
        if (read == null) {
            read = RunCases.from(Corpus.load(CORPUS).cases());
        }
        return read;
    }

    static Stream<Arguments> corpusCases() throws CorpusException {
        List<RunCase> cases = cases();
        assertFalse(cases.isEmpty(), "the corpus has cases");
        return cases.stream().map(c -> Arguments.of(c.id(), c));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("corpusCases")
    void referencePassesTheCase(String id, RunCase c) throws IOException, IutException {
        try (ImplementationUnderTest reference = Iuts.open("reference", IutOptions.defaults())) {
            CaseResult result = runOne(reference, c);
            assertEquals(CaseStatus.PASSED, result.status(), () -> c.id() + ": " + result.message());
        }
    }

    static Stream<Arguments> positiveCases() throws CorpusException {
        return corpusCases().filter(a -> ((RunCase) a.get()[1]).expectedError().isEmpty());
    }

    @ParameterizedTest(name = "{0} on the compiled kernel")
    @MethodSource("positiveCases")
    void referenceOnTheKernelPassesTheCase(String id, RunCase c) throws IOException, IutException {
        try (ImplementationUnderTest reference = CompiledReference.open()) {
            CaseResult result = runOne(reference, c);
            assertEquals(CaseStatus.PASSED, result.status(), () -> c.id() + " on the compiled kernel: " + result.message());
        }
    }

    private static CaseResult runOne(ImplementationUnderTest iut, RunCase c) throws IOException, IutException {
        List<RunCase> one = List.of(c);
        var info = iut.hello();
        RunHeader header = RunHeaders.of(info, info.command(), null, CORPUS.toString(), "", one, one,
                List.of(List.of(), List.of(), List.of()));
        List<CaseResult> results = new Runner(EXPORT_NOT_JUDGED, RunListener.NONE).run(iut, header, one, new ResultSink() {
            @Override
            public void header(RunHeader h) {
            }

            @Override
            public void accept(CaseResult result) {
            }
        });
        assertEquals(1, results.size());
        return results.get(0);
    }
}
