package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * Keeps README.md true: every {@code $ ./fclcert ...} line in a {@code console} block is run
 * in-process from the repository root, and its stdout followed by its stderr must be the lines shown
 * under it; a following {@code $ echo $?} must show its exit code. When output changes on purpose,
 * re-run the command and paste (or run {@code .ci/refresh-readme}).
 */
class ReadmeTest {
    private static final Pattern CONSOLE_BLOCK = Pattern.compile("```console\n(.*?)```", Pattern.DOTALL);
    private static final String PROMPT = "$ ./fclcert";

    /** One shown command: its arguments, the output lines under it and the exit code shown, if any. */
    record Shown(List<String> args, List<String> output, Integer exitCode) {
    }

    @TestFactory
    Stream<DynamicTest> everyShownCommandPrintsWhatTheReadmeShows() throws IOException {
        List<Shown> shown = shownCommands(Files.readString(Path.of("README.md"), StandardCharsets.UTF_8));
        assertFalse(shown.isEmpty(), "README.md shows no ./fclcert command");
        return shown.stream().map(s -> DynamicTest.dynamicTest("fclcert " + String.join(" ", s.args()), () -> {
            Cli r = runLeavingFilesAlone(s.args());
            List<String> actual = new ArrayList<>(r.outLines());
            // the ticks a long run prints off a terminal come with the machine's speed, not with the command
            r.errLines().stream().filter(l -> !l.startsWith("progress: ")).forEach(actual::add);
            assertEquals(String.join("\n", s.output()), String.join("\n", actual),
                    "README.md shows other output for this command; re-run it and paste the real output");
            if (s.exitCode() != null) {
                assertEquals(s.exitCode(), r.exitCode(), "README.md shows another exit code");
            }
        }));
    }

    /** Runs the command; files it names are restored afterwards, and a shown command must not change them. */
    private static Cli runLeavingFilesAlone(List<String> args) throws IOException {
        java.util.Map<Path, byte[]> before = new java.util.LinkedHashMap<>();
        for (String a : args) {
            Path p = Path.of(a);
            if (Files.isRegularFile(p)) {
                before.put(p, Files.readAllBytes(p));
            }
        }
        // '< FILE' at the end (a command reading standard input, '-'): the file becomes standard input
        Cli r;
        if (args.size() >= 2 && args.get(args.size() - 2).equals("<")) {
            byte[] input = Files.readAllBytes(Path.of(args.get(args.size() - 1)));
            r = SarifOutputTest.withStdin(input, args.subList(0, args.size() - 2).toArray(String[]::new));
        } else {
            r = Cli.run(args.toArray(String[]::new));
        }
        for (var e : before.entrySet()) {
            boolean changed = !java.util.Arrays.equals(e.getValue(), Files.readAllBytes(e.getKey()));
            Files.write(e.getKey(), e.getValue());
            assertFalse(changed, "a command shown in README.md changed " + e.getKey() + " (restored)");
        }
        return r;
    }

    @Test
    void theTestCommandIsWhatCiRuns() throws IOException {
        String readme = Files.readString(Path.of("README.md"), StandardCharsets.UTF_8);
        String ci = Files.readString(Path.of(".ci/run"), StandardCharsets.UTF_8);
        assertTrue(readme.contains("\nmvn -B verify "), "README's test command");
        assertTrue(ci.strip().endsWith("\nmvn -B verify"), ".ci/run must run exactly the README's test command");
    }

    static List<Shown> shownCommands(String readme) {
        List<Shown> all = new ArrayList<>();
        Matcher m = CONSOLE_BLOCK.matcher(readme);
        while (m.find()) {
            all.addAll(parseBlock(m.group(1).lines().toList()));
        }
        return all;
    }

    private static List<Shown> parseBlock(List<String> lines) {
        List<Shown> out = new ArrayList<>();
        int i = 0;
        while (i < lines.size()) {
            String line = lines.get(i);
            assertTrue(line.startsWith(PROMPT), "console blocks hold only ./fclcert commands, their output and 'echo $?': " + line);
            List<String> args = List.of(line.substring(PROMPT.length()).trim().split("\\s+"));
            List<String> output = new ArrayList<>();
            i++;
            while (i < lines.size() && !lines.get(i).startsWith("$ ")) {
                output.add(lines.get(i++));
            }
            Integer exit = null;
            if (i + 1 < lines.size() && lines.get(i).equals("$ echo $?")) {
                exit = Integer.valueOf(lines.get(i + 1).trim());
                i += 2;
            }
            out.add(new Shown(args.get(0).isEmpty() ? List.of() : args, output, exit));
        }
        return out;
    }
}
