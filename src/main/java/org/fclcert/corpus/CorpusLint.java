package org.fclcert.corpus;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.check.FeatureReport;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FairVectors;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Program;

/**
 * Keeps the corpus and the toolkit in agreement. For every case: valid metadata; id unique, equal to the
 * file name, not retired, in the directory of its level; {@code level} and {@code features} exactly what the
 * feature detector finds; {@code tests} within {@code features}; a positive case analyses without error and
 * the reference evaluator reproduces every vector (also replayed in reverse on a fresh instance unless it
 * is flagged {@code stateful}); a negative case has exactly one error, with the declared code and line.
 * Then coverage: see {@link CoverageRules}.
 */
public final class CorpusLint {
    /** The file listing retired ids, one per line (text after the id is the reason; '#' starts a comment). */
    public static final String RETIRED_FILE = "RETIRED";

    private final FeatureDetector detector = new FeatureDetector();

    /** Lints the corpus under {@code dir}. */
    public LintReport lint(Path dir) {
        Corpus.Scan scan = Corpus.scan(dir);
        List<CorpusProblem> findings = new ArrayList<>(scan.problems());
        Set<String> retired = retiredIds(dir, findings);
        for (CorpusCase c : scan.cases()) {
            new CaseLint(c, dir, retired, findings).run();
        }
        findings.sort(null);
        List<CorpusCase> cases = scan.cases();
        int negative = (int) cases.stream().filter(CorpusCase::expectReject).count();
        return new LintReport(cases.size(), cases.size() - negative, negative, findings,
                CoverageRules.gaps(cases));
    }

    private static Set<String> retiredIds(Path dir, List<CorpusProblem> findings) {
        Path file = dir.resolve(RETIRED_FILE);
        Set<String> ids = new LinkedHashSet<>();
        if (!Files.isRegularFile(file)) {
            return ids;
        }
        try {
            String retired = new String(org.fclcert.model.Limits.readFile(file), java.nio.charset.StandardCharsets.UTF_8);
            for (String line : retired.lines().toList()) {
                String text = line.replaceFirst("#.*", "").strip();
                if (!text.isEmpty()) {
                    ids.add(text.split("\\s+")[0]);
                }
            }
        } catch (IOException e) {
            findings.add(new CorpusProblem(file, 0, "cannot read the retired ids: " + e.getMessage()));
        }
        return ids;
    }

    /** The checks of one case. */
    private final class CaseLint {
        private final CorpusCase c;
        private final Path dir;
        private final Set<String> retired;
        private final List<CorpusProblem> findings;

        CaseLint(CorpusCase c, Path dir, Set<String> retired, List<CorpusProblem> findings) {
            this.c = c;
            this.dir = dir;
            this.retired = retired;
            this.findings = findings;
        }

        void run() {
            identity();
            if (!c.features().containsAll(c.tests())) {
                List<String> extra = ids(c.tests().stream().filter(f -> !c.features().contains(f)).toList());
                finding(1, "'tests' names features the case does not use: " + extra);
            }
            // standard FCL plus the Open Level methods, or the case's dialect (CorpusCase#reader)
            Analysis analysis = Analysis.analyze(c.reader(), c.path().toString(), c.programText());
            if (c.expectReject()) {
                negative(analysis);
            } else {
                positive(analysis);
            }
        }

        private void identity() {
            String fileName = c.path().getFileName().toString();
            if (!fileName.equals(c.id() + ".fcl")) {
                finding(1, "id " + c.id() + " does not match the file name " + fileName);
            }
            if (retired.contains(c.id())) {
                finding(1, "id " + c.id() + " is retired (conformance/RETIRED); retired ids are never reused");
            }
            String expectedDir = c.expectReject() ? "negative" : c.level().word();
            Path parent = dir.relativize(c.path()).getParent();
            if (parent == null || !parent.toString().equals(expectedDir)) {
                finding(1, (c.expectReject() ? "a negative case" : "a " + c.level().word() + " case")
                        + " belongs in the directory " + expectedDir + "/");
            }
            char prefix = c.expectReject() ? 'N' : c.level().word().toUpperCase(Locale.ROOT).charAt(0);
            if (!c.id().isEmpty() && c.id().charAt(0) != prefix) {
                finding(1, "id " + c.id() + " should start with " + prefix + "- for a "
                        + (c.expectReject() ? "negative" : c.level().word()) + " case");
            }
        }

