package org.fclcert.fuzz;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.fclcert.corpus.Tolerance;
import org.fclcert.eval.Trace;
import org.fclcert.iut.Fuzzylite;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.iut.JFuzzyLogic;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fclcert fuzz} on the real libraries, each in its own layout ({@code --present-as auto}), finds their known
 * deviations (docs/peers.md) within a short fixed-seed run, and shrinks each to a small case. A finding counts as
 * known only when a model of the deviation, independent of the fuzzer, gives the library's answer on the minimal
 * case: CoGS summed per rule, NSUM computed as BSUM, RM answered as LM, NaN before the first firing under NC, a rule of
 * degree at most 1e-6 taken as not fired — or when fclcert's writer for the library predicts it for that case
 * (its FCL-X2nn notes: sampling, weight before activation, a vertical edge). Outside CI a missing library skips;
 * with {@code CI} set it fails.
 */
class FuzzFindsLibraryDeviationsTest {
    private static final SourceLocation AT = SourceLocation.UNKNOWN;

    @Test
    void fuzzyliteSumsCogsPerRule(@TempDir Path dir) throws Exception {
        Fuzzylite.assumeInstalled();
        assertKnown("fuzzylite", Fuzzylite.options(), new FuzzSettings(ConformanceLevel.BASIC, Set.of()), dir);
    }

    @Test
    void jfuzzyliteInItsLayout(@TempDir Path dir) throws Exception {
        assertKnown("jfuzzylite", IutOptions.defaults().withTimeout(Duration.ofSeconds(20)),
                new FuzzSettings(ConformanceLevel.EXTENSION, Set.of(Feature.E_WITH_CONST)), dir);
    }

    @Test
    void jfuzzylogicInItsLayout(@TempDir Path dir) throws Exception {
        assertKnown(JFuzzyLogic.spec(), IutOptions.defaults().withTimeout(Duration.ofSeconds(20)),
                new FuzzSettings(ConformanceLevel.EXTENSION, Set.of(Feature.E_ACCU_NSUM)), dir);
    }

    private static void assertKnown(String spec, IutOptions iut, FuzzSettings settings, Path dir) throws Exception {
        Optional<Dialect> layout = org.fclcert.orchestration.PresentAs.AUTO.resolve(spec);
        // a minute to find it; shrinking is given up to 90 s, so that a loaded CI machine still gets a small case
        Fuzzer.Options options = new Fuzzer.Options(3, Duration.ofSeconds(60), 0, settings, 1, Duration.ofSeconds(90), 40,
                1, layout);
        Fuzzer.Result result = new Fuzzer().run(() -> Iuts.open(spec, iut), options, Duration.ofSeconds(10), p -> { });
        assertFalse(result.findings().isEmpty(), spec + ": nothing found in " + result.progress());
        List<FuzzReport.Written> written = FuzzReport.write(result, dir);
        for (FuzzReport.Written w : written) {
            Finding f = w.finding();
            Optional<String> why = known(f, new Presentation(layout));
            assertTrue(why.isPresent(), spec + ": " + f.key() + " is not a known deviation: " + f.deviation().message()
                    + "\n" + java.nio.file.Files.readString(w.file()));
            assertTrue(w.programLines() <= 25, spec + ": " + w.programLines() + " lines");
            System.out.printf("%s: %s after %.1f s (program %d), %d lines: %s%n", spec, f.key(),
                    f.foundAfterMillis() / 1000.0, f.programIndex(), w.programLines(), why.get());
            FuzzFindsSingleDefectsTest.assertCaseLints(w, dir);
        }
    }

