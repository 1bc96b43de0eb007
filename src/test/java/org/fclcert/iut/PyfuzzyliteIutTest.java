package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.fclcert.check.Analysis;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.DialectWriters;
import org.fclcert.write.Written;
import org.fclcert.syntax.dialect.Dialect;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The real pyfuzzylite 8.0.6 (PyPI, in the virtual environment scripts/ensure-pyfuzzylite makes) through fclcert's
 * bridge ({@code --iut pyfuzzylite}): its version, an FLL program of our own evaluated by hand, standard FCL refused,
 * state kept by {@code lock-previous} until {@code reset}, and a standard program presented through the FLL writer.
 *
 * <p>The lamp (our own program): input dusk with triangles bright (-10, 0, 10) and dark (0, 10, 20), output power with
 * the constants off = 0 and full = 100; bright gives off, dark full. By hand: at dusk = d in [0, 10], bright = 1 - d/10
 * and dark = d/10, so the weighted average is (0 · (1 - d/10) + 100 · d/10) / 1 = 10·d: 25 at 2.5, 50 at 5.
 */
class PyfuzzyliteIutTest {
    private static final IutOptions OPTIONS = IutOptions.defaults().withTimeout(Duration.ofSeconds(20));
    private static final String LAMP = """
            Engine: lamp
            InputVariable: dusk
              enabled: true
              range: 0 10
              lock-range: false
              term: bright Triangle -10 0 10
              term: dark Triangle 0 10 20
            OutputVariable: power
              enabled: true
              range: 0 100
              lock-range: false
              aggregation: none
              defuzzifier: WeightedAverage
              default: 7
              lock-previous: LOCK
              term: off Constant 0
              term: full Constant 100
            RuleBlock: rules
              enabled: true
              conjunction: none
              disjunction: none
              implication: none
              activation: General
              rule: if dusk is bright then power is off
              rule: if dusk is dark then power is full
            """;

    @BeforeAll
    static void installed() {
        Pyfuzzylite.assumeInstalled();
    }

    private static String lamp(boolean lockPrevious) {
        return LAMP.replace("LOCK", Boolean.toString(lockPrevious));
    }

    @Test
    void theBridgeReportsPyfuzzylitesOwnVersion() throws Exception {
        try (ImplementationUnderTest iut = Iuts.open("pyfuzzylite", OPTIONS)) {
            IutInfo info = iut.hello();
            assertEquals("pyfuzzylite", info.name());
            // fuzzylite.__version__ as the library says it; scripts/ensure-pyfuzzylite installs exactly this one
            assertEquals(PyfuzzyliteIut.DEFAULT_VERSION, info.version());
        }
    }

    @Test
    void loadsFllAndEvaluatesByHand() throws Exception {
        try (ImplementationUnderTest iut = Iuts.open("pyfuzzylite", OPTIONS)) {
            assertEquals(new LoadOutcome.Loaded(List.of("lamp")), iut.load(lamp(false)));
            assertEquals(50.0, iut.eval(null, Map.of("dusk", 5.0)).get("power"), 1e-12);
            assertEquals(25.0, iut.eval("LAMP", Map.of("DUSK", 2.5)).get("power"), 1e-12);
            IutException unknown = assertThrows(IutException.class, () -> iut.eval(null, Map.of("dawn", 1.0)));
            assertEquals(Kind.EVAL_ERROR, unknown.kind());
            assertTrue(iut.export().isEmpty(), "pyfuzzylite writes no FCL");
        }
    }

    @Test
    void standardFclIsRefusedByItsFllImporterAtTheFirstLine() throws Exception {
        try (ImplementationUnderTest iut = Iuts.open("pyfuzzylite", OPTIONS)) {
            LoadOutcome outcome = iut.load("FUNCTION_BLOCK lamp\nVAR_INPUT dusk : REAL; END_VAR\nEND_FUNCTION_BLOCK\n");
            LoadOutcome.Rejected rejected = assertInstanceOf(LoadOutcome.Rejected.class, outcome);
            assertTrue(rejected.message().contains("FUNCTION_BLOCK lamp"), rejected.message());
            assertEquals(1, rejected.line().orElse(-1));
        }
    }