        private void positive(Analysis analysis) {
            if (c.level() == ConformanceLevel.BASIC && c.derivation().isEmpty()) {
                finding(1, "a Basic case needs a 'derivation' showing how the expected numbers were obtained");
            }
            List<Diagnostic> errors = errors(analysis);
            if (!errors.isEmpty() || analysis.program().isEmpty()) {
                errors.forEach(d -> finding(d.location().line(), "the program of a positive case has an error: " + d));
                return;
            }
            Program program = analysis.program().get();
            features(program);
            integratedOutputsAreContinuous(program);
            refusedSteps();
            List<String> wrong = VectorReplay.check(c, program);
            if (!wrong.isEmpty()) {
                int line = vectorsLine();
                wrong.forEach(m -> finding(line, m));
            }
            fairness(program);
        }

        /**
         * Steps that must be refused (conformance/README.md): not in a stateful case, whose next step would start from
         * a state the standard does not define after a failed evaluation; and not every step, so that the case's
         * fresh vectors have outputs to compare.
         */
        private void refusedSteps() {
            long refused = c.vectors().stream().filter(Vector::refused).count();
            if (refused > 0 && c.stateful()) {
                finding(vectorsLine(), "a stateful case cannot expect a step to be refused: the state after a refused"
                        + " evaluation is not defined");
            }
            if (refused > 0 && refused == c.vectors().size()) {
                finding(vectorsLine(), "every step expects an evaluation error: a case needs a step with outputs too");
            }
        }

        /**
         * Every vector is fair to judge (FairVectors, docs/semantics.md point 10) unless the case flags it
         * {@code knife-edge:<n>}; a flagged vector must really be one, and a case needs one fair vector.
         */
        private void fairness(Program program) {
            int[] line = {0};   // the vectors' line, read once and only when there is a finding
            java.util.function.IntSupplier at = () -> line[0] > 0 ? line[0] : (line[0] = vectorsLine());
            LoadedProgram loaded = Evaluator.load(program);
            OutputScales scales = OutputScales.of(blockOf(c, program));
            if (c.inDialect() && !VectorReplay.exactPathEvaluates(loaded, c)) {
                // Takagi-Sugeno terms, Tsukamoto's method, hedges in conclusions: only the reference's double path with
                // its bounds evaluates them (ExactInstance refuses), so there is no second arithmetic to nudge; the
                // vectors are judged by that path alone (conformance/README.md, "Open Level methods and dialects")
                return;
            }
            FairVectors.Verdict verdict;
            try {
                verdict = FairVectors.judge(loaded, c.block().orElse(null),
                        c.vectors().stream().map(Vector::in).toList(),
                        (out, a, b) -> c.tolerance().compare(out, a, b, scales.width(out)).passed());
            } catch (IllegalArgumentException e) {
                finding(at.getAsInt(), "the vectors cannot be judged for fairness: " + e.getMessage());
                return;
            }
            java.util.SortedSet<Integer> flagged = c.knifeEdges();
            for (FairVectors.KnifeEdge k : verdict.knifeEdges()) {
                if (!flagged.contains(k.step())) {
                    finding(at.getAsInt(), "vector " + k.step() + " is a knife edge, not fair to judge: " + k
                            + "; move the inputs off the tie, or flag the case knife-edge:" + k.step());
                }
            }
            for (int step : flagged) {
                if (step > c.vectors().size()) {
                    finding(1, "flag knife-edge:" + step + " names a vector the case does not have");
                } else if (verdict.fair(step)) {
                    finding(1, "flag knife-edge:" + step + ", but vector " + step + " is fair to judge; remove the flag");
                }
            }
            if (!c.vectors().isEmpty() && flagged.size() >= c.vectors().size()) {
                finding(at.getAsInt(), "every vector is flagged knife-edge: a case needs at least one fair vector");
            }
        }

