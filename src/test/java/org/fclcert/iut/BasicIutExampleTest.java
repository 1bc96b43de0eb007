package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The example IUT of docs/iut-protocol.md (examples/iut/basic_iut.py), driven through the real
 * process adapter; expected values are worked out by hand in the comments.
 */
class BasicIutExampleTest {
    static final String SPEC = "process:python3 " + Path.of("examples/iut/basic_iut.py").toAbsolutePath();

    /** Clause 5.3, figure 7, as written in the standard. */
    static final String VALVE = String.join("\n",
            "FUNCTION_BLOCK Fuzzy_FB",
            "VAR_INPUT",
            "    temp:    REAL;",
            "    pressure: REAL;",
            "END_VAR",
            "VAR_OUTPUT",
            "    valve:    REAL;",
            "END_VAR",
            "FUZZIFY temp",
            "    TERM cold    := (3, 1) (27, 0);",
            "    TERM hot     := (3, 0) (27, 1);",
            "END_FUZZIFY",
            "FUZZIFY pressure",
            "    TERM low     := (55, 1) (95, 0);",
            "    TERM high    := (55, 0) (95, 1);",
            "END_FUZZIFY",
            "DEFUZZIFY valve",
            "    TERM drainage := -100;",
            "    TERM closed  := 0;",
            "    TERM inlet   := 100;",
            "    METHOD: CoGS;",
            "    DEFAULT     := 0;",
            "END_DEFUZZIFY",
            "RULEBLOCK No1",
            "    AND: MIN;",
            "    ACCU: MAX;",
            "    RULE 1: IF temp IS cold AND pressure IS low THEN valve IS inlet;",
            "    RULE 2: IF temp IS cold AND pressure IS high THEN valve IS closed WITH 0.8;",
            "    RULE 3: IF temp IS hot AND pressure IS low THEN valve IS closed;",
            "    RULE 4: IF temp IS hot AND pressure IS high THEN valve IS drainage;",
            "END_RULEBLOCK",
            "END_FUNCTION_BLOCK",
            "");

    private static ImplementationUnderTest iut;

    @BeforeAll
    static void start() throws IutException {
        iut = Iuts.open(SPEC, IutOptions.defaults().withTimeout(Duration.ofSeconds(3)));
    }

    @AfterAll
    static void stop() {
        iut.close();
    }

    private static double valve(double temp, double pressure) throws IutException {
        return iut.eval(null, Map.of("temp", temp, "pressure", pressure)).get("valve");
    }

    @Test
    void itIntroducesItselfWithItsClaims() throws IutException {
        IutInfo info = iut.hello();
        assertEquals("basic_iut.py", info.name());
        assertTrue(info.claims().containsAll(List.of("B-COGS", "B-DEFAULT-NC", "E-WITH-CONST")), info.claims().toString());
    }

    @Test
    void theValveExampleOfClause53() throws IutException {
        assertEquals(new LoadOutcome.Loaded(List.of("Fuzzy_FB")), iut.load(VALVE));
        // temp 5: cold = (27-5)/24 = 11/12, hot = 1/12; pressure 60: low = (95-60)/40 = 7/8, high = 1/8.
        // rule 1: min(11/12, 7/8) = 7/8 -> inlet; rule 2: min(11/12, 1/8) * 0.8 = 1/10 -> closed;
        // rule 3: min(1/12, 7/8) = 1/12 -> closed (MAX with 1/10 keeps 1/10); rule 4: 1/12 -> drainage.
        // CoGS = (100*7/8 + 0*1/10 - 100*1/12) / (7/8 + 1/10 + 1/12) = (950/12) / (127/120) = 9500/127
        assertEquals(9500.0 / 127.0, valve(5, 60), 1e-12);
        // temp 27, pressure 95: only rule 4 fires, fully -> drainage
        assertEquals(-100.0, valve(27, 95), 1e-12);
        // temp 15, pressure 75: every degree 1/2 (rule 2: 0.4, MAX with rule 3's 0.5 -> 0.5): (50 + 0 - 50)/1.5 = 0
        assertEquals(0.0, valve(15, 75), 1e-12);
        // beyond the outer points the degrees stay as at the ends: temp -40 is as cold as temp 3 -> same as (3, 55): inlet
        assertEquals(100.0, valve(-40, 0), 1e-12);
    }

