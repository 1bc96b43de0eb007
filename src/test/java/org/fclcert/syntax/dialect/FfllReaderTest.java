package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Collectors;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.model.Condition;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.junit.jupiter.api.Test;

/** The FFLL reader on the sample programs: every construct of the FFLL notes and docs/peers.md, located, with its meaning. */
class FfllReaderTest {
    private static Analysis analyze(String sample) {
        return Analysis.analyze(new FfllReader(), sample, FfllSamples.text(sample));
    }

    private static Program program(String sample) {
        Analysis a = analyze(sample);
        assertTrue(a.program().isPresent(), () -> sample + ": " + a.diagnostics());
        return a.program().get();
    }

    /** The Open Level uses as "ID@line:col", in source order. */
    private static List<String> openFeatures(Program p) {
        return new FeatureDetector().detect(p).uses().stream().filter(u -> u.feature().level() == ConformanceLevel.OPEN)
                .map(FfllReaderTest::at).toList();
    }

    private static String at(FeatureUse u) {
        return u.feature().id() + "@" + u.location().line() + ":" + u.location().column();
    }

    private static List<String> codes(Analysis a) {
        return a.diagnostics().stream().map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column())
                .toList();
    }

    @Test
    void guardUsesFfllShorthandEverywhere() {
        Program p = program("guard.fcl");
        assertEquals(List.of(
                "O-DECLARATION-WITHOUT-COLON@5:15", "O-RANGE-COMMENT@5:22",
                "O-DECLARATION-WITHOUT-COLON@6:15", "O-RANGE-COMMENT@6:22",
                "O-DECLARATION-WITHOUT-COLON@10:15", "O-RANGE-COMMENT@10:22",
                "O-FFLL-OUTPUT-FUZZIFY@23:1", "O-FFLL-NO-DEFAULT@29:1", "O-END-FUZZIFY@31:1", "O-ACCUM@35:5",
                "O-FFLL-TERM-ONLY-CONDITION@36:16", "O-FFLL-TERM-ONLY-CONDITION@36:25", "O-FFLL-TERM-ONLY-CONCLUSION@36:34",
                "O-FFLL-TERM-ONLY-CONDITION@37:16", "O-FFLL-TERM-ONLY-CONDITION@37:25", "O-FFLL-TERM-ONLY-CONCLUSION@37:35",
                "O-FFLL-TERM-ONLY-CONDITION@38:16", "O-FFLL-TERM-ONLY-CONDITION@38:24", "O-FFLL-TERM-ONLY-CONCLUSION@38:33",
                "O-FFLL-TERM-ONLY-CONDITION@39:16", "O-FFLL-TERM-ONLY-CONDITION@39:24", "O-FFLL-TERM-ONLY-CONCLUSION@39:34"),
                openFeatures(p));
        assertEquals(List.of("FCL-D114@29:1", "FCL-D116@30:5"), codes(analyze("guard.fcl")));
        FunctionBlock fb = p.functionBlocks().get(0);
        assertEquals(List.of("health", "threat"), fb.fuzzifications().stream().map(f -> f.variable()).toList(),
                "the output's FUZZIFY block became its DEFUZZIFY terms");
        Defuzzification fight = fb.defuzzification("fight").orElseThrow();
        assertEquals(List.of("flee", "hold", "attack"), fight.terms().stream().map(t -> t.name()).toList());
        assertEquals(0.0, fight.range().orElseThrow().min().value());
        assertEquals(4.0, fight.range().orElseThrow().max().value(), "the output's RANGE comment is its RANGE");
        assertEquals(DefuzzificationMethod.COG, fight.method().orElseThrow().value());
        assertEquals(0.0, ((DefaultValue.Constant) fight.defaultValue().orElseThrow()).value().value());
        Rule r2 = fb.ruleBlocks().get(0).rules().get(2);
        Condition.And c = (Condition.And) r2.condition();
        assertEquals(new Condition.TermSubcondition("health", "fit", false, r2.location()), c.operands().get(0));
        assertEquals(new Condition.TermSubcondition("threat", "low", false, r2.location()), c.operands().get(1));
        assertEquals("fight", r2.conclusion().get(0).variable());
        assertEquals("attack", r2.conclusion().get(0).term().orElseThrow());
    }

    /*
     * health 35: weak = (50-35)/30 = 0.5, fit = (35-20)/30 = 0.5; threat 1: low = 1, high = 0.
     * Rules 0 (hold) and 2 (attack) at 0.5, the others 0. max(hold, attack) clipped at 0.5 is
     * (1,0) (1.5,0.5) (3.5,0.5) (4,0), symmetric about 2.5: CoG = 2.5.
     */
    @Test
    void guardEvaluatesAsHandDerived() throws EvaluationException {
        FunctionBlockInstance fb = Evaluator.load(program("guard.fcl")).newInstance();
        fb.set("health", 35);
        fb.set("threat", 1);
        fb.evaluate();
        assertEquals(2.5, fb.get("fight"), 1e-12);
    }

    /*
     * MoM (docs/semantics.md): room 15: cold = (20-15)/10 = 0.5, warm = (15-10)/10 = 0.5, hot = 0. full
     * clipped at 0.5 is 0.5 on [85, 100], half on [40, 60]: MoM = (20·50 + 15·92.5)/35 = 2387.5/35.
     * room 5: cold = 1, full unclipped has its plateau [90, 100]: MoM = 95.
     */
    @Test
    void heaterReadsTheGrammarNotesFormsAndMoM() throws EvaluationException {
        Analysis a = analyze("heater.fcl");
        assertEquals(List.of("FCL-D115@22:5"), codes(a), "OPTION, RANGE := and RANGE last are FFLL's own forms");
        Program p = a.program().orElseThrow();
        assertEquals(List.of("O-VAR-RETAIN@4:11", "O-RANGE-COMMENT@5:18", "O-RANGE-COMMENT@9:19", "O-MOM@22:5"),
                openFeatures(p));
        FunctionBlockInstance fb = Evaluator.load(p).newInstance();
        fb.set("room", 15);
        fb.evaluate();
        assertEquals(2387.5 / 35, fb.get("power"), 1e-12);
        fb.set("room", 5);
        fb.evaluate();
        assertEquals(95.0, fb.get("power"), 1e-12);
    }

    @Test
    void writtenVariablesGiveWayToPositionWithAWarning() {
        Analysis a = analyze("mixer.fcl");
        // the mixer's two rules leave regions where none fires (FCL-W005, CoverageGapsTest's concern): left out here
        assertEquals(List.of("FCL-D116@35:5", "FCL-D117@40:5", "FCL-D111@47:16", "FCL-D111@47:33", "FCL-W105@48:48",
                "FCL-D113@48:53"), codes(a).stream().filter(c -> !c.startsWith("FCL-W005")).toList());
        Diagnostic first = a.diagnostics().stream().filter(d -> !d.code().equals("FCL-W005")).toList().get(2);
        assertTrue(first.message().contains("read as 'speed IS slow'"), first.message());
        Rule r1 = a.program().orElseThrow().functionBlocks().get(0).ruleBlocks().get(0).rules().get(0);
        Condition.And c = (Condition.And) r1.condition();
        assertEquals("speed", ((Condition.TermSubcondition) c.operands().get(0)).variable());
        assertEquals("load", ((Condition.TermSubcondition) c.operands().get(1)).variable());
        assertEquals(List.of("torque IS large", "lamp IS lit"), r1.conclusion().stream()
                .map(s -> s.variable() + " IS " + s.term().orElseThrow()).toList(), "term-only subconclusions by position");
    }

    @Test
    void aRealMistakeInAnFfllProgramGetsTheUsualCheck() {
        Analysis a = analyze("broken-term.fcl");
        assertFalse(a.program().isPresent());
        List<Diagnostic> errors = a.diagnostics().stream().filter(Diagnostic::isError).toList();
        assertEquals(1, errors.size(), () -> a.diagnostics().toString());
        assertEquals("broken-term.fcl:23:16: error FCL-C002: level IS medium: 'medium' is not a term of input 'level'"
                + " (its terms: low, high)", errors.get(0).toString());
    }

    @Test
    void subconditionsAndSubconclusionsBeyondTheDeclaredVariablesAreLocatedErrors() {
        Analysis a = analyze("broken-position.fcl");
        assertEquals(List.of("FCL-D116@17:5", "FCL-D101@24:25", "FCL-D102@24:39"), codes(a));
        assertFalse(a.program().isPresent());
    }

    /* Issue 18 item 12: one rule of 10 000 subconditions beyond the one input gave an FCL-D101 each. */
    @Test
    void positionErrorsAreCappedPerFile() {
        String many = "low" + " AND low".repeat(10_000);
        String text = FfllSamples.text("broken-position.fcl").replace("IF high AND low THEN", "IF " + many + " THEN");
        Analysis a = Analysis.analyze(new FfllReader(), "many.fcl", text);
        List<Diagnostic> errors = a.diagnostics().stream().filter(Diagnostic::isError).toList();
        assertEquals(26, errors.size(), "25 errors and the one that says the rest are not reported");
        assertEquals(25, errors.stream().filter(d -> d.code().equals("FCL-D101")).count());
        assertEquals(1, errors.stream().filter(d -> d.code().equals("FCL-S399")).count());
        assertTrue(errors.get(errors.size() - 1).message().equals("more than 25 errors; the rest are not reported"),
                errors.toString());
        assertFalse(a.program().isPresent());
    }

    @Test
    void malformedRangeCommentAndMisspeltKeywordsAreLocatedErrors() {
        Analysis a = analyze("broken-range.fcl");
        assertEquals(List.of("FCL-D103@3:17", "FCL-S019@19:5"), codes(a));
    }

    @Test
    void theStandardsExampleReadsAsFfllWithPortabilityWarningsOnly() throws java.io.IOException {
        String valve = java.nio.file.Files.readString(java.nio.file.Path.of("examples/valve.fcl"));
        Analysis ffll = Analysis.analyze(new FfllReader(), "valve.fcl", valve);
        Analysis strict = Analysis.analyze(new org.fclcert.syntax.StrictReader(), "valve.fcl", valve);
        assertEquals(strict.program().orElseThrow(), ffll.program().orElseThrow(), "same meaning, same model");
        assertEquals(List.of(), ffll.program().get().dialectFeatures());
        // no RANGE comments (D118), 2-point terms (D119), CoGS (D117), WITH (D113): FFLL would not run it as written
        assertEquals(java.util.Set.of("FCL-D113", "FCL-D117", "FCL-D118", "FCL-D119"), ffll.diagnostics().stream()
                .map(Diagnostic::code).collect(Collectors.toSet()));
        assertTrue(ffll.diagnostics().stream().noneMatch(Diagnostic::isError));
    }
    /**
     * FFLL's API sample writes FUNCTION_BLOCK without a name and ': =' with a blank inside: read as 'function_block' and
     * ':=' (O-UNNAMED-BLOCK, O-SPACED-ASSIGN); a DEFUZZIFY of a variable never declared stays the standard's error.
     */
    @Test
    void theApiSamplesUnnamedBlockAndSpacedAssign() throws EvaluationException {
        String text = """
                FUNCTION_BLOCK
                VAR_INPUT
                  good REAL; (* RANGE(0 .. 10) *)
                END_VAR
                VAR_OUTPUT
                  fight REAL; (* RANGE(0 .. 10) *)
                END_VAR
                FUZZIFY good
                  TERM yes : = (0, 0) (5, 1) (10, 1);
                END_FUZZIFY
                FUZZIFY fight
                  TERM hard : = (0, 0) (10, 1) (10, 0);
                END_FUZZIFY
                DEFUZZIFY fight
                  METHOD: CoG;
                END_DEFUZZIFY
                RULEBLOCK first
                  AND: MIN;
                  ACCUM: MAX;
                  RULE 1: IF yes THEN hard;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = Analysis.analyze(new FfllReader(), "api.fcl", text);
        Program p = a.program().orElseThrow(() -> new AssertionError(a.diagnostics()));
        assertEquals("function_block", p.functionBlocks().get(0).name());
        List<String> uses = p.dialectFeatures().stream().map(FfllReaderTest::at).toList();
        assertTrue(uses.containsAll(List.of("O-UNNAMED-BLOCK@1:1", "O-SPACED-ASSIGN@9:12", "O-SPACED-ASSIGN@12:13")),
                uses::toString);
        // good = 2.5: yes 0.5 clips the ramp (0, 0) (10, 1) at 0.5 over [0, 10] (its vertical edge at 10):
        // area 5·0.5/2 + 5·0.5 = 3.75, moment ∫0..5 u·u/10 + ∫5..10 0.5u = 125/30 + 18.75 → CoG 6.1111
        FunctionBlockInstance x = Evaluator.load(p).newInstance();
        x.set("good", 2.5);
        x.evaluate();
        assertEquals((125.0 / 30 + 18.75) / 3.75, x.get("fight"), 1e-12);
        // FFLL's own samples name another variable after DEFUZZIFY; FFLL skips the name and defuzzifies its one
        // output: read so, with FCL-D122 saying it, and evaluating as before
        Analysis undeclared = Analysis.analyze(new FfllReader(), "api.fcl", text.replace("DEFUZZIFY fight",
                "DEFUZZIFY attack"));
        assertTrue(codes(undeclared).contains("FCL-D122@14:11"), codes(undeclared)::toString);
        assertTrue(codes(undeclared).stream().noneMatch(c -> c.startsWith("FCL-C001")), codes(undeclared)::toString);
        FunctionBlockInstance y = Evaluator.load(undeclared.program().orElseThrow()).newInstance();
        y.set("good", 2.5);
        y.evaluate();
        assertEquals((125.0 / 30 + 18.75) / 3.75, y.get("fight"), 1e-12);
    }
}
