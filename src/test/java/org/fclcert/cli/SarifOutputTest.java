package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;
import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * {@code check --format sarif}: the log validates against the SARIF 2.1.0 JSON schema (draft-04, from the npm
 * package scripts/ensure-sarif-schema takes it from), and a file with six findings gives six results at the
 * places worked out by hand from the text; standard input is named {@code <stdin>}.
 */
class SarifOutputTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path SIX = Path.of("src/test/resources/org/fclcert/cli/six-findings.fcl");

    static JsonSchema schema() throws Exception {
        Path file = Path.of("target/sarif-schema/sarif-2.1.0-rtm.5.json");
        if (!Files.isRegularFile(file)) {
            String why = file + " is missing (scripts/ensure-sarif-schema takes it from npm)";
            if (System.getenv("CI") != null) {
                fail("CI is set but " + why);
            }
            assumeTrue(false, why + "; the SARIF schema test is skipped");
        }
        ObjectNode node = (ObjectNode) JSON.readTree(file.toFile());
        node.remove("id");   // its refs are all '#/definitions/...': resolved in the document, nothing fetched
        return JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V4).getSchema(node);
    }

    /** The schema's findings on the log: empty when it is valid SARIF 2.1.0. */
    static Set<ValidationMessage> violations(String log) throws Exception {
        return schema().validate(JSON.readTree(log));
    }

    @Test
    void sixFindingsGiveSixResultsWithTheirRegionsAndTheLogIsValidSarif() throws Exception {
        Cli r = Cli.run("check", "--format", "sarif", SIX.toString());
        assertEquals(1, r.exitCode(), r.err());
        assertEquals(Set.of(), violations(r.out()));
        JsonNode run = JSON.readTree(r.out()).get("runs").get(0);
        List<String> results = new ArrayList<>();
        for (JsonNode result : run.get("results")) {
            JsonNode loc = result.get("locations").get(0).get("physicalLocation");
            assertEquals(SIX.toString(), loc.get("artifactLocation").get("uri").asText());
            JsonNode rule = run.get("tool").get("driver").get("rules").get(result.get("ruleIndex").asInt());
            assertEquals(result.get("ruleId").asText(), rule.get("id").asText());
            results.add(result.get("ruleId").asText() + " " + result.get("level").asText() + " "
                    + loc.get("region").get("startLine").asInt() + ":" + loc.get("region").get("startColumn").asInt());
        }
        // by hand from the text: 'fan' (7:5) never concluded; TERM warm (12:5) unused, its third point (8, 0)
        // at 12:33 after x = 10; 'temp IS hott' and 'tmp IS hot' at column 17 of lines 24 and 25; 'WITH 0' at 26:52
        assertEquals(List.of("FCL-W003 warning 7:5", "FCL-W001 warning 12:5", "FCL-C010 error 12:33",
                "FCL-C002 error 24:17", "FCL-C001 error 25:17", "FCL-W004 warning 26:52"), results);
        JsonNode c002 = run.get("tool").get("driver").get("rules").findParents("id").stream()
                .filter(n -> n.get("id").asText().equals("FCL-C002")).findFirst().orElseThrow();
        assertEquals("5.2.4", c002.get("properties").get("clause").asText());
        assertEquals("error", c002.get("defaultConfiguration").get("level").asText());
        assertTrue(c002.get("help").get("text").asText().contains("(IEC 61131-7 5.2.4)"), c002.toString());
        assertEquals(6, run.get("tool").get("driver").get("rules").size(), "six distinct codes, one rule each");
    }

    @Test
    void theSchemaRejectsALogThatIsNotSarif() throws Exception {
        // the validation can fail: without 'version', and with a result whose line is 0
        String log = Cli.run("check", "--format", "sarif", SIX.toString()).out();
        assertFalse(violations(log.replace("\"version\" : \"2.1.0\",", "")).isEmpty());
        assertFalse(violations(log.replace("\"startLine\" : 7", "\"startLine\" : 0")).isEmpty());
    }

    @Test
    void aCleanFileGivesAValidLogWithNoResults() throws Exception {
        Path clean = Path.of("src/test/resources/org/fclcert/check/standard/valve_5_3.fcl");
        Cli r = Cli.run("check", "--format", "sarif", clean.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertEquals(Set.of(), violations(r.out()));
        assertEquals(0, JSON.readTree(r.out()).get("runs").get(0).get("results").size());
    }

    @Test
    void standardInputIsNamedStdinInTextAndInSarif() throws Exception {
        byte[] text = Files.readAllBytes(SIX);
        Cli plain = withStdin(text, "check", "-");
        assertEquals(1, plain.exitCode());
        assertEquals("<stdin>:7:5: warning FCL-W003: output 'fan' is never concluded by any rule, so no rule ever"
                + " sets it", plain.outLines().get(0));
        Cli sarif = withStdin(text, "check", "--format", "sarif", "-");
        assertEquals(Set.of(), violations(sarif.out()));
        assertEquals("%3Cstdin%3E", JSON.readTree(sarif.out()).get("runs").get(0).get("results").get(0)
                .get("locations").get(0).get("physicalLocation").get("artifactLocation").get("uri").asText());
        Cli twice = withStdin(text, "check", "-", "-");
        assertEquals(2, twice.exitCode());
        assertEquals("fclcert: '-' (standard input) is given more than once; it can be read only once",
                twice.errLines().get(0));
    }

    /** Runs the command line with {@code input} as standard input. */
    static Cli withStdin(byte[] input, String... args) {
        InputStream before = System.in;
        System.setIn(new ByteArrayInputStream(input));
        try {
            return Cli.run(args);
        } finally {
            System.setIn(before);
        }
    }

    static Cli withStdin(String input, String... args) {
        return withStdin(input.getBytes(StandardCharsets.UTF_8), args);
    }
}
