package org.fclcert.corpus;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * The conformance corpus: every case file ({@code *.fcl}) under a directory, sorted by id.
 *
 * <p>{@link #load} is what runners use: it reads every file, collects every problem (malformed metadata,
 * duplicate ids, unreadable files) and throws them all together, so a corpus author sees the whole list at
 * once. {@link #scan} returns the cases it could read together with the problems, for the lint.
 */
public record Corpus(Path directory, List<CorpusCase> cases, String sha256) {

    public Corpus {
        cases = List.copyOf(cases);
    }

    /** What {@link #scan} found: the readable cases (sorted by id) and every problem. */
    public record Scan(Path directory, List<CorpusCase> cases, List<CorpusProblem> problems, String sha256) {
        public Scan {
            cases = List.copyOf(cases);
            problems = List.copyOf(problems);
        }
    }

    /** Loads every case under {@code dir}; throws with all problems when there is any. */
    public static Corpus load(Path dir) throws CorpusException {
        Scan scan = scan(dir);
        if (!scan.problems().isEmpty()) {
            throw new CorpusException(scan.problems());
        }
        return new Corpus(dir, scan.cases(), scan.sha256());
    }

    /** Reads every case under {@code dir}, keeping the readable ones and recording every problem. */
    public static Scan scan(Path dir) {
        List<CorpusProblem> problems = new ArrayList<>();
        List<CorpusCase> cases = new ArrayList<>();
        MessageDigest digest = sha256Digest();
        for (Path file : caseFiles(dir, problems)) {
            readFile(file, problems).ifPresent(text -> {
                digest.update(dir.relativize(file).toString().replace('\\', '/').getBytes(StandardCharsets.UTF_8));
                digest.update((byte) 0);
                digest.update(text.getBytes(StandardCharsets.UTF_8));
                CaseFileReader.read(file, text, problems).ifPresent(cases::add);
            });
        }
        cases.sort(Comparator.comparing(CorpusCase::id));
        reportDuplicates(cases, problems);
        problems.sort(null);
        return new Scan(dir, cases, problems, HexFormat.of().formatHex(digest.digest()));
    }

    /** The case with this id. */
    public Optional<CorpusCase> byId(String id) {
        return cases.stream().filter(c -> c.id().equals(id)).findFirst();
    }

    private static List<Path> caseFiles(Path dir, List<CorpusProblem> problems) {
        if (!Files.isDirectory(dir)) {
            problems.add(new CorpusProblem(dir, 0, "not a directory: the corpus is a directory of .fcl case files"));
            return List.of();
        }
        try (Stream<Path> s = Files.walk(dir)) {
            // sorted by path so that the digest does not depend on the file system's order
            return s.filter(p -> p.getFileName().toString().endsWith(".fcl") && Files.isRegularFile(p))
                    .sorted(Comparator.comparing(p -> dir.relativize(p).toString()))
                    .toList();
        } catch (IOException e) {
            problems.add(new CorpusProblem(dir, 0, "cannot list the corpus directory: " + e.getMessage()));
            return List.of();
        }
    }

    private static Optional<String> readFile(Path file, List<CorpusProblem> problems) {
        try {
            byte[] bytes = org.fclcert.model.Limits.readFile(file);
            return Optional.of(StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(bytes)).toString()
                    .replace("\r\n", "\n"));
        } catch (CharacterCodingException e) {
            problems.add(new CorpusProblem(file, 0, "not valid UTF-8 text"));
        } catch (IOException e) {
            problems.add(new CorpusProblem(file, 0, "cannot read the file: " + e.getMessage()));
        }
        return Optional.empty();
    }

    private static void reportDuplicates(List<CorpusCase> cases, List<CorpusProblem> problems) {
        Map<String, CorpusCase> seen = new HashMap<>();
        for (CorpusCase c : cases) {
            CorpusCase first = seen.putIfAbsent(c.id(), c);
            if (first != null) {
                problems.add(new CorpusProblem(c.path(), 1, "id " + c.id() + " is already used by " + first.path()));
            }
        }
    }

    private static MessageDigest sha256Digest() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java runtime has SHA-256", e);
        }
    }
}
