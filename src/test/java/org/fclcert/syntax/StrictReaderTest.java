package org.fclcert.syntax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;
import org.junit.jupiter.api.Test;

/** Valid programs read into the model exactly; the model's values are read off the source text by hand. */
class StrictReaderTest {
    private static final SourceLocation L = SourceLocation.UNKNOWN;
    private final StrictReader reader = new StrictReader();

    private Program readValid(String resource) {
        ReadResult r = reader.read(resource, FclTestPrograms.text(resource));
        assertTrue(r.program().isPresent(), () -> "diagnostics: " + r.diagnostics());
        return r.program().get();
    }

    private static Literal lit(Object operand) {
        return assertInstanceOf(Literal.class, operand);
    }

    @Test
    void figure7ReadsWithoutAnyDiagnostic() {
        ReadResult r = reader.read("fig7.fcl", FclTestPrograms.text("figure7_valve.fcl"));
        assertEquals(List.of(), r.diagnostics());
        FunctionBlock fb = r.program().orElseThrow().functionBlocks().get(0);
        assertEquals("Fuzzy_FB", fb.name());
        assertEquals(List.of("temp", "pressure", "valve"), fb.variables().stream().map(Variable::name).toList());
        assertEquals(VariableKind.OUTPUT, fb.variable("VALVE").orElseThrow().kind());
        assertEquals(DataType.REAL, fb.variable("temp").orElseThrow().type());

        // TERM cold := (3, 1) (27, 0);
        MembershipFunction.Points cold = assertInstanceOf(MembershipFunction.Points.class,
                fb.fuzzification("temp").orElseThrow().term("cold").orElseThrow().function());
        List<Point> p = cold.points();
        assertEquals(2, p.size());
        assertEquals(3.0, lit(p.get(0).x()).value());
        assertEquals(1.0, lit(p.get(0).degree()).value());
        assertEquals(27.0, lit(p.get(1).x()).value());
        assertEquals(0.0, lit(p.get(1).degree()).value());
        assertTrue(lit(p.get(0).x()).integral());

        Defuzzification valve = fb.defuzzification("valve").orElseThrow();
        assertEquals(List.of(-100.0, 0.0, 100.0), valve.terms().stream()
                .map(t -> lit(((MembershipFunction.Singleton) t.function()).value()).value()).toList());
        assertEquals(DefuzzificationMethod.COGS, valve.method().orElseThrow().value());
        assertEquals(0.0, ((DefaultValue.Constant) valve.defaultValue().orElseThrow()).value().value());
        assertTrue(valve.range().isEmpty());

        RuleBlock block = fb.ruleBlocks().get(0);
        assertEquals("No1", block.name());
        assertEquals(AndAlgorithm.MIN, block.and().orElseThrow().value());
        assertTrue(block.or().isEmpty());
        assertTrue(block.activation().isEmpty());
        assertEquals(AccumulationMethod.MAX, block.accumulation().orElseThrow().value());
        assertEquals(List.of("1", "2", "3", "4"), block.rules().stream().map(Rule::name).toList());

        // RULE 2: IF temp IS cold AND pressure IS high THEN valve IS closed WITH 0.8;  (line 28)
        Rule rule2 = block.rules().get(1);
        assertTrue(rule2.location().sameAs(SourceLocation.of("fig7.fcl", 28, 5)));
        Condition.And and = assertInstanceOf(Condition.And.class, rule2.condition());
        assertEquals(List.of(new Condition.TermSubcondition("temp", "cold", false, L),
                new Condition.TermSubcondition("pressure", "high", false, L)), and.operands());
        assertTrue(and.operands().get(1).location().sameAs(SourceLocation.of("fig7.fcl", 28, 33)));
        Subconclusion s = rule2.conclusion().get(0);
        assertEquals("valve", s.variable());
        assertEquals(Optional.of("closed"), s.term());
        assertEquals(0.8, lit(s.weight().orElseThrow()).value());
        assertFalse(lit(s.weight().orElseThrow()).integral());
    }

    @Test
    void annexCParsesItsRuleTwoErrorIsForTheChecker() {
        ReadResult r = reader.read("crane.fcl", FclTestPrograms.text("annexC_crane.fcl"));
        assertEquals(List.of(), r.diagnostics());
        FunctionBlock fb = r.program().orElseThrow().functionBlock("container_crane").orElseThrow();
        assertEquals(5, fb.fuzzification("angle").orElseThrow().terms().size());
        RuleBlock block = fb.ruleBlocks().get(0);
        assertEquals(6, block.rules().size());
        assertEquals(Optional.of("pos_big"), block.rules().get(1).conclusion().get(0).term());
        // TERM neg_small := (-50, 0) (-5, 1) ( 0,0);
        MembershipFunction.Points negSmall = (MembershipFunction.Points)
                fb.fuzzification("angle").orElseThrow().term("neg_small").orElseThrow().function();
        assertEquals(List.of(-50.0, -5.0, 0.0), negSmall.points().stream().map(q -> lit(q.x()).value()).toList());
    }