    /** The model that gives the library's answer on the minimal case, or the writer's note that predicts it. */
    static Optional<String> known(Finding f, Presentation presentation) throws Exception {
        Shrinker.Case c = f.minimal();
        Deviation d = f.deviation();
        FunctionBlock fb = c.block();
        Defuzzification def = fb.defuzzification(d.output()).orElse(null);
        List<ReferenceProgram.Step> steps = new ReferenceProgram(c.program()).run(c.steps());
        Trace trace = d.step() >= 0 ? steps.get(d.step()).trace() : null;
        double width = org.fclcert.corpus.OutputScales.of(fb).width(d.output()).orElse(1);
        if (f.feature() == Feature.B_COGS && trace != null && def != null && close(perRuleCogs(def, trace, d.output()), d.actual(), 0)) {
            return Optional.of("CoGS summed per rule gives " + d.actual());
        }
        if (f.feature() == Feature.E_ACCU_NSUM && close(value(with(c, AccumulationMethod.BSUM, null), d), d.actual(), 0.01 * width)) {
            return Optional.of("NSUM computed as BSUM gives " + d.actual());
        }
        if (f.feature() == Feature.E_RM && close(value(with(c, null, DefuzzificationMethod.LM), d), d.actual(), 0.01 * width)) {
            return Optional.of("RM answered as LM: " + d.actual());
        }
        if (f.feature() == Feature.B_DEFAULT_NC && d.step() == 0 && Double.isNaN(d.actual())) {
            return Optional.of("NaN before any rule fired under NC");
        }
        if (f.feature() == Feature.B_DEFAULT_VALUE && trace != null && def != null
                && trace.ruleDegrees().stream().anyMatch(r -> r.degree() > 0 && r.degree() <= 1e-6)
                && def.defaultValue().orElse(null) instanceof DefaultValue.Constant k && d.actual() == k.value().value()) {
            return Optional.of("a rule of degree at most 1e-6 taken as not fired: DEFAULT " + d.actual());
        }
        String predicted = switch (f.feature()) {
            case E_COG, E_COA, E_LM, E_RM, O_MOM -> "FCL-X201";
            case E_WITH_CONST, E_WITH_VAR -> "FCL-X203";
            case B_IN_TERM, E_IN_TERM_4, O_MANY_POINTS -> "FCL-X209";
            case E_ACCU_NSUM -> "FCL-X202";
            case B_COGS -> "FCL-X204";
            default -> "";
        };
        Optional<Presentation.Sent> sent = presentation.present(c.program(), steps).sent();
        return sent.flatMap(s -> s.differences().stream().filter(x -> x.code().equals(predicted)).findFirst())
                .map(x -> "predicted by the writer: " + x.code() + " " + x.message());
    }

    /** Every activation of a singleton of {@code output} weighted separately (per rule), not per term. */
    private static double perRuleCogs(Defuzzification def, Trace t, String output) {
        double num = 0;
        double den = 0;
        for (Trace.Activation a : t.activations()) {
            if (Names.same(a.variable(), output) && a.term().isPresent()) {
                double v = def.terms().stream().filter(x -> Names.same(x.name(), a.term().get())).findFirst()
                        .map(x -> ((Literal) ((MembershipFunction.Singleton) x.function()).value()).value()).orElseThrow();
                num += v * a.activatedDegree();
                den += a.activatedDegree();
            }
        }
        return num / den;
    }

    /** The minimal case with another accumulation or method of the deviating output (null: unchanged). */
    private static Shrinker.Case with(Shrinker.Case c, AccumulationMethod accu, DefuzzificationMethod method) {
        FunctionBlock fb = c.block();
        List<RuleBlock> blocks = fb.ruleBlocks().stream().map(rb -> accu == null ? rb : new RuleBlock(rb.name(), rb.and(),
                rb.or(), rb.activation(), Optional.of(new Located<>(accu, AT)), rb.rules(), rb.location())).toList();
        List<Defuzzification> defs = fb.defuzzifications().stream().map(d -> method == null ? d : new Defuzzification(
                d.variable(), d.range(), d.terms(), Optional.of(new Located<>(method, AT)), d.defaultValue(), d.location()))
                .toList();
        return new Shrinker.Case(new Program(c.program().sourceName(), List.of(new FunctionBlock(fb.name(), fb.variables(),
                fb.fuzzifications(), defs, blocks, fb.options(), fb.location()))), c.steps());
    }

    private static double value(Shrinker.Case c, Deviation d) throws Exception {
        List<ReferenceProgram.Step> steps = new ReferenceProgram(c.program()).run(c.steps());
        return steps.get(d.step()).outputs().get(d.output());
    }

    private static boolean close(double model, double actual, double allowed) {
        return Math.abs(model - actual) <= Math.max(allowed, Tolerance.EXACT.allowed(model, java.util.OptionalDouble.empty()));
    }
}