    @Test
    void lockPreviousKeepsTheLastValueUntilReset() throws Exception {
        String onlyDark = lamp(true).replace("  rule: if dusk is bright then power is off\n", "");
        try (ImplementationUnderTest iut = Iuts.open("pyfuzzylite", OPTIONS)) {
            iut.load(onlyDark);
            // at dusk 0 no rule fires: first the default 7, then the previous value 100 (dark alone gives full)
            assertEquals(7.0, iut.eval(null, Map.of("dusk", 0.0)).get("power"));
            assertEquals(100.0, iut.eval(null, Map.of("dusk", 5.0)).get("power"), 1e-12);
            assertEquals(100.0, iut.eval(null, Map.of("dusk", 0.0)).get("power"), 1e-12);
            iut.reset();
            assertEquals(7.0, iut.eval(null, Map.of("dusk", 0.0)).get("power"));
        }
    }

    @Test
    void aRuleOfAThousandSubconditionsCrashesItsEvaluationAndTheSessionGoesOn() throws Exception {
        String subconditions = String.join(" and ", java.util.Collections.nCopies(1000, "dusk is dark"));
        String deep = lamp(false).replace("conjunction: none", "conjunction: Minimum").replace(
                "rule: if dusk is dark then", "rule: if " + subconditions + " then");
        try (ImplementationUnderTest iut = Iuts.open("pyfuzzylite", OPTIONS)) {
            assertEquals(new LoadOutcome.Loaded(List.of("lamp")), iut.load(deep));
            // pyfuzzylite evaluates the condition tree recursively: Python's RecursionError, an internal failure
            IutException crash = assertThrows(IutException.class, () -> iut.eval(null, Map.of("dusk", 5.0)));
            assertEquals(Kind.CRASH, crash.kind(), crash.getMessage());
            assertTrue(crash.getMessage().contains("RecursionError"), crash.getMessage());
            iut.load(lamp(false));
            assertEquals(50.0, iut.eval(null, Map.of("dusk", 5.0)).get("power"), 1e-12);
        }
    }

    @Test
    void aStandardProgramRunsAsTheFllWriterPresentsIt() throws Exception {
        String fcl = """
                FUNCTION_BLOCK lamp
                VAR_INPUT dusk : REAL; END_VAR
                VAR_OUTPUT power : REAL; END_VAR
                FUZZIFY dusk
                    TERM bright := (0, 1) (10, 0);
                    TERM dark := (0, 0) (10, 1);
                END_FUZZIFY
                DEFUZZIFY power
                    TERM off := 0;
                    TERM full := 100;
                    METHOD : CoGS;
                    DEFAULT := 0;
                END_DEFUZZIFY
                RULEBLOCK rules
                    AND : MIN;
                    ACCU : MAX;
                    RULE 1 : IF dusk IS bright THEN power IS off;
                    RULE 2 : IF dusk IS dark THEN power IS full;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        Analysis a = Analysis.analyze(StrictReader.openLevel(), "lamp.fcl", fcl);
        Written w = DialectWriters.writer(Dialect.FLL).write(a.program().orElseThrow());
        assertTrue(w.exact(), w.diagnostics().toString());
        try (ImplementationUnderTest iut = Iuts.open("pyfuzzylite", OPTIONS)) {
            assertEquals(new LoadOutcome.Loaded(List.of("lamp")), iut.loadWritten(w.text(), Dialect.FLL));
            // the same 10·d as above: Discrete points for the ramps, Constant terms for the singletons
            assertEquals(25.0, iut.eval(null, Map.of("dusk", 2.5)).get("power"), 1e-12);
            assertEquals(80.0, iut.eval(null, Map.of("dusk", 8.0)).get("power"), 1e-12);
        }
    }
}