    @Test
    void everyConstructIsReadIntoTheModel() {
        ReadResult r = reader.read("all.fcl", FclTestPrograms.text("every_construct.fcl"));
        // the only diagnostic: WITH after the last of two subconclusions in RULE 02 (line 48)
        assertEquals(List.of("FCL-W105@48"), r.diagnostics().stream()
                .map(d -> d.code() + "@" + d.location().line()).toList());
        Program program = r.program().orElseThrow();
        assertEquals(List.of("every_construct", "second_block"),
                program.functionBlocks().stream().map(FunctionBlock::name).toList());
        FunctionBlock fb = program.functionBlocks().get(0);

        // bp_warm1, bp_warm2 : LREAL := 0.8;  w_rule : REAL := 1_000.0E-3;
        assertEquals(0.8, fb.variable("bp_warm2").orElseThrow().initialValue().orElseThrow().value());
        assertEquals(DataType.LREAL, fb.variable("bp_warm1").orElseThrow().type());
        assertEquals(1.0, fb.variable("w_rule").orElseThrow().initialValue().orElseThrow().value());
        // 16#FF = 255, 2#1010 = 10, 8#17 = 15, +5 = 5
        assertEquals(List.of(255.0, 10.0, 15.0, 5.0), List.of("u1", "u2", "u3", "u4").stream()
                .map(n -> fb.variable(n).orElseThrow().initialValue().orElseThrow().value()).toList());
        assertEquals(List.of(DataType.SINT, DataType.INT, DataType.DINT, DataType.LINT, DataType.USINT,
                DataType.UINT, DataType.UDINT, DataType.ULINT), List.of("level", "i2", "i3", "i4", "u1", "u2", "u3", "u4")
                .stream().map(n -> fb.variable(n).orElseThrow().type()).toList());
        assertEquals(-2.5, fb.variable("power").orElseThrow().initialValue().orElseThrow().value());
        assertEquals(VariableKind.LOCAL, fb.variable("scratch").orElseThrow().kind());
        assertTrue(fb.variable("_lead").isPresent());

        // TERM warm := (bp_warm1, 0.0), (21.0, 1.0), (bp_warm2, 0.0);  TERM hot := (3,0)(27,level);
        MembershipFunction.Points warm = (MembershipFunction.Points)
                fb.fuzzification("TEMP").orElseThrow().term("warm").orElseThrow().function();
        assertEquals(new VariableRef("bp_warm1", L), warm.points().get(0).x());
        assertEquals(21.0, lit(warm.points().get(1).x()).value());
        MembershipFunction.Points hot = (MembershipFunction.Points)
                fb.fuzzification("temp").orElseThrow().term("hot").orElseThrow().function();
        assertEquals(new VariableRef("level", L), hot.points().get(1).degree());

        Defuzzification valve = fb.defuzzification("valve").orElseThrow();
        assertEquals(-100.0, valve.range().orElseThrow().min().value());
        assertEquals(100.0, valve.range().orElseThrow().max().value());
        assertInstanceOf(DefaultValue.NoChange.class, valve.defaultValue().orElseThrow());
        assertEquals(new MembershipFunction.Singleton(new VariableRef("bp_warm1", L)),
                valve.term("inlet").orElseThrow().function());
        Defuzzification power = fb.defuzzification("power").orElseThrow();
        assertEquals(25.0, power.range().orElseThrow().max().value());   // 2.5E1
        assertEquals(DefuzzificationMethod.COG, power.method().orElseThrow().value());   // written 'cog'

        RuleBlock first = fb.ruleBlocks().get(0);
        assertEquals(AndAlgorithm.PROD, first.and().orElseThrow().value());
        assertEquals(OrAlgorithm.ASUM, first.or().orElseThrow().value());
        assertEquals(ActivationMethod.MIN, first.activation().orElseThrow().value());
        assertEquals(AccumulationMethod.NSUM, first.accumulation().orElseThrow().value());

        // RULE 1: a AND b OR c  ==  OR(AND(a, b), c)   (Table 6: AND binds tighter than OR)
        Condition c1 = first.rules().get(0).condition();
        Condition.Or or = assertInstanceOf(Condition.Or.class, c1);
        assertEquals(2, or.operands().size());
        assertEquals(new Condition.And(List.of(new Condition.TermSubcondition("temp", "cold", false, L),
                new Condition.TermSubcondition("pressure", "low", false, L)), L), or.operands().get(0));
        assertEquals(new Condition.TermSubcondition("temp", "hot", false, L), or.operands().get(1));

        // RULE 02: NOT temp IS hot AND (pressure IS NOT low OR w_rule)
        Rule rule2 = first.rules().get(1);
        assertEquals("2", rule2.name());
        assertEquals(new Condition.And(List.of(
                new Condition.Not(new Condition.TermSubcondition("temp", "hot", false, L), L),
                new Condition.Parenthesized(new Condition.Or(List.of(
                        new Condition.TermSubcondition("pressure", "low", true, L),
                        new Condition.VariableSubcondition("w_rule", L)), L), L)), L), rule2.condition());
        assertEquals(0.5, lit(rule2.conclusion().get(0).weight().orElseThrow()).value());
        assertEquals(Optional.of(new VariableRef("w_rule", L)), rule2.conclusion().get(1).weight());

        // RULE 3: NOT (temp IS warm) THEN scratch, valve IS drainage
        Rule rule3 = first.rules().get(2);
        assertEquals(new Condition.Not(new Condition.Parenthesized(
                new Condition.TermSubcondition("temp", "warm", false, L), L), L), rule3.condition());
        assertTrue(rule3.conclusion().get(0).bareVariable());
        assertEquals("scratch", rule3.conclusion().get(0).variable());
        assertEquals(Optional.of("drainage"), rule3.conclusion().get(1).term());

        assertEquals("second", fb.ruleBlocks().get(1).name());   // 'RuleBlock second' in mixed case
        assertEquals("vendor_speed := fast; (* kept verbatim *)", fb.options().get(0).content());
    }

