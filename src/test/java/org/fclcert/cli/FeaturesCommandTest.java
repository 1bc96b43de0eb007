package org.fclcert.cli;

import static org.fclcert.cli.CheckCommandTest.UNDEFINED_TERM;
import static org.fclcert.cli.CheckCommandTest.VALVE;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class FeaturesCommandTest {
    /**
     * What the valve of 5.3 uses, read off Tables 8 and 9: a function block with inputs and outputs,
     * input terms of two constant points with degrees 0/1, constant output singletons, AND MIN,
     * ACCU MAX, CoGS, a DEFAULT value, one rule block, IF ... IS ... subconditions, one subconclusion
     * per rule - all Basic - and rule 2's constant WITH 0.8, which Table 9 lists: so Extension.
     */
    private static final Set<String> VALVE_FEATURES = Set.of("B-FB", "B-IN-TERM", "B-OUT-SINGLETON", "B-AND-MIN",
            "B-ACCU-MAX", "B-COGS", "B-DEFAULT-VALUE", "B-ONE-RULEBLOCK", "B-SUBCONDITIONS", "B-ONE-SUBCONCLUSION",
            "E-WITH-CONST");

    @TempDir
    Path dir;

    @Test
    void jsonGivesTheLevelAndEveryFeatureUse() throws Exception {
        Path valve = Cli.write(dir, "valve.fcl", VALVE);
        Cli r = Cli.run("features", "--format", "json", valve.toString());
        assertEquals(0, r.exitCode(), r.err());
        JsonNode report = new ObjectMapper().readTree(r.out());
        assertEquals("extension", report.get("level").asText());
        Set<String> ids = new TreeSet<>();
        List<JsonNode> withConst = new ArrayList<>();
        for (JsonNode f : report.get("features")) {
            ids.add(f.get("id").asText());
            assertEquals(f.get("id").asText().startsWith("B-") ? 8 : 9, f.get("table").asInt(), f.toString());
            assertTrue(f.get("line").asInt() >= 1 && f.get("column").asInt() >= 1, f.toString());
            assertTrue(!f.get("description").asText().isBlank(), f.toString());
            if (f.get("id").asText().equals("E-WITH-CONST")) {
                withConst.add(f);
            }
        }
        assertEquals(new TreeSet<>(VALVE_FEATURES), ids);
        assertEquals(1, withConst.size());
        // the factor 0.8 of rule 2: line 28, column 77 (see CheckCommandTest.ZERO_WEIGHT)
        assertEquals(28, withConst.get(0).get("line").asInt());
        assertEquals(77, withConst.get(0).get("column").asInt());
    }

    @Test
    void textGroupsFeaturesByLevel() {
        Path valve = Cli.write(dir, "valve.fcl", VALVE);
        Cli r = Cli.run("features", valve.toString());
        assertEquals(0, r.exitCode(), r.err());
        List<String> lines = r.outLines();
        assertEquals(valve + ": lowest conformance level that can run it: extension", lines.get(0));
        int basic = lines.indexOf("Basic level (Table 8)");
        int extension = lines.indexOf("Extension level (Table 9)");
        assertTrue(basic > 0 && extension > basic, r.out());
        // 10 Basic rows, a blank line, the Extension heading, 1 Extension row
        assertEquals(basic + 12, extension, r.out());
        assertTrue(lines.get(extension + 1).startsWith("  E-WITH-CONST "), r.out());
        assertTrue(lines.get(extension + 1).endsWith(" at 28:77"), r.out());
        assertEquals(extension + 2, lines.size(), r.out());
    }

    @Test
    void aProgramWithErrorsGetsItsDiagnosticsAndExitCodeOne() {
        Path bad = Cli.write(dir, "bad.fcl", UNDEFINED_TERM);
        Cli r = Cli.run("features", bad.toString());
        assertEquals(1, r.exitCode());
        assertEquals(1, r.outLines().size(), r.out());
        assertTrue(r.outLines().get(0).startsWith(bad + ":29:54: error FCL-C002: "), r.out());
        assertEquals(List.of("fclcert: " + bad + " has errors; features are listed only for a valid program"), r.errLines());
    }

    @Test
    void aMissingFileIsExitCodeTwo() {
        String missing = dir.resolve("nope.fcl").toString();
        Cli r = Cli.run("features", missing);
        assertEquals(2, r.exitCode());
        assertEquals(List.of("fclcert: cannot read " + missing + ": no such file"), r.errLines());
    }
}
