package org.fclcert.write;

import static org.fclcert.write.M.AT;
import static org.fclcert.write.M.and;
import static org.fclcert.write.M.bare;
import static org.fclcert.write.M.i;
import static org.fclcert.write.M.is;
import static org.fclcert.write.M.isNot;
import static org.fclcert.write.M.not;
import static org.fclcert.write.M.or;
import static org.fclcert.write.M.p;
import static org.fclcert.write.M.par;
import static org.fclcert.write.M.points;
import static org.fclcert.write.M.r;
import static org.fclcert.write.M.singleton;
import static org.fclcert.write.M.then;
import static org.fclcert.write.M.thenVariable;
import static org.fclcert.write.M.v;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Collections;
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
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Located;
import org.fclcert.model.OptionsBlock;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.junit.jupiter.api.Test;

class CanonicalWriterTest {
    private final CanonicalWriter writer = new CanonicalWriter();

    private static Variable var(String name, VariableKind kind, DataType type) {
        return new Variable(name, kind, type, Optional.empty(), AT);
    }

    private static Rule rule(String name, Condition c, Subconclusion... s) {
        return new Rule(name, c, List.of(s), AT);
    }

    private static <T> Optional<Located<T>> set(T value) {
        return Optional.of(new Located<>(value, AT));
    }

    /** The function block of 5.3, Figure 7. */
    static FunctionBlock valve() {
        return new FunctionBlock("Fuzzy_FB",
                List.of(var("temp", VariableKind.INPUT, DataType.REAL),
                        var("pressure", VariableKind.INPUT, DataType.REAL),
                        var("valve", VariableKind.OUTPUT, DataType.REAL)),
                List.of(new Fuzzification("temp", List.of(points("cold", p(i(3), i(1)), p(i(27), i(0))),
                                points("hot", p(i(3), i(0)), p(i(27), i(1)))), AT),
                        new Fuzzification("pressure", List.of(points("low", p(i(55), i(1)), p(i(95), i(0))),
                                points("high", p(i(55), i(0)), p(i(95), i(1)))), AT)),
                List.of(new Defuzzification("valve", Optional.empty(),
                        List.of(singleton("drainage", i(-100)), singleton("closed", i(0)), singleton("inlet", i(100))),
                        set(DefuzzificationMethod.COGS),
                        Optional.of(new DefaultValue.Constant(i(0), AT)), AT)),
                List.of(new RuleBlock("No1", set(AndAlgorithm.MIN), Optional.empty(), Optional.empty(),
                        set(AccumulationMethod.MAX),
                        List.of(rule("1", and(is("temp", "cold"), is("pressure", "low")), then("valve", "inlet")),
                                rule("2", and(is("temp", "cold"), is("pressure", "high")), then("valve", "closed", r(0.8))),
                                rule("3", and(is("temp", "hot"), is("pressure", "low")), then("valve", "closed")),
                                rule("4", and(is("temp", "hot"), is("pressure", "high")), then("valve", "drainage"))),
                        AT)),
                List.of(), AT);
    }