        private void negative(Analysis analysis) {
            // with a semantic (not a syntax) error the reader still gives a program, whose features can be checked
            c.reader().read(c.path().toString(), c.programText()).program().ifPresent(this::features);
            List<Diagnostic> errors = errors(analysis);
            ExpectedError want = c.expectedError().orElseThrow();
            if (errors.size() != 1) {
                finding(want.line(), "a negative case must have exactly one error, the analysis found "
                        + errors.size() + (errors.isEmpty() ? "" : ": " + errors));
                return;
            }
            Diagnostic got = errors.get(0);
            if (!got.code().equals(want.code()) || got.location().line() != want.line()) {
                finding(want.line(), "expected error " + want.code() + " at line " + want.line() + ", the analysis found "
                        + got);
            }
        }

        private void features(Program program) {
            FeatureReport report = detector.detect(program);
            Set<Feature> detected = new LinkedHashSet<>();
            report.uses().stream().map(FeatureUse::feature).forEach(detected::add);
            List<FeatureUse> undeclared = report.uses().stream()
                    .filter(u -> !c.features().contains(u.feature())).toList();
            Set<Feature> reportedOnce = new LinkedHashSet<>();
            for (FeatureUse u : undeclared) {
                if (reportedOnce.add(u.feature())) {
                    finding(u.location().line(), "the program uses " + u.feature().id() + " (" + u.feature().description()
                            + ") here, but 'features' does not declare it");
                }
            }
            for (Feature f : c.features()) {
                if (!detected.contains(f)) {
                    finding(1, "'features' declares " + f.id() + " but the feature detector does not find it in the program");
                }
            }
            if (report.level() != c.level()) {
                finding(1, "level is " + c.level().word() + " but the program's features make it " + report.level().word());
            }
        }

        /**
         * An output defuzzified by CoG, CoA, LM or RM over point terms is judged {@code continuous}
         * (conformance/README.md, "Tolerance"): an implementation that integrates or samples correctly misses the
         * exact value by more than {@code exact} allows, and a case judged exactly would fail it for that alone.
         */
        private void integratedOutputsAreContinuous(Program program) {
            if (c.tolerance() != Tolerance.EXACT) {
                return;
            }
            FunctionBlock block = blockOf(c, program);
            OutputScales scales = OutputScales.of(block);
            for (Defuzzification d : block.defuzzifications()) {
                DefuzzificationMethod m = d.method().map(Located::value).orElse(null);
                boolean integrated = m == DefuzzificationMethod.COG || m == DefuzzificationMethod.COA
                        || m == DefuzzificationMethod.LM || m == DefuzzificationMethod.RM;
                boolean points = d.terms().stream().anyMatch(t -> t.function() instanceof MembershipFunction.Points);
                if (integrated && points && scales.width(d.variable()).isPresent()) {
                    finding(1, "output '" + d.variable() + "' is defuzzified by " + m.keyword() + " over point terms: "
                            + "its tolerance must be continuous, not exact (conformance/README.md, Tolerance)");
                }
            }
        }

        /** The line of {@code vectors:} in the case file (1 if none); a file that cannot be read again is a finding. */
        private int vectorsLine() {
            List<String> lines;
            try {
                lines = Files.readAllLines(c.path());
            } catch (IOException | RuntimeException e) {   // read once already: a race or a disk fault, never ignored
                finding(1, "cannot read the case file again to place its vector findings ("
                        + e.getClass().getSimpleName() + ": " + e.getMessage() + "); they are shown at line 1");
                return 1;
            }
            for (int i = 0; i < lines.size(); i++) {
                if (lines.get(i).startsWith("vectors:")) {
                    return i + 1;
                }
            }
            return 1;
        }

        private void finding(int line, String message) {
            findings.add(new CorpusProblem(c.path(), line, message));
        }
    }

    private static List<Diagnostic> errors(Analysis analysis) {
        return analysis.diagnostics().stream().filter(Diagnostic::isError).toList();
    }

    private static List<String> ids(List<Feature> features) {
        return features.stream().map(Feature::id).toList();
    }

    /** The function block a case instantiates: its {@code block}, else the first. */
    static FunctionBlock blockOf(CorpusCase c, Program program) {
        return c.block().flatMap(program::functionBlock).orElse(program.functionBlocks().get(0));
    }
}
