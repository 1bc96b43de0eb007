package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 30's smaller points: {@code fmt --check} with its unified diff (compared with GNU diff where it is
 * installed, an independent implementation), {@code -} for standard input in fmt and features, warnings kept
 * beside a syntax error, and {@code plot --axes} with the regions where no rule fires drawn on the surface.
 */
class KeyboardFeaturesTest {
    @Test
    void fmtCheckExitsOneWithAUnifiedDiffAndZeroWhenCanonical(@TempDir Path dir) {
        Path canonical = Cli.write(dir, "c.fcl", FmtCommandTest.CANONICAL_VALVE);
        Cli ok = Cli.run("fmt", "--check", canonical.toString());
        assertEquals(0, ok.exitCode(), ok.err());
        assertEquals("", ok.out());
        // lower-case keywords on line 3 and a missing blank line before line 7 (VAR_OUTPUT)
        String messy = FmtCommandTest.CANONICAL_VALVE.replace("    temp : REAL;", "    temp : real;")
                .replace("END_VAR\n\nVAR_OUTPUT", "END_VAR\nVAR_OUTPUT");
        Path file = Cli.write(dir, "m.fcl", messy);
        Cli r = Cli.run("fmt", "--check", file.toString());
        assertEquals(1, r.exitCode(), r.err());
        assertEquals(List.of("--- " + file, "+++ " + file + " (canonical)",
                "@@ -1,8 +1,9 @@",
                " FUNCTION_BLOCK Fuzzy_FB",
                " VAR_INPUT",
                "-    temp : real;",
                "+    temp : REAL;",
                "     pressure : REAL;",
                " END_VAR",
                "+",
                " VAR_OUTPUT",
                "     valve : REAL;",
                " END_VAR"), r.outLines());
        assertEquals("fclcert: " + file + " is not in canonical layout ('fclcert fmt --write " + file
                + "' rewrites it)", r.errLines().get(0));
        assertEquals(messy, Cli.read(file), "--check never writes");
        assertEquals(2, Cli.run("fmt", "--check", "--write", file.toString()).exitCode());
    }

    @Test
    void theDiffHasTheHunksGnuDiffFinds(@TempDir Path dir) throws Exception {
        assumeGnuDiff();
        String a = String.join("\n", lines(1, 40)) + "\n";
        List<String> changed = new ArrayList<>(lines(1, 40));
        changed.set(4, "five");
        changed.remove(19);
        changed.add(30, "inserted");
        changed.set(38, "thirty-nine");
        String b = String.join("\n", changed) + "\n";
        Path fa = Cli.write(dir, "a", a);
        Path fb = Cli.write(dir, "b", b);
        Process p = new ProcessBuilder("diff", "-u", fa.toString(), fb.toString()).redirectErrorStream(true).start();
        List<String> gnu = new String(p.getInputStream().readAllBytes()).lines().skip(2).toList();
        p.waitFor();
        List<String> ours = UnifiedDiff.of("a", a, "b", b).lines().skip(2).toList();
        assertEquals(gnu, ours);
        assertTrue(ours.stream().filter(l -> l.startsWith("@@")).count() >= 3, ours::toString);
    }

    private static List<String> lines(int from, int to) {
        List<String> out = new ArrayList<>();
        for (int i = from; i <= to; i++) {
            out.add("line " + i);
        }
        return out;
    }