    @Test
    void writesTheValveExampleInCanonicalLayout() {
        String expected = """
                FUNCTION_BLOCK Fuzzy_FB
                VAR_INPUT
                    temp : REAL;
                    pressure : REAL;
                END_VAR

                VAR_OUTPUT
                    valve : REAL;
                END_VAR

                FUZZIFY temp
                    TERM cold := (3, 1) (27, 0);
                    TERM hot := (3, 0) (27, 1);
                END_FUZZIFY

                FUZZIFY pressure
                    TERM low := (55, 1) (95, 0);
                    TERM high := (55, 0) (95, 1);
                END_FUZZIFY

                DEFUZZIFY valve
                    TERM drainage := -100;
                    TERM closed := 0;
                    TERM inlet := 100;
                    METHOD : CoGS;
                    DEFAULT := 0;
                END_DEFUZZIFY

                RULEBLOCK No1
                    AND : MIN;
                    ACCU : MAX;
                    RULE 1 : IF temp IS cold AND pressure IS low THEN valve IS inlet;
                    RULE 2 : IF temp IS cold AND pressure IS high THEN valve IS closed WITH 0.8;
                    RULE 3 : IF temp IS hot AND pressure IS low THEN valve IS closed;
                    RULE 4 : IF temp IS hot AND pressure IS high THEN valve IS drainage;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        assertEquals(expected, writer.write(new Program("valve.fcl", List.of(valve()))));
    }

    @Test
    void writesEveryDefuzzificationAndRuleBlockSetting() {
        FunctionBlock fb = new FunctionBlock("all",
                List.of(new Variable("w", VariableKind.INPUT, DataType.LREAL, Optional.of(r(0.8)), AT),
                        new Variable("bp", VariableKind.INPUT, DataType.INT, Optional.of(i(-3)), AT),
                        var("out", VariableKind.OUTPUT, DataType.REAL),
                        var("flag", VariableKind.OUTPUT, DataType.REAL),
                        new Variable("tmp", VariableKind.LOCAL, DataType.UDINT, Optional.of(i(7)), AT)),
                List.of(new Fuzzification("w", List.of(points("up", p(v("bp"), i(0)), p(r(1.5), v("w")), p(i(3), r(0.25)))), AT)),
                List.of(new Defuzzification("out", Optional.of(new Range(i(-10), r(1e-5), AT)),
                        List.of(points("a", p(i(-10), i(0)), p(i(0), i(1)))),
                        set(DefuzzificationMethod.COA), Optional.of(new DefaultValue.NoChange(AT)), AT)),
                List.of(new RuleBlock("rb", set(AndAlgorithm.PROD), set(OrAlgorithm.ASUM), set(ActivationMethod.MIN),
                        set(AccumulationMethod.NSUM),
                        List.of(rule("first", or(is("w", "up"), bare("bp")),
                                thenVariable("flag"), then("out", "a", v("w")), then("out", "a", r(0.5)))),
                        AT)),
                List.of(new OptionsBlock("vendor x = 1;\n  indented line", AT)), AT);
        String expected = """
                FUNCTION_BLOCK all
                VAR_INPUT
                    w : LREAL := 0.8;
                    bp : INT := -3;
                END_VAR

                VAR_OUTPUT
                    out : REAL;
                    flag : REAL;
                END_VAR

                VAR
                    tmp : UDINT := 7;
                END_VAR

                FUZZIFY w
                    TERM up := (bp, 0) (1.5, w) (3, 0.25);
                END_FUZZIFY

                DEFUZZIFY out
                    RANGE (-10 .. 1.0E-5);
                    TERM a := (-10, 0) (0, 1);
                    METHOD : CoA;
                    DEFAULT := NC;
                END_DEFUZZIFY

                RULEBLOCK rb
                    AND : PROD;
                    OR : ASUM;
                    ACT : MIN;
                    ACCU : NSUM;
                    RULE first : IF w IS up OR bp THEN flag,
                        out IS a WITH w,
                        out IS a WITH 0.5;
                END_RULEBLOCK

                OPTIONS
                vendor x = 1;
                  indented line
                END_OPTIONS
                END_FUNCTION_BLOCK
                """;
        assertEquals(expected, writer.write(new Program("all.fcl", List.of(fb))));
    }

    @Test
    void variableSectionsFollowDeclarationRunsWithLocalsLast() {
        FunctionBlock fb = new FunctionBlock("f",
                List.of(var("a", VariableKind.INPUT, DataType.REAL), var("l", VariableKind.LOCAL, DataType.REAL),
                        var("b", VariableKind.OUTPUT, DataType.REAL), var("c", VariableKind.INPUT, DataType.REAL)),
                List.of(), List.of(), List.of(), List.of(), AT);
        assertEquals("""
                FUNCTION_BLOCK f
                VAR_INPUT
                    a : REAL;
                END_VAR

                VAR_OUTPUT
                    b : REAL;
                END_VAR

                VAR_INPUT
                    c : REAL;
                END_VAR

                VAR
                    l : REAL;
                END_VAR
                END_FUNCTION_BLOCK
                """, writer.write(fb));
    }

    @Test
    void severalFunctionBlocksAreSeparatedByABlankLine() {
        FunctionBlock empty = new FunctionBlock("e", List.of(), List.of(), List.of(), List.of(), List.of(), AT);
        FunctionBlock other = new FunctionBlock("g", List.of(), List.of(), List.of(), List.of(),
                List.of(new OptionsBlock("", AT)), AT);
        assertEquals("""
                FUNCTION_BLOCK e
                END_FUNCTION_BLOCK

                FUNCTION_BLOCK g
                OPTIONS
                END_OPTIONS
                END_FUNCTION_BLOCK
                """, writer.write(new Program("p", List.of(empty, other))));
    }

    @Test
    void conditionsKeepExplicitParenthesesAndNegations() {
        Condition c = or(and(not(is("a", "x")), isNot("b", "y")),
                and(par(or(is("a", "z"), bare("w"))), not(par(is("b", "y")))),
                par(par(bare("w"))));
        assertEquals("NOT a IS x AND b IS NOT y OR (a IS z OR w) AND NOT (b IS y) OR ((w))", ConditionText.of(c));
    }

    @Test
    void conditionsBuiltByToolsGetTheParenthesesTheirShapeNeeds() {
        // an OR under an AND, an AND under an AND, an OR under an OR and a compound under a NOT
        // could not be read back with the same meaning without parentheses (Table 6)
        assertEquals("(a OR b) AND (c AND d)", ConditionText.of(and(or(bare("a"), bare("b")), and(bare("c"), bare("d")))));
        assertEquals("a OR (b OR c) OR c AND d", ConditionText.of(or(bare("a"), or(bare("b"), bare("c")), and(bare("c"), bare("d")))));
        assertEquals("NOT (a AND b)", ConditionText.of(not(and(bare("a"), bare("b")))));
        assertEquals("NOT (NOT a)", ConditionText.of(not(not(bare("a")))));
    }

    @Test
    void longChainsAndDeepNestingDoNotUseTheCallStack() {
        List<Condition> operands = new ArrayList<>(Collections.nCopies(200_000, bare("a")));
        String chain = ConditionText.of(new Condition.And(operands, AT));
        assertEquals(200_000 * "a AND ".length() - " AND ".length(), chain.length());

        Condition deep = bare("a");
        for (int k = 0; k < 200_000; k++) {
            deep = par(deep);
        }
        String nested = ConditionText.of(deep);
        assertEquals("(".repeat(200_000) + "a" + ")".repeat(200_000), nested);
    }
}
