package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 26: the semantic axis ({@code --present-as}) is disguised and judged again like the language axis: the
 * program written in the library's layout is the disguised one (its inputs go out under the disguise's names), the
 * presentation's exchanges are part of the case's evidence, and a presented verdict edited in results.jsonl is
 * refused by {@code report --from}.
 */
class PresentedEvidenceTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void thePresentedAxisIsDisguisedAndAnEditedPresentedVerdictIsRefused() throws Exception {
        Path run = dir.resolve("run");
        Cli c = Cli.run("certify", "--iut", "reference", "--present-as", "fuzzylite", "--no-probe", "--seed", "9",
                "--case", "B-ACCU-MAX-00*", "--out", run.toString());
        assertEquals(0, c.exitCode(), c.err());
        List<String> lines = Files.readAllLines(run.resolve("results.jsonl"));
        int presented = 0;
        int edited = -1;
        List<ObjectNode> nodes = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            ObjectNode n = (ObjectNode) JSON.readTree(lines.get(i));
            nodes.add(n);
            JsonNode p = n.path("presented");
            if (!p.isObject()) {
                continue;
            }
            assertEquals("passed", p.path("status").asText(), n.toString());
            presented++;
            // two loads in the evidence (the standard's text, then the library's layout), no corpus name sent
            int loads = 0;
            for (JsonNode x : n.path("replies")) {
                loads += x.path("op").asText().equals("load") ? 1 : 0;
                // every name sent is a disguise's new name (a letter, a digit, four letters or digits)
                x.path("in").fieldNames().forEachRemaining(k -> assertTrue(k.matches("[a-z][0-9][a-z0-9]{4}"),
                        n.path("id") + ": the name '" + k + "' was sent: " + x));
            }
            assertEquals(2, loads, n.path("id") + ": " + n.path("replies"));
            edited = i;
        }
        assertEquals(3, presented, "B-ACCU-MAX-001..003 presented in fuzzylite's layout");
        assertEquals(0, Cli.run("report", "--verify", run.toString()).exitCode(), "the run is consistent");

        // the forger flips the presented verdict and recomputes the chain
        ((ObjectNode) nodes.get(edited).path("presented")).put("status", "failed");
        Path forged = dir.resolve("forged");
        Files.createDirectories(forged);
        Files.writeString(forged.resolve("results.jsonl"), EditedResultsTest.rechained(nodes));
        Cli from = Cli.run("report", "--from", forged.resolve("results.jsonl").toString(), "--out",
                dir.resolve("rebuilt").toString());
        assertEquals(1, from.exitCode(), from.out() + from.err());
        assertTrue(from.err().contains("presented"), from.err());
    }
}
