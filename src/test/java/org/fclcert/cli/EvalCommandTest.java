package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class EvalCommandTest {
    @TempDir
    Path dir;

    /** Output y with DEFAULT NC and initial value 7: x IS hi (x >= 1) gives y = 10, else nothing fires. */
    static final String NC = """
            FUNCTION_BLOCK hold
            VAR_INPUT x : REAL; k : REAL := 2; END_VAR
            VAR_OUTPUT y : REAL := 7; END_VAR
            FUZZIFY x TERM hi := (0, 0) (1, 1); END_FUZZIFY
            FUZZIFY k TERM any := (0, 1) (1, 1); END_FUZZIFY
            DEFUZZIFY y
                TERM ten := 10;
                METHOD : CoGS;
                DEFAULT := NC;
            END_DEFUZZIFY
            RULEBLOCK r
                AND : MIN;
                ACCU : MAX;
                RULE 1 : IF x IS hi AND k IS any THEN y IS ten;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            FUNCTION_BLOCK second
            VAR_INPUT a : REAL; END_VAR
            VAR_OUTPUT b : REAL; END_VAR
            FUZZIFY a TERM hi := (0, 0) (1, 1); END_FUZZIFY
            DEFUZZIFY b
                TERM one := 1;
                TERM three := 3;
                METHOD : CoGS;
                DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK r
                ACCU : MAX;
                RULE 1 : IF a IS hi THEN b IS three;
                RULE 2 : IF a IS NOT hi THEN b IS one;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    private String valve() {
        return Cli.write(dir, "valve.fcl", CheckCommandTest.VALVE).toString();
    }

    /* 5.3 at temp 5, pressure 60: 9500/127, printed as Double.toString gives it (shortest round trip). */
    @Test
    void printsOneLinePerOutput() {
        Cli r = Cli.run("eval", valve(), "--in", "temp=5", "--in", "pressure=60");
        assertEquals(0, r.exitCode(), r.err());
        assertEquals(List.of("valve=74.80314960629921"), r.outLines());
        assertEquals(9500.0 / 127, Double.parseDouble(r.outLines().get(0).substring(6)));
    }

    @Test
    void traceShowsEveryStage() {
        Cli r = Cli.run("eval", valve(), "--in", "temp=5", "--in", "pressure=60", "--trace");
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.outLines().contains("fuzzification temp IS cold = 0.9166666666666666"), r.out());
        assertTrue(r.outLines().contains("aggregation No1 RULE 2 = 0.125"), r.out());
        assertTrue(r.outLines().contains("activation No1 RULE 2 valve IS closed weight 0.8 = 0.1"), r.out());
        assertTrue(r.outLines().contains("accumulation valve singletons (-100.0, 0.08333333333333333) (0.0, 0.1) "
                + "(100.0, 0.875)"), r.out());
        assertTrue(r.outLines().contains("result valve = 74.80314960629921 (defuzzified)"), r.out());
    }

    @Test
    void jsonForMachines() throws Exception {
        Cli r = Cli.run("eval", valve(), "--in", "temp=5", "--in", "pressure=60", "--format", "json", "--trace");
        assertEquals(0, r.exitCode(), r.err());
        JsonNode json = new ObjectMapper().readTree(r.out());
        assertEquals("Fuzzy_FB", json.get("block").asText());
        assertEquals(5.0, json.get("inputs").get("temp").asDouble());
        assertEquals(9500.0 / 127, json.get("outputs").get("valve").asDouble());
        assertEquals(0.875, json.get("trace").get("ruleDegrees").get(0).get("degree").asDouble());
        assertEquals("DEFUZZIFIED", json.get("trace").get("results").get(0).get("outcome").asText());
    }

    /*
     * Steps on one instance: x=1 -> 10; x=0 -> nothing fires, NC keeps 10; the empty cell keeps
     * x=0 (still 10); x=1 again -> 10. k is never given: its declared initial value 2 is used.
     * A fresh instance at x=0 would give the initial value 7, which the first step of the second
     * file shows.
     */
    @Test
    void csvStepsCarryStateOver() {
        Path fcl = Cli.write(dir, "hold.fcl", NC);
        Path rows = Cli.write(dir, "rows.csv", "x\n1\n0\n\n# a comment\n \n1\n");
        Cli r = Cli.run("eval", fcl.toString(), "--csv", rows.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertEquals(List.of("x,k,y", "1.0,2.0,10.0", "0.0,2.0,10.0", "1.0,2.0,10.0"), r.outLines());
        Path rows2 = Cli.write(dir, "rows2.csv", "x,k\n0,1\n,\n1,\n");
        Cli r2 = Cli.run("eval", fcl.toString(), "--csv", rows2.toString());
        assertEquals(List.of("x,k,y", "0.0,1.0,7.0", "0.0,1.0,7.0", "1.0,1.0,10.0"), r2.outLines());
    }

    @Test
    void csvToAFileAndAsJson() throws Exception {
        Path fcl = Cli.write(dir, "hold.fcl", NC);
        Path rows = Cli.write(dir, "rows.csv", "x\n1\n0\n");
        Path out = dir.resolve("out.csv");
        Cli r = Cli.run("eval", fcl.toString(), "--csv", rows.toString(), "--out", out.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertEquals("", r.out());
        assertEquals("x,k,y\n1.0,2.0,10.0\n0.0,2.0,10.0\n", Cli.read(out));
        Cli json = Cli.run("eval", fcl.toString(), "--csv", rows.toString(), "--format", "json");
        JsonNode steps = new ObjectMapper().readTree(json.out());
        assertEquals(2, steps.size());
        assertEquals(10.0, steps.get(1).get("outputs").get("y").asDouble());
    }

    /* The second block: a=0.25 -> three 0.25, one 0.75 -> (0.75 + 0.75)/1 = 1.5. */
    @Test
    void blockSelectsTheFunctionBlock() {
        Path fcl = Cli.write(dir, "two.fcl", NC);
        Cli r = Cli.run("eval", fcl.toString(), "--block", "SECOND", "--in", "a=0.25");
        assertEquals(0, r.exitCode(), r.err());
        assertEquals(List.of("b=1.5"), r.outLines());
        Cli unknown = Cli.run("eval", fcl.toString(), "--block", "third", "--in", "a=0.25");
        assertEquals(1, unknown.exitCode());
        assertTrue(unknown.err().contains("FCL-V001") && unknown.err().contains("third"), unknown.err());
    }

    /** A block of 25 inputs: the message names the first 20 and says how many more (100 000 made one huge line). */
    @Test
    void anUnknownNameListsAtMostTwentyInputs() {
        StringBuilder text = new StringBuilder("FUNCTION_BLOCK wide\nVAR_INPUT\n");
        for (int i = 0; i < 25; i++) {
            text.append("    in").append(i).append(" : REAL;\n");
        }
        text.append("END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n");
        for (int i = 0; i < 25; i++) {
            text.append("FUZZIFY in").append(i).append(" TERM t := (0, 0) (1, 1); END_FUZZIFY\n");
        }
        text.append("DEFUZZIFY y TERM one := 1; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY\nRULEBLOCK r ACCU : MAX;\n");
        for (int i = 0; i < 25; i++) {
            text.append("    RULE ").append(i + 1).append(" : IF in").append(i).append(" IS t THEN y IS one;\n");
        }
        text.append("END_RULEBLOCK\nEND_FUNCTION_BLOCK\n");
        Path fcl = Cli.write(dir, "wide.fcl", text.toString());
        Cli unknown = Cli.run("eval", fcl.toString(), "--in", "zz=1");
        assertEquals(1, unknown.exitCode());
        assertEquals(List.of("fclcert: FCL-V001: --in zz=1: function block 'wide' has no variable 'zz'; its inputs: "
                + "in0, in1, in2, in3, in4, in5, in6, in7, in8, in9, in10, in11, in12, in13, in14, in15, in16, in17,"
                + " in18, in19 and 5 more"), unknown.errLines().subList(unknown.errLines().size() - 1,
                unknown.errLines().size()));
    }

    @Test
    void inputErrorsAreClearMessagesWithExitCode1() {
        String valve = valve();
        Cli unknown = Cli.run("eval", valve, "--in", "temp=5", "--in", "presure=60");
        assertEquals(1, unknown.exitCode());
        assertEquals(List.of("fclcert: FCL-V001: --in presure=60: function block 'Fuzzy_FB' has no variable "
                + "'presure'; did you mean 'pressure'? its inputs: temp, pressure"), unknown.errLines());
        Cli far = Cli.run("eval", valve, "--in", "temp=5", "--in", "xyz=60");
        assertEquals(1, far.exitCode());
        assertEquals(List.of("fclcert: FCL-V001: --in xyz=60: function block 'Fuzzy_FB' has no variable "
                + "'xyz'; its inputs: temp, pressure"), far.errLines().subList(far.errLines().size() - 1,
                far.errLines().size()));
        Cli missing = Cli.run("eval", valve, "--in", "temp=5");
        assertEquals(1, missing.exitCode());
        assertTrue(missing.err().contains("input 'pressure' has no value"), missing.err());
        Cli nan = Cli.run("eval", valve, "--in", "temp=NaN", "--in", "pressure=60");
        assertEquals(1, nan.exitCode());
        assertTrue(nan.err().contains("FCL-V002"), nan.err());
        Cli text = Cli.run("eval", valve, "--in", "temp=warm", "--in", "pressure=60");
        assertEquals(1, text.exitCode());
        assertTrue(text.err().contains("'warm' is not a number"), text.err());
        Cli output = Cli.run("eval", valve, "--in", "valve=1");
        assertEquals(1, output.exitCode());
        assertTrue(output.err().contains("FCL-V003"), output.err());
        Path rows = Cli.write(dir, "bad.csv", "temp,pressure\n5,60\n5\n");
        Cli csv = Cli.run("eval", valve, "--csv", rows.toString());
        assertEquals(1, csv.exitCode());
        assertTrue(csv.err().contains("bad.csv:3: 1 cell where the header has 2"), csv.err());
        // a header typo is the header's mistake: line 1, before any row is evaluated
        Path typo = Cli.write(dir, "typo.csv", "temp,presure\n5,60\n");
        Cli header = Cli.run("eval", valve, "--csv", typo.toString());
        assertEquals(1, header.exitCode());
        assertEquals(List.of("fclcert: FCL-V001: " + typo + ":1: column 'presure': function block 'Fuzzy_FB' has no"
                + " variable 'presure'; did you mean 'pressure'? its inputs: temp, pressure"), header.errLines());
        Path semi = Cli.write(dir, "semi.csv", "temp;pressure\n5;60\n");
        Cli semicolons = Cli.run("eval", valve, "--csv", semi.toString());
        assertEquals(1, semicolons.exitCode());
        assertEquals(List.of("fclcert: " + semi + ":1: the header is separated by semicolons; eval --csv reads"
                + " comma-separated values (e.g. temp,pressure)"), semicolons.errLines());
    }

    /* Issue 18 item 13: Java's number spellings are not numbers to a user (0x1p2 is 4.0 to parseDouble). */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(strings = {"0x1p2", "5d", "5f", "5D", "0X10", "1_0"})
    void javaNumberSpellingsAreRejected(String spelling) {
        Cli in = Cli.run("eval", valve(), "--in", "temp=" + spelling, "--in", "pressure=60");
        assertEquals(1, in.exitCode());
        assertEquals(List.of("fclcert: --in temp=" + spelling + ": '" + spelling + "' is not a number: write a decimal"
                + " number such as 4, -2.5 or 1.5E3"), in.errLines());
        Path rows = Cli.write(dir, "java.csv", "temp,pressure\n5,60\n" + spelling + ",60\n");
        Cli csv = Cli.run("eval", valve(), "--csv", rows.toString());
        assertEquals(1, csv.exitCode());
        assertTrue(csv.err().contains("'" + spelling + "' is not a number"), csv.err());
        assertEquals("", csv.out());
    }

    @Test
    void decimalSpellingsAreNumbers() {
        for (String spelling : List.of("5", "+5", "5.", ".5E1", "5.0e0", "50E-1")) {
            Cli r = Cli.run("eval", valve(), "--in", "temp=" + spelling, "--in", "pressure=60");
            assertEquals(0, r.exitCode(), spelling + ": " + r.err());
            assertEquals(Cli.run("eval", valve(), "--in", "temp=5", "--in", "pressure=60").out(), r.out(), spelling);
        }
    }

    /* The valve with an undefined term (line 29, column 54, see CheckCommandTest) is not evaluated. */
    @Test
    void programWithErrorsIsNotEvaluated() {
        Path bad = Cli.write(dir, "bad.fcl", CheckCommandTest.UNDEFINED_TERM);
        Cli r = Cli.run("eval", bad.toString(), "--in", "temp=5", "--in", "pressure=60");
        assertEquals(1, r.exitCode());
        assertEquals("", r.out());
        assertTrue(r.errLines().get(0).startsWith(bad + ":29:54: error FCL-C002: "), r.err());
        assertTrue(r.err().contains("has errors; not evaluated"), r.err());
    }

    @Test
    void usageAndFileProblemsGiveExitCode2() {
        assertEquals(2, Cli.run("eval", dir.resolve("none.fcl").toString()).exitCode());
        assertEquals(2, Cli.run("eval", valve(), "--in", "temp").exitCode());
        assertEquals(2, Cli.run("eval", valve(), "--csv", dir.resolve("none.csv").toString()).exitCode());
        Cli both = Cli.run("eval", valve(), "--csv", "x.csv", "--trace");
        assertEquals(2, both.exitCode());
        assertTrue(both.err().contains("--trace cannot be combined with --csv"), both.err());
    }
}
