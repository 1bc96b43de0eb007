package org.fclcert.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.File;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fclcert.cli.Main;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The language server in a real editor: headless Neovim (Debian package {@code neovim}, installed by
 * scripts/ensure-neovim) opens a program with known mistakes, its built-in LSP client starts {@code fclcert lsp},
 * and the script {@code neovim-client.lua} reads back through Neovim's own API the diagnostics, a hover, a
 * definition and a completion list. The diagnostics must be exactly what {@code fclcert check --format json}
 * prints for the file; the rest is compared with what the file says, counted by hand. Outside CI a missing
 * {@code nvim} skips the test with the reason; with {@code CI} set it fails.
 */
class NeovimLspTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void neovimShowsWhatCheckFinds() throws Exception {
        String nvim = nvim();
        Path file = dir.resolve("mistakes.fcl");
        Files.writeString(file, resource("mistakes.fcl"));
        Path script = dir.resolve("client.lua");
        Files.writeString(script, resource("neovim-client.lua"));
        Path out = dir.resolve("out.json");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> server = List.of(java, "-cp", System.getProperty("java.class.path"), Main.class.getName(), "lsp");
        ProcessBuilder pb = new ProcessBuilder(nvim, "--headless", "--clean", "-n", file.toString(),
                "-c", "luafile " + script).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("nvim.log").toFile());
        pb.environment().put("FCL_OUT", out.toString());
        pb.environment().put("FCL_CMD", JSON.writeValueAsString(server));
        // line 26 (0-based 25): 'service' of RULE 2; 'generous' of RULE 2; the start of 'rancd' after 'food IS' (line 25)
        pb.environment().put("FCL_HOVER", "25:17");
        pb.environment().put("FCL_DEFINITION", "25:44");
        pb.environment().put("FCL_COMPLETION", "24:42");
        Process p = pb.start();
        if (!p.waitFor(3, TimeUnit.MINUTES)) {
            p.destroyForcibly();
            fail("Neovim did not finish in 3 minutes; its log: " + Files.readString(dir.resolve("nvim.log")));
        }
        assertTrue(Files.exists(out), "Neovim wrote no result; its log: " + Files.readString(dir.resolve("nvim.log")));
        JsonNode got = JSON.readTree(out.toFile());
        assertNull(got.get("error"), () -> "the Lua script failed: " + got.get("error"));
        assertTrue(got.get("attached").asBoolean(), "no diagnostics reached Neovim");

        // the diagnostics: check's, one for one (position, severity, code, message)
        StringWriter checkOut = new StringWriter();
        Main.run(new PrintWriter(checkOut), new PrintWriter(new StringWriter()), "check", "--format", "json",
                file.toString());
        JsonNode check = JSON.readTree(checkOut.toString());
        List<String> expected = new ArrayList<>();
        for (JsonNode d : check) {
            expected.add((d.get("line").asInt() - 1) + ":" + (d.get("column").asInt() - 1) + " "
                    + ("error".equals(d.get("severity").asText()) ? 1 : 2) + " " + d.get("code").asText() + " "
                    + d.get("message").asText());
        }
        List<String> shown = new ArrayList<>();
        for (JsonNode d : got.get("diagnostics")) {
            shown.add(d.get("lnum").asInt() + ":" + d.get("col").asInt() + " " + d.get("severity").asInt() + " "
                    + d.get("code").asText() + " " + d.get("message").asText());
            assertEquals("fclcert", d.get("source").asText());
        }
        assertEquals(expected, shown);
        // the mistakes written into the file: an unused term, a missing ';', no DEFAULT, two misspellings
        assertEquals(List.of("FCL-W001", "FCL-S014", "FCL-C017", "FCL-C001", "FCL-C002"),
                shown.stream().map(s -> s.split(" ")[2]).toList());

        String hover = got.get("hover").asText();
        assertTrue(hover.contains("**service** : REAL") && hover.contains("VAR_INPUT") && hover.contains("line 3")
                && hover.contains("terms: poor, good"), hover);
        // TERM generous is on line 19, its name at column 10
        assertEquals(18, got.get("definition").get("line").asInt());
        assertEquals(9, got.get("definition").get("character").asInt());
        List<String> completion = new ArrayList<>();
        got.get("completion").forEach(c -> completion.add(c.asText()));
        assertEquals(List.of("rancid", "delicious", "NOT"), completion);
    }

    private static String nvim() {
        for (String d : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            Path candidate = Path.of(d, "nvim");
            if (Files.isExecutable(candidate)) {
                return candidate.toString();
            }
        }
        if (System.getenv("CI") != null) {
            fail("CI is set but Neovim (nvim) is not installed; scripts/ensure-neovim installs the Debian package");
        }
        assumeTrue(false, "Neovim (nvim) is not installed, so the editor test is skipped (scripts/ensure-neovim"
                + " installs it; with CI set the test fails instead)");
        return null;
    }

    private static String resource(String name) throws Exception {
        try (var in = NeovimLspTest.class.getResourceAsStream(name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
