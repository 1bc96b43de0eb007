package org.fclcert.harness;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;
import java.util.stream.Stream;

/**
 * Identifies the exact corpus a report was made from: sha256 over the bytes of every case file
 * ({@code *.fcl}), taken in the order of their paths relative to the corpus directory ('/' separated).
 */
public final class CorpusFingerprint {
    private CorpusFingerprint() {
    }

    public static String sha256(Path corpusDir) throws IOException {
        MessageDigest digest = newDigest();
        for (Path file : caseFiles(corpusDir)) {
            digest.update(Files.readAllBytes(file));
        }
        return HexFormat.of().formatHex(digest.digest());
    }

    static List<Path> caseFiles(Path corpusDir) throws IOException {
        try (Stream<Path> files = Files.walk(corpusDir)) {
            return files.filter(Files::isRegularFile).filter(p -> p.getFileName().toString().endsWith(".fcl"))
                    .sorted((a, b) -> relative(corpusDir, a).compareTo(relative(corpusDir, b))).toList();
        }
    }

    private static String relative(Path dir, Path file) {
        return dir.relativize(file).toString().replace('\\', '/');
    }

    private static MessageDigest newDigest() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }
}
