package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import java.util.OptionalLong;
import org.fclcert.iut.IutException.Kind;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The fuzzylite adapter driving the real fuzzylite 6.0 command line (skipped when it is not installed,
 * failing when CI is set), and — with small shell scripts standing in for the binary — its handling of
 * hangs, crashes and a binary that is not there.
 *
 * <p>Expected values are worked out by hand from fuzzylite's documented CoGS: its "WeightedAverage" sums
 * every rule's activation separately, Σ wᵢ·vᵢ / Σ wᵢ over the rules that fired, where the standard first
 * accumulates per term (ACCU MAX: two rules concluding the same singleton count once).
 */
class FuzzyliteIutTest {
    private static final double EXACT = 1e-9;

    /**
     * Clause 5.3's valve example (figure 7) in the layout fuzzylite reads: {@code ACCU} inside DEFUZZIFY,
     * {@code METHOD : COGS} with a blank before the colon and in upper case, rule keywords in lower case.
     * The numbers are those of the standard.
     */
    static final String VALVE_FUZZYLITE_LAYOUT = """
            FUNCTION_BLOCK Fuzzy_FB
            VAR_INPUT
                temp: REAL;
                pressure: REAL;
            END_VAR
            VAR_OUTPUT
                valve: REAL;
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
                ACCU : MAX;
                METHOD : COGS;
                DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK No1
                AND : MIN;
                RULE 1 : if temp is cold and pressure is low then valve is inlet;
                RULE 2 : if temp is cold and pressure is high then valve is closed with 0.8;
                RULE 3 : if temp is hot and pressure is low then valve is closed;
                RULE 4 : if temp is hot and pressure is high then valve is drainage;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /**
     * One input, two singletons; at x = 10 neither term has a degree above 0 (lo falls to 0 at 10, hi rises
     * from 0 at 10), so nothing fires. {@code defaultLine} is the DEFAULT line of the DEFUZZIFY block (line 17;
     * empty for none).
     */
    private static String idleAt10(String defaultLine) {
        return """
                FUNCTION_BLOCK idle
                VAR_INPUT
                    x: REAL;
                END_VAR
                VAR_OUTPUT
                    y: REAL;
                END_VAR
                FUZZIFY x
                    TERM lo := (0, 1) (10, 0);
                    TERM hi := (10, 0) (20, 1);
                END_FUZZIFY
                DEFUZZIFY y
                    TERM one := 1;
                    TERM two := 2;
                    ACCU : MAX;
                    METHOD : COGS;
                %s
                END_DEFUZZIFY
                RULEBLOCK r
                    AND : MIN;
                    RULE 1 : if x is lo then y is one;
                    RULE 2 : if x is hi then y is two;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """.formatted(defaultLine);
    }

    private static ImplementationUnderTest fuzzylite() throws IutException {
        Fuzzylite.assumeInstalled();
        return Iuts.open("fuzzylite", Fuzzylite.options());
    }

    private static double valve(ImplementationUnderTest iut, double temp, double pressure) throws IutException {
        Map<String, Double> out = iut.eval(null, Map.of("temp", temp, "pressure", pressure));
        assertEquals(List.of("valve"), List.copyOf(out.keySet()));
        return out.get("valve");
    }

    @Test
    void helloNamesFuzzyliteAndTheVersionItsBannerGives() throws IutException {
        try (ImplementationUnderTest iut = fuzzylite()) {
            IutInfo info = iut.hello();
            assertEquals("fuzzylite", info.name());
            assertEquals("6.0", info.version());
            assertEquals("fuzzylite", info.command());
            assertEquals(List.of(), info.claims());
        }
    }

    @Test
    void theStandardsOwnValveExampleIsRejectedAtItsFirstLineForTheComment() throws Exception {
        try (ImplementationUnderTest iut = fuzzylite()) {
            String valve = Files.readString(Path.of("examples/valve.fcl"));
            LoadOutcome outcome = iut.load(valve);
            LoadOutcome.Rejected rejected = assertInstanceOf(LoadOutcome.Rejected.class, outcome);
            assertTrue(rejected.message().contains("unknown block definition <(*>"), rejected.message());
            assertEquals(OptionalInt.of(1), rejected.line());

            // without the comment it stops at 'METHOD: CoGS;' (line 22 of the file), which it quotes without a number
            String uncommented = valve.replaceFirst("\\(\\*[^\n]*\\*\\)", "");
            rejected = assertInstanceOf(LoadOutcome.Rejected.class, iut.load(uncommented));
            assertTrue(rejected.message().contains("unexpected token <METHOD:> in line: METHOD: CoGS"), rejected.message());
            assertEquals(OptionalInt.of(22), rejected.line());
            assertThrows(IutException.class, () -> iut.eval(null, Map.of("temp", 5.0)), "no program is loaded after a rejection");
        }
    }

    @Test
    void theValveInFuzzylitesLayoutSumsEveryRuleSeparatelyUnderCogs() throws IutException {
        try (ImplementationUnderTest iut = fuzzylite()) {
            assertEquals(new LoadOutcome.Loaded(List.of("Fuzzy_FB")), iut.load(VALVE_FUZZYLITE_LAYOUT));
            // temp 5: cold 22/24 = 11/12, hot 1/12; pressure 60: low 35/40 = 7/8, high 1/8.
            // R1 7/8 -> inlet, R2 min(11/12, 1/8)·0.8 = 1/10 -> closed, R3 1/12 -> closed, R4 1/12 -> drainage.
            // fuzzylite, per rule: (100·7/8 + 0·1/10 + 0·1/12 − 100·1/12) / (7/8 + 1/10 + 1/12 + 1/12)
            //   = (1050/12 − 100/12) / (137/120) = (950/12)·(120/137) = 9500/137 ≈ 69.3431
            // (the standard, MAX per term, keeps closed = 1/10 once: 9500/127 ≈ 74.8031).
            assertEquals(9500.0 / 137, valve(iut, 5, 60), EXACT);
            // temp 20: cold 7/24, hot 17/24; pressure 90: low 5/40 = 1/8, high 7/8.
            // R1 min(7/24, 1/8) = 1/8, R2 min(7/24, 7/8)·0.8 = 7/30, R3 min(17/24, 1/8) = 1/8, R4 17/24.
            // per rule: (100/8 − 100·17/24) / (1/8 + 7/30 + 1/8 + 17/24) = (−1400/24) / (143/120) = −7000/143
            // (the standard: closed = max(7/30, 1/8) = 7/30, denominator 128/120, −7000/128 = −54.6875).
            assertEquals(-7000.0 / 143, valve(iut, 20, 90), EXACT);
            // temp 3, pressure 55: cold 1, low 1, hot = high = 0: only R1 fires, the result is inlet's 100.
            assertEquals(100.0, valve(iut, 3, 55), EXACT);
        }
    }

    /** A program of ours in fuzzylite's layout: Einstein ACT and ACCU, and a Tsukamoto output of a ramp and a sigmoid. */
    static String mixer() throws java.io.IOException {
        return Files.readString(Path.of("src/test/resources/org/fclcert/syntax/dialect/fuzzylite/einstein-tsukamoto.fcl"));
    }

    /**
     * fuzzylite and fclcert's reading of Einstein norms and Tsukamoto's method agree: the Tsukamoto output exactly
     * (by hand), the Einstein-activated CoG to fuzzylite's 100-sample integration (the midpoint rule written here).
     */
    @Test
    void einsteinNormsAndTsukamotoAsFclcertReadsThem() throws Exception {
        org.fclcert.check.Analysis a = org.fclcert.check.Analysis.analyze(org.fclcert.syntax.dialect.DialectReaders
                .reader(org.fclcert.syntax.dialect.Dialect.FUZZYLITE), "mixer.fcl", mixer());
        org.fclcert.eval.FunctionBlockInstance ours = org.fclcert.eval.Evaluator.load(a.program().orElseThrow(
                () -> new AssertionError(a.diagnostics()))).newInstance();
        try (ImplementationUnderTest iut = fuzzylite()) {
            assertEquals(new LoadOutcome.Loaded(List.of("mixer")), iut.load(mixer()));
            // x = 2.5: lo 0.75, hi 0.25. valve: the falling ramp 1 → 0 is 0.75 at 0.25, the sigmoid
            // 1/(1 + e^(−12(u − 0.5))) is 0.25 at 0.5 − ln 3 / 12: (0.75·0.25 + 0.25·(0.5 − ln 3/12)) / 1
            double valve = 0.75 * 0.25 + 0.25 * (0.5 - Math.log(3) / 12);
            Map<String, Double> theirs = iut.eval("mixer", Map.of("x", 2.5));
            ours.set("x", 2.5);
            ours.evaluate();
            assertEquals(valve, theirs.get("valve"), EXACT);
            assertEquals(valve, ours.get("valve"), EXACT);
            // heat: EPROD(d, triangle) on each triangle (they do not overlap, so ESUM leaves each as it is), its
            // CoG by a 10⁶-sample midpoint rule; fuzzylite samples 100 points: agreement to a sample step's order
            double area = 0;
            double moment = 0;
            int n = 1_000_000;
            for (int i = 0; i < n; i++) {
                double u = (i + 0.5) * 20.0 / n;
                double mu = Math.max(0, 1 - Math.abs(u - (u < 10 ? 5 : 15)) / 5);
                double d = u < 10 ? 0.75 : 0.25;
                double c = d * mu / (2 - (d + mu - d * mu));
                area += c;
                moment += u * c;
            }
            assertEquals(moment / area, ours.get("heat"), 1e-6);
            assertEquals(moment / area, theirs.get("heat"), 0.02);
        }
    }

    @Test
    void aRuleFuzzyliteCannotReadIsDroppedSilentlyAndShowsAsAWrongValue() throws IutException {
        try (ImplementationUnderTest iut = fuzzylite()) {
            String upperCaseIf = VALVE_FUZZYLITE_LAYOUT.replace("RULE 2 : if", "RULE 2 : IF");
            assertInstanceOf(LoadOutcome.Loaded.class, iut.load(upperCaseIf), "the program still loads");
            // without R2: (100·7/8 − 100·1/12) / (7/8 + 1/12 + 1/12) = (950/12) / (25/24) = 76
            assertEquals(76.0, valve(iut, 5, 60), EXACT);
        }
    }

    @Test
    void inputNamesMatchWithoutRegardToLetterCaseAndUnknownOnesAreEvaluationErrors() throws IutException {
        try (ImplementationUnderTest iut = fuzzylite()) {
            iut.load(VALVE_FUZZYLITE_LAYOUT);
            assertEquals(9500.0 / 137, iut.eval("FUZZY_FB", Map.of("TEMP", 5.0, "Pressure", 60.0)).get("valve"), EXACT);
            IutException unknown = assertThrows(IutException.class, () -> iut.eval(null, Map.of("humidity", 1.0)));
            assertEquals(Kind.EVAL_ERROR, unknown.kind());
            assertTrue(unknown.getMessage().contains("'humidity' is not an input"), unknown.getMessage());
            IutException block = assertThrows(IutException.class, () -> iut.eval("other", Map.of("temp", 1.0)));
            assertEquals(Kind.EVAL_ERROR, block.kind());
            assertTrue(block.getMessage().contains("only function block 'Fuzzy_FB'"), block.getMessage());
        }
    }

    @Test
    void withoutDefaultAnOutputWhereNothingFiredIsNan() throws IutException {
        try (ImplementationUnderTest iut = fuzzylite()) {
            assertInstanceOf(LoadOutcome.Loaded.class, iut.load(idleAt10("")));
            assertEquals(1.0, iut.eval(null, Map.of("x", 5.0)).get("y"), EXACT);   // lo = 1/2 alone: singleton 1
            assertTrue(Double.isNaN(iut.eval(null, Map.of("x", 10.0)).get("y")));
        }
    }

    @Test
    void theStandardsDefaultNcIsRejectedButFuzzylitesNanOrNcKeepsTheLastValueOverSteps() throws IutException {
        try (ImplementationUnderTest iut = fuzzylite()) {
            String standard = idleAt10("    DEFAULT := NC;");
            LoadOutcome.Rejected rejected = assertInstanceOf(LoadOutcome.Rejected.class, iut.load(standard));
            assertTrue(rejected.message().contains("expected numeric value, but found <NC>"), rejected.message());
            assertEquals(OptionalInt.of(17), rejected.line());

            assertInstanceOf(LoadOutcome.Loaded.class, iut.load(idleAt10("    DEFAULT := nan | NC;")));
            assertEquals(1.0, iut.eval(null, Map.of("x", 5.0)).get("y"), EXACT);    // lo fires
            assertEquals(1.0, iut.eval(null, Map.of("x", 10.0)).get("y"), EXACT);   // nothing fires: kept
            assertEquals(2.0, iut.eval(null, Map.of("x", 15.0)).get("y"), EXACT);   // hi fires
            assertEquals(2.0, iut.eval(null, Map.of()).get("y"), EXACT);            // x stays 15
            assertEquals(2.0, iut.eval(null, Map.of("x", 10.0)).get("y"), EXACT);   // kept again
            iut.reset();
            // a fresh engine has no previous value: fuzzylite starts from nan (the standard from 0)
            assertTrue(Double.isNaN(iut.eval(null, Map.of("x", 10.0)).get("y")));
            assertEquals(2.0, iut.eval(null, Map.of("x", 15.0)).get("y"), EXACT);
        }
    }

    @Test
    void exportIsFuzzylitesOwnFclWhichTheHarnessThenChecks() throws IutException {
        try (ImplementationUnderTest iut = fuzzylite()) {
            IutException none = assertThrows(IutException.class, iut::export);
            assertEquals(Kind.EVAL_ERROR, none.kind());
            iut.load(VALVE_FUZZYLITE_LAYOUT);
            String fcl = iut.export().orElseThrow();
            assertTrue(fcl.startsWith("//Code automatically generated with fuzzylite 6.0."), fcl);
            assertTrue(fcl.contains("RANGE := (-inf .. inf);"), fcl);
            assertTrue(fcl.contains("RULE 2 : if temp is cold and pressure is high then valve is closed with 0.8"), fcl);
        }
    }

    @Test
    void peakMemoryIsMeasuredWhereGnuTimeIsInstalled() throws IutException {
        try (ImplementationUnderTest iut = fuzzylite()) {
            iut.load(VALVE_FUZZYLITE_LAYOUT);
            valve(iut, 5, 60);
            OptionalLong peak = iut.peakMemoryBytes();
            assertEquals(FuzzyliteProcess.gnuTimeAvailable(Duration.ofSeconds(5)), peak.isPresent(), "measured exactly when GNU time is there");
            if (peak.isPresent()) {
                assertTrue(peak.getAsLong() > 512 * 1024 && peak.getAsLong() < 1024L * 1024 * 1024, "peak RSS " + peak);
            }
        }
    }

    // --- failures, with shell scripts standing in for the binary (these need no fuzzylite) ---

    /** A stand-in that answers --help like fuzzylite and runs {@code body} for every other launch. */
    private static String fake(Path dir, String body) throws Exception {
        // readable by others: as root, the sandbox runs the launch as an unprivileged uid (JUnit's directory is 700)
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        Path script = dir.resolve("fake-fuzzylite");
        Files.writeString(script, "#!/bin/sh\nif [ \"$1\" = --help ]; then echo 'version: 6.0'; exit 0; fi\n" + body + "\n");
        Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwxr-xr-x"));
        return "fuzzylite:" + script;
    }

    @Test
    void aBinaryThatIsNotThereIsAnInfrastructureErrorWithAClearMessage() throws IutException {
        try (ImplementationUnderTest iut = Iuts.open("fuzzylite:/nonexistent/bin/fuzzylite", IutOptions.defaults())) {
            IutException e = assertThrows(IutException.class, iut::hello);
            assertEquals(Kind.INFRA, e.kind());
            assertTrue(e.getMessage().startsWith("could not start /nonexistent/bin/fuzzylite"), e.getMessage());
            assertTrue(e.getMessage().contains("apt-get install fuzzylite"), e.getMessage());
        }
        IutException malformed = assertThrows(IutException.class, () -> Iuts.open("fuzzylite:", IutOptions.defaults()));
        assertEquals(Kind.INFRA, malformed.kind());
        IutException noVersion = assertThrows(IutException.class,
                () -> Iuts.open("fuzzylite:/bin/true", IutOptions.defaults()).hello());
        assertEquals(Kind.INFRA, noVersion.kind());
        assertTrue(noVersion.getMessage().contains("does not name a version"), noVersion.getMessage());
    }

    @Test
    void aHangingLaunchTimesOutAndItsChildProcessIsKilled(@TempDir Path dir) throws Exception {
        Path pid = dir.resolve("child.pid");
        String spec = fake(dir, "sleep 60 &\necho $! > " + pid + "\nwait");
        // without the sandbox: the test reads the host pid the launch writes (in the sandbox the PID namespace ends it)
        IutOptions options = IutOptions.defaults().withTimeout(Duration.ofMillis(700)).withRestartBudget(1)
                .withSandbox(org.fclcert.sandbox.SandboxSettings.none());
        try (ImplementationUnderTest iut = Iuts.open(spec, options)) {
            assertEquals("6.0", iut.hello().version());
            long start = System.nanoTime();
            IutException e = assertThrows(IutException.class, () -> iut.load(VALVE_FUZZYLITE_LAYOUT));
            assertEquals(Kind.TIMEOUT, e.kind());
            assertTrue((System.nanoTime() - start) / 1_000_000 < 5000, "the timeout, not the sleep, ended the wait");
            long child = Long.parseLong(Files.readString(pid).strip());
            assertFalse(ProcessIutTest.runningAfter(child, 2000), "the script's child 'sleep' was killed too");
            // the restart budget of 1 allows one more timed-out launch; after that every request gives up at once
            assertEquals(Kind.TIMEOUT, assertThrows(IutException.class, () -> iut.load("x")).kind());
            assertEquals(Kind.GAVE_UP, assertThrows(IutException.class, () -> iut.load("x")).kind());
        }
    }

    @Test
    void aLaunchKilledByASignalIsACrashWithItsExitCodeAndStderr(@TempDir Path dir) throws Exception {
        String spec = fake(dir, "echo 'free(): invalid pointer' >&2\nkill -SEGV $$");
        try (ImplementationUnderTest iut = Iuts.open(spec, IutOptions.defaults())) {
            IutException e = assertThrows(IutException.class, () -> iut.load(VALVE_FUZZYLITE_LAYOUT));
            assertEquals(Kind.CRASH, e.kind());
            assertTrue(e.getMessage().contains("exited with code 139 while loading (killed by signal 11)"), e.getMessage());
            assertTrue(e.stderrTail().contains("free(): invalid pointer"), e.stderrTail());
        }
    }

    @Test
    void anOutputTableWithRowsMissingAndNoMessageIsAProtocolFault(@TempDir Path dir) throws Exception {
        // loading writes an FLL file; evaluating writes a header and no row at all
        String spec = fake(dir, String.join("\n",
                "while [ $# -gt 0 ]; do case \"$1\" in -of) of=$2;; -o) o=$2;; esac; shift; done",
                "if [ \"$of\" = fll ]; then printf 'Engine: e\\nInputVariable: x\\nOutputVariable: y\\n' > \"$o\"; fi",
                "if [ \"$of\" = fld ]; then printf 'y\\n' > \"$o\"; fi"));
        try (ImplementationUnderTest iut = Iuts.open(spec, IutOptions.defaults())) {
            assertEquals(new LoadOutcome.Loaded(List.of("e")), iut.load("anything"));
            IutException e = assertThrows(IutException.class, () -> iut.eval(null, Map.of("x", 1.0)));
            assertEquals(Kind.PROTOCOL, e.kind());
            assertTrue(e.getMessage().contains("wrote 0 result rows for 1 input rows"), e.getMessage());
        }
    }
}