    @Test
    void ruleNumbersBecomeDecimalStrings() {
        String text = minimal("RULE 007 : IF x IS a THEN y IS b;");
        Rule rule = reader.read("t.fcl", text).program().orElseThrow()
                .functionBlocks().get(0).ruleBlocks().get(0).rules().get(0);
        assertEquals("7", rule.name());
        assertTrue(rule.numbered());
    }

    @Test
    void missingMethodDefaultAccuAndOperatorsAreLeftToTheChecks() {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM a := (0, 0) (1, 1); END_FUZZIFY
                DEFUZZIFY y TERM b := 1; END_DEFUZZIFY
                RULEBLOCK r RULE 1 : IF x IS a THEN y IS b; END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        ReadResult r = reader.read("t.fcl", text);
        assertEquals(List.of(), r.diagnostics());
        Defuzzification y = r.program().orElseThrow().functionBlocks().get(0).defuzzifications().get(0);
        assertTrue(y.method().isEmpty());
        assertTrue(y.defaultValue().isEmpty());
    }

    @Test
    void aSyntaxErrorIsALocatedDiagnosticAndNoProgram() {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT x : REAL; END_VAR
                FUZZIFY x
                    TERM a := (0, 0) (1, 1)
                    TERM b := (0, 1) (1, 0);
                END_FUZZIFY
                END_FUNCTION_BLOCK
                """;
        ReadResult r = reader.read("t.fcl", text);
        assertTrue(r.program().isEmpty());
        assertEquals(1, r.diagnostics().size(), () -> r.diagnostics().toString());
        Diagnostic d = r.diagnostics().get(0);
        assertEquals("FCL-S014", d.code());
        // at the end of line 4, which lacks the ';', not at the TERM of line 5 where the parser notices
        assertTrue(d.location().sameAs(SourceLocation.of("t.fcl", 4, 28)), d.location().toString());
        assertEquals("expected ';' after the term's membership function (5.2.2), found 'TERM' on line 5", d.message());
    }

    @Test
    void anEmptyProgramIsAnError() {
        for (String text : List.of("", "   \n", "(* only a comment *)\n")) {
            ReadResult r = reader.read("e.fcl", text);
            assertTrue(r.program().isEmpty());
            assertEquals(List.of("FCL-S005"), r.diagnostics().stream().map(Diagnostic::code).toList());
        }
    }

    @Test
    void windowsLineEndsAndAByteOrderMarkDoNotMoveLocations() {
        String text = "\uFEFF" + FclTestPrograms.text("figure7_valve.fcl").replace("\n", "\r\n");
        ReadResult r = reader.read("crlf.fcl", text);
        assertEquals(List.of(), r.diagnostics());
        FunctionBlock fb = r.program().orElseThrow().functionBlocks().get(0);
        assertTrue(fb.location().sameAs(SourceLocation.of("crlf.fcl", 1, 1)));
        assertTrue(fb.ruleBlocks().get(0).rules().get(1).location().sameAs(SourceLocation.of("crlf.fcl", 28, 5)));
    }

    /** A one-rule program around the given rule. */
    static String minimal(String rule) {
        return """
                FUNCTION_BLOCK f
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM a := (0, 0) (1, 1); END_FUZZIFY
                DEFUZZIFY y TERM b := 1; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r AND : MIN; ACCU : MAX;
                """ + rule + "\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n";
    }
}
