package org.fclcert.corpus;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.fclcert.check.Analysis;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Diagnostic;

/**
 * Which corpus a run used: the fclcert conformance corpus built into this fclcert, or a custom one. A verdict of a
 * conformance level speaks of the built-in corpus: a custom corpus earns one only when it holds every built-in case
 * of that level unchanged ({@link #missingBuiltIn}). Before a custom corpus is run, each of its cases is checked
 * with the exact reference as lint does ({@link #unreproduced}), so that no implementation can be certified
 * against expected values the standard does not give.
 */
public final class CorpusIdentity {
    private CorpusIdentity() {
    }

    /** The built-in corpus, or null when this build carries none. */
    public static Corpus builtIn() {
        try {
            return BundledCorpus.load();
        } catch (CorpusException e) {
            return null;
        }
    }

    /** Whether {@code corpus} is the built-in corpus (the same digest). */
    public static boolean isBuiltIn(Corpus corpus, Corpus builtIn) {
        return builtIn != null && builtIn.sha256().equals(corpus.sha256());
    }

    /**
     * The ids of the built-in cases of {@code level} (not flagged interpretation, negative ones included) that {@code corpus}
     * does not hold unchanged (same program, vectors, expected error, tolerance and flags); every built-in id when
     * there is no built-in corpus to compare with is not known, so then the answer is a one-element list saying so.
     */
    public static List<String> missingBuiltIn(Corpus corpus, Corpus builtIn, ConformanceLevel level) {
        if (builtIn == null) {
            return List.of("(this build carries no built-in corpus)");
        }
        Map<String, CorpusCase> mine = corpus.cases().stream()
                .collect(Collectors.toMap(CorpusCase::id, Function.identity(), (a, b) -> a));
        List<String> missing = new ArrayList<>();
        for (CorpusCase c : builtIn.cases()) {
            if (c.level() != level || c.interpretation().isPresent()) {
                continue;
            }
            CorpusCase other = mine.get(c.id());
            if (other == null || !sameCase(c, other)) {
                missing.add(c.id());
            }
        }
        return missing;
    }

    private static boolean sameCase(CorpusCase a, CorpusCase b) {
        return a.programText().equals(b.programText()) && a.vectors().equals(b.vectors())
                && Objects.equals(a.expectedError(), b.expectedError()) && a.tolerance() == b.tolerance()
                && a.flags().equals(b.flags()) && a.level() == b.level() && a.block().equals(b.block())
                && a.dialect() == b.dialect();
    }

    /**
     * Every case whose expectation the exact reference does not reproduce: a positive case whose program has an
     * error or whose vectors the reference evaluator does not give (in order, and in reverse unless stateful), a
     * negative case whose program has no error of the declared code at the declared line. Each problem names its
     * case file.
     */
    public static List<CorpusProblem> unreproduced(Corpus corpus) {
        List<CorpusProblem> problems = new ArrayList<>();
        for (CorpusCase c : corpus.cases()) {
            Analysis analysis = Analysis.analyze(c.reader(), c.path().toString(), c.programText());
            if (c.expectReject()) {
                ExpectedError want = c.expectedError().orElseThrow();
                boolean found = analysis.diagnostics().stream().filter(Diagnostic::isError)
                        .anyMatch(d -> d.code().equals(want.code()) && d.location().line() == want.line());
                if (!found) {
                    problems.add(new CorpusProblem(c.path(), 1, "case " + c.id() + ": the reference finds no "
                            + want.code() + " at line " + want.line() + ", which the case expects"));
                }
                continue;
            }
            if (analysis.program().isEmpty() || analysis.diagnostics().stream().anyMatch(Diagnostic::isError)) {
                problems.add(new CorpusProblem(c.path(), 1, "case " + c.id() + ": the program of a positive case has an"
                        + " error for the reference"));
                continue;
            }
            for (String m : VectorReplay.check(c, analysis.program().get())) {
                problems.add(new CorpusProblem(c.path(), 1, "case " + c.id() + ": the reference does not reproduce"
                        + " its expected values: " + m));
            }
        }
        return problems;
    }
}
