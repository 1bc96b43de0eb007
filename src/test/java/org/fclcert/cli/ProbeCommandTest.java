package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ProbeCommandTest {
    @TempDir
    Path dir;

    @Test
    void probesTheReferenceAndWritesTheList() throws Exception {
        Cli r = Cli.run("probe", "--cap", "8", "--format", "json", "--out", dir.toString());
        assertEquals(0, r.exitCode(), r.err());
        JsonNode list = new ObjectMapper().readTree(r.out());
        assertEquals(22, list.size());
        assertEquals("max-rules-per-block", list.get(17).get("id").asText());
        assertEquals("8", list.get(17).get("value").asText());
        assertEquals("at-least", list.get(17).get("bound").asText());
        assertEquals(list, new ObjectMapper().readTree(Files.readString(dir.resolve("data-check-list.json"))));
    }

    @Test
    void textShowsOneRowPerItem() {
        Cli r = Cli.run("probe", "--cap", "4");
        assertEquals(0, r.exitCode(), r.err());
        String[] lines = r.out().split("\n");
        assertEquals(22, lines.length, r.out());
        assertTrue(lines[17].matches("max-rules-per-block +≥ 4 rules +reached the cap of 4 \\(--probe-cap\\)"), lines[17]);
    }

    @Test
    void badOptionsAndUnreachableIutsExitWith2() {
        Cli bad = Cli.run("probe", "--budget", "soon");
        assertEquals(2, bad.exitCode());
        assertTrue(bad.err().startsWith("Invalid value for option '--budget': 'soon' is not a duration (write e.g. 5s,"
                + " 500ms or 2m)"), bad.err());
        Cli zero = Cli.run("probe", "--timeout", "0ms");
        assertEquals(2, zero.exitCode());
        assertTrue(zero.err().startsWith("Invalid value for option '--timeout': '0ms' is not a duration"), zero.err());
        Cli none = Cli.run("probe", "--iut", "java:no.such.Class");
        assertEquals(2, none.exitCode());
        assertTrue(none.err().startsWith("fclcert probe: cannot probe 'java:no.such.Class'"), none.err());
        assertEquals(1, none.err().strip().split("\n").length, "one line, no stack trace: " + none.err());
    }
}