    private static void assumeGnuDiff() {
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isExecutable(Path.of("/usr/bin/diff")),
                "GNU diff is not installed: the independent comparison is skipped");
    }

    @Test
    void fmtAndFeaturesReadStandardInput() {
        String text = FmtCommandTest.CANONICAL_VALVE.replace("    temp : REAL;", "    temp : real;");
        Cli fmt = SarifOutputTest.withStdin(text, "fmt", "-");
        assertEquals(0, fmt.exitCode(), fmt.err());
        assertEquals(FmtCommandTest.CANONICAL_VALVE, fmt.out());
        Cli check = SarifOutputTest.withStdin(text, "fmt", "--check", "-");
        assertEquals(1, check.exitCode());
        assertEquals("--- <stdin>", check.outLines().get(0));
        assertEquals(2, SarifOutputTest.withStdin(text, "fmt", "--write", "-").exitCode());
        Cli features = SarifOutputTest.withStdin(text, "features", "-");
        assertEquals(0, features.exitCode(), features.err());
        assertTrue(features.out().contains("<stdin>: lowest conformance level that can run it: extension"), features.out());
        Cli broken = SarifOutputTest.withStdin("FUNCTION_BLOCK\n", "check", "-");
        assertTrue(broken.outLines().get(0).startsWith("<stdin>:"), broken.out());
    }

    @Test
    void aReaderWarningAfterASyntaxErrorIsStillReported(@TempDir Path dir) {
        // the missing ';' on line 13 is an error; the RANGE := on line 25 (FCL-W103) comes after it and is reported
        // from the text the reader recovered, as are the checks' warnings (the unused 'falling', line 19)
        String text = Cli.read(Path.of("examples/heater.fcl"))
                .replace("DEFUZZIFY heat\n", "DEFUZZIFY heat\n    RANGE := (0 .. 100);\n")
                .replace("    TERM cold := (1, 0) (5, 1);", "    TERM cold := (1, 0) (5, 1)");
        Cli r = Cli.run("check", Cli.write(dir, "w.fcl", text).toString());
        assertEquals(1, r.exitCode());
        List<String> codes = r.outLines().stream().map(l -> l.substring(l.indexOf(':') + 1, l.indexOf(':',
                l.indexOf(": ") + 2))).toList();
        assertTrue(codes.contains("13:31: error FCL-S014"), codes::toString);
        assertTrue(codes.contains("19:5: warning FCL-W001"), codes::toString);
        assertTrue(codes.contains("25:11: warning FCL-W103"), codes::toString);
    }

    @Test
    void plotAxesChoosesTheSurfaceAndTheGapsAreDrawn(@TempDir Path dir) throws Exception {
        Cli r = Cli.run("plot", "--axes", "trend,error", "--out", dir.toString(), "examples/heater.fcl");
        assertEquals(0, r.exitCode(), r.err());
        Path surface = dir.resolve("heater-heat-over-trend-and-error.svg");
        assertTrue(r.outLines().contains(surface.toString()), r.out());
        String svg = Files.readString(surface);
        // three regions (W005 of examples/heater.fcl): trend <= 0 and error <= -1, and the lines error = -1 and 1
        // (-1 with trend > 0); x is trend over [-2, 2], y error over [-5, 5]: 100 px per unit of trend, 30 per error
        List<String> gaps = svg.lines().filter(l -> l.contains("class=\"gap\"")).toList();
        assertEquals(3, gaps.size(), svg);
        assertTrue(gaps.get(0).contains("x=\"64\" y=\"216\" width=\"200\" height=\"120\""), gaps.get(0));
        assertTrue(svg.contains("hatched: no rule fires, heat falls back (FCL-W005)"));
        assertEquals(2, Cli.run("plot", "--axes", "trend", "examples/heater.fcl", "--out", dir.toString()).exitCode());
        Cli wrong = Cli.run("plot", "--axes", "trend,eror", "examples/heater.fcl", "--out", dir.toString());
        assertEquals(2, wrong.exitCode());
        assertEquals(List.of("fclcert: --axes eror: not an input with terms; the inputs with terms: error, trend"),
                wrong.errLines().stream().filter(l -> l.startsWith("fclcert: --axes")).toList());
        Cli twice = Cli.run("plot", "--in", "trend=1", "--in", "TREND=2", "examples/heater.fcl", "--out",
                dir.toString());
        assertEquals(2, twice.exitCode());
        assertEquals(List.of("fclcert: --in TREND is given twice; give each input once"), twice.errLines());
    }

    @Test
    void evalCsvSkipsUnknownColumnsOnRequestAndRefusesRepeatedColumnsAndInputs(@TempDir Path dir) {
        // logged data with a time stamp; the valve's values at temp 5, pressure 60 and 90 are README's (74.803..,
        // 4.587..), worked out there by the evaluator's own tests
        Path csv = Cli.write(dir, "log.csv", "time,temp,pressure\n0,5,60\n10,5,90\n");
        Cli refused = Cli.run("eval", "examples/valve.fcl", "--csv", csv.toString());
        assertEquals(1, refused.exitCode());
        assertTrue(refused.err().contains(":1: column 'time': function block 'Fuzzy_FB' has no variable"), refused.err());
        Cli r = Cli.run("eval", "examples/valve.fcl", "--csv", csv.toString(), "--ignore-unknown-columns");
        assertEquals(0, r.exitCode(), r.err());
        assertEquals(List.of("temp,pressure,valve", "5.0,60.0,74.80314960629921", "5.0,90.0,4.587155963302753"),
                r.outLines());
        Path twice = Cli.write(dir, "twice.csv", "temp,pressure,TEMP\n5,60,6\n");
        Cli repeated = Cli.run("eval", "examples/valve.fcl", "--csv", twice.toString());
        assertEquals(1, repeated.exitCode());
        assertEquals(List.of("fclcert: " + twice + ":1: column 'TEMP' is given twice (columns 1 and 3); give each"
                + " input one column"), repeated.errLines());
        Cli in = Cli.run("eval", "examples/valve.fcl", "--in", "temp=5", "--in", "pressure=60", "--in", "temp=6");
        assertEquals(2, in.exitCode());
        assertEquals(List.of("fclcert: --in temp is given twice; give each input once"), in.errLines());
    }
}
