package org.fclcert.corpus;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Adds one case file to a corpus (what {@code fclcert corpus add FILE} does): the case gets the next free id of
 * its prefix (never a retired one), goes into the directory of its level, and is linted with the corpus; if the
 * lint finds anything in it, it is taken out again and the findings are returned.
 */
public final class CorpusAdd {
    private static final Pattern ID_LINE = Pattern.compile("(?m)^id:[ \\t]*(\\S+)[ \\t]*$");
    private static final Pattern LEVEL_LINE = Pattern.compile("(?m)^level:[ \\t]*(\\S+)[ \\t]*$");
    private static final Pattern EXPECT_REJECT = Pattern.compile("(?m)^expect:[ \\t]*reject[ \\t]*$");
    private static final Pattern ID = Pattern.compile("([BEON](?:-[A-Z0-9]+)+)-([0-9]{3})");

    /** The outcome: where the case went (empty when it was not added) and the lint's findings in it. */
    public record Outcome(Optional<Path> placed, String id, List<CorpusProblem> findings) {
        public Outcome {
            findings = List.copyOf(findings);
        }
    }

    /** A case file that cannot be added at all (no metadata, no id); the message says why. */
    public static final class NotACase extends Exception {
        private static final long serialVersionUID = 1L;

        NotACase(String message) {
            super(message);
        }
    }

    private CorpusAdd() {
    }

    public static Outcome add(Path corpus, Path file) throws IOException, NotACase {
        String text = new String(org.fclcert.model.Limits.readFile(file), StandardCharsets.UTF_8);
        if (!text.startsWith(CaseFileReader.OPEN)) {
            throw new NotACase(file + ": not a case file (its first line must start with " + CaseFileReader.OPEN + ")");
        }
        Matcher id = ID_LINE.matcher(text);
        if (!id.find()) {
            throw new NotACase(file + ": the metadata has no 'id:' line");
        }
        Matcher parts = ID.matcher(id.group(1));
        if (!parts.matches()) {
            throw new NotACase(file + ": '" + id.group(1) + "' is not a case id (e.g. E-ACCU-NSUM-001)");
        }
        String prefix = parts.group(1);
        String dirName;
        if (EXPECT_REJECT.matcher(text).find()) {
            dirName = "negative";
        } else {
            Matcher level = LEVEL_LINE.matcher(text);
            if (!level.find()) {
                throw new NotACase(file + ": the metadata has no 'level:' line");
            }
            dirName = level.group(1).toLowerCase(Locale.ROOT);
        }
        Path dir = corpus.resolve(dirName);
        Files.createDirectories(dir);
        String newId = prefix + String.format(Locale.ROOT, "-%03d", next(corpus, prefix));
        Path target = dir.resolve(newId + ".fcl");
        Files.writeString(target, id.replaceFirst("id: " + newId), StandardCharsets.UTF_8);
        LintReport report = new CorpusLint().lint(corpus);
        List<CorpusProblem> mine = report.caseFindings().stream()
                .filter(p -> p.file() != null && p.file().toAbsolutePath().normalize().equals(target.toAbsolutePath().normalize()))
                .toList();
        if (!mine.isEmpty()) {
            Files.delete(target);
            return new Outcome(Optional.empty(), newId, mine);
        }
        return new Outcome(Optional.of(target), newId, List.of());
    }

    /** One more than the highest number of the prefix in use or retired. */
    static int next(Path corpus, String prefix) throws IOException {
        int max = 0;
        try (Stream<Path> files = Files.walk(corpus)) {
            for (Path p : (Iterable<Path>) files::iterator) {
                max = Math.max(max, number(p.getFileName().toString().replaceFirst("\\.fcl$", ""), prefix));
            }
        }
        Path retired = corpus.resolve(CorpusLint.RETIRED_FILE);
        if (Files.isRegularFile(retired)) {
            for (String line : new String(org.fclcert.model.Limits.readFile(retired), StandardCharsets.UTF_8).lines()
                    .toList()) {
                String word = line.replaceFirst("#.*", "").strip().split("\\s+")[0];
                max = Math.max(max, number(word, prefix));
            }
        }
        return max + 1;
    }

    private static int number(String id, String prefix) {
        Matcher m = ID.matcher(id);
        return m.matches() && m.group(1).equals(prefix) ? Integer.parseInt(m.group(2)) : 0;
    }
}