    private static String oneRule(String defaultValue) {
        return String.join("\n",
                "FUNCTION_BLOCK hold",
                "VAR_INPUT x : REAL; END_VAR",
                "VAR_OUTPUT y : REAL; END_VAR",
                "FUZZIFY x TERM low := (0, 1) (10, 0); TERM high := (0, 0) (10, 1); END_FUZZIFY",
                "DEFUZZIFY y TERM a := 0; TERM b := 100; METHOD : CoGS; DEFAULT := " + defaultValue + "; END_DEFUZZIFY",
                "RULEBLOCK r ACCU : MAX;",
                "  RULE 1 : IF x IS low THEN y IS b;",
                "  RULE 2 : IF x IS low THEN y IS b;",
                "  RULE 3 : IF x IS high THEN y IS a WITH 0.0;",
                "END_RULEBLOCK END_FUNCTION_BLOCK");
    }

    @Test
    void defaultValueAndNoChange() throws IutException {
        iut.load(oneRule("NC"));
        // x = 2.5: low = 0.75 (rules 1 and 2, MAX -> 0.75 once), high = 0.25 but weighted 0 -> only b fires: 100
        assertEquals(100.0, iut.eval(null, Map.of("x", 2.5)).get("y"), 1e-12);
        // x = 20: low = 0, rule 3 weighted 0: nothing fired -> NC keeps 100
        assertEquals(100.0, iut.eval(null, Map.of("x", 20.0)).get("y"), 1e-12);
        // a fresh instance has y = 0 (its initial value) and keeps it
        iut.reset();
        assertEquals(0.0, iut.eval(null, Map.of("x", 20.0)).get("y"), 1e-12);
        iut.load(oneRule("7"));
        assertEquals(7.0, iut.eval(null, Map.of("x", 20.0)).get("y"), 1e-12);
        assertEquals(Optional.empty(), iut.export());
    }

    @Test
    void accumulationIsPerTermNotPerRule() throws IutException {
        iut.load(oneRule("0").replace("WITH 0.0", ""));
        // x = 2.5: b = MAX(0.75, 0.75) = 0.75, a = 0.25 -> (0.75*100 + 0.25*0)/(0.75 + 0.25) = 75
        // (summing per rule would give 150/1.75 = 85.71...)
        assertEquals(75.0, iut.eval(null, Map.of("x", 2.5)).get("y"), 1e-12);
    }

    @Test
    void whatItDoesNotSupportIsRejectedAtTheRightLine() throws IutException {
        // line 27 is rule 1
        assertRejectedAt(27, VALVE.replace("cold AND pressure IS low THEN valve IS inlet", "cold OR pressure IS low THEN valve IS inlet"));
        // line 10 is the term cold
        assertRejectedAt(10, VALVE.replace("(3, 1) (27, 0);", "(3, 1) (10, 1) (20, 0) (27, 0);"));
        // line 30: rule 4 names a term 'warm' that temp does not have
        assertRejectedAt(30, VALVE.replace("temp IS hot AND pressure IS high", "temp IS warm AND pressure IS high"));
        // line 21: CoG needs non-singleton terms, which the Basic Level lacks
        assertRejectedAt(21, VALVE.replace("METHOD: CoGS", "METHOD: CoG"));
    }

    @Test
    void programsTheStandardForbidsAreRejectedAtTheRightLine() throws IutException {
        // line 3: MAX is a keyword and cannot name a variable
        assertRejectedAt(3, VALVE.replace("temp:    REAL;", "max:    REAL;"));
        // line 18: an integer literal may not have two underscores in a row
        assertRejectedAt(18, VALVE.replace("-100;", "-1__00;"));
        // line 22: DEFAULT given twice
        assertRejectedAt(22, VALVE.replace("DEFAULT     := 0;", "DEFAULT     := 0; DEFAULT := 1;"));
        // line 16: FUZZIFY temp after the DEFUZZIFY block, moved up to lines 9-15, breaks the order of 5.4
        String defuzzify = VALVE.substring(VALVE.indexOf("DEFUZZIFY valve"), VALVE.indexOf("RULEBLOCK"));
        String reordered = VALVE.replace(defuzzify, "").replace("FUZZIFY temp", defuzzify + "FUZZIFY temp");
        assertRejectedAt(16, reordered);
        // line 10: a degree above 1
        assertRejectedAt(10, VALVE.replace("(27, 0);", "(27, 2);"));
    }

    private static void assertRejectedAt(int line, String program) throws IutException {
        LoadOutcome.Rejected rejected = assertInstanceOf(LoadOutcome.Rejected.class, iut.load(program));
        assertEquals(OptionalInt.of(line), rejected.line(), rejected.message());
    }

    @Test
    void anUnknownInputIsAnEvaluationError() throws IutException {
        iut.load(VALVE);
        IutException e = assertThrows(IutException.class, () -> iut.eval(null, Map.of("humidity", 1.0)));
        assertEquals(IutException.Kind.EVAL_ERROR, e.kind());
        assertTrue(e.getMessage().contains("humidity"), e.getMessage());
    }
}
