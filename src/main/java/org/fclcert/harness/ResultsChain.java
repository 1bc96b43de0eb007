package org.fclcert.harness;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;

/**
 * The hash chain of {@code results.jsonl}: every line carries in {@code prev} the sha256 of the line before it
 * (the first line {@link #START}), and the run's last line, {@code {"type":"end", "digest":…, "endedAt":…}},
 * carries the sha256 of the line before it as the run's digest, which every report shows. A line changed,
 * removed, added or moved breaks the chain at the line after it. What that proves is consistency — the reports
 * and the lines are one run's, unedited since the digest was written — not authorship: there is no key, so
 * whoever rewrites every line and every report can rebuild the chain; re-judging the evidence
 * ({@link Rejudge}) and rerunning with the seed are what show the results are the implementation's.
 */
public final class ResultsChain {
    /** The {@code prev} of the first line. */
    public static final String START = "0".repeat(64);
    /** The type of the last line. */
    public static final String END = "end";

    private String head = START;
    private int lines;

    /** The hash the next line carries in {@code prev}. */
    String head() {
        return head;
    }

    /** Extends the chain by a line as written (without its line break). */
    void append(String line) {
        head = sha256(line);
        lines++;
    }

    /** How a finished run was sealed: its digest, when it ended, how many lines precede the end line. */
    public record Seal(String digest, String endedAt, int lines) {
    }

    Seal seal(String endedAt) {
        return new Seal(head, endedAt, lines);
    }

    /**
     * The chain of a results file read back: {@code seal} of its end line (null when the run never wrote one:
     * killed, or made before fclcert chained its results), and the first place where the chain breaks (null: none).
     */
    public record Check(Seal seal, String firstBreak, boolean chained) {
        public boolean intact() {
            return firstBreak == null;
        }
    }

    /** Checks the chain of {@code lines} (as read, blank lines ignored) of the file {@code name}. */
    public static Check check(String name, List<String> lines) {
        String expected = START;
        int count = 0;
        Seal seal = null;
        boolean chained = false;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.isBlank()) {
                continue;
            }
            String where = name + ":" + (i + 1);
            if (seal != null) {
                return new Check(seal, where + ": a line after the run's end line (the file was added to)", true);
            }
            JsonNode node;
            try {
                node = Json.mapper().readTree(line);
            } catch (Exception e) {
                boolean last = lines.subList(i + 1, lines.size()).stream().allMatch(String::isBlank);
                // a last line cut in the middle is a run killed while writing it: intact up to there, not sealed
                return new Check(null, last ? null : where + ": not one JSON object, so the chain cannot be followed",
                        chained);
            }
            String prev = node.path("prev").asText(null);
            if (prev == null) {
                return new Check(null, where + ": the line carries no 'prev' hash: the results are not chained"
                        + (i == 0 ? " (written by an fclcert that did not chain them, or stripped)" : ""), chained);
            }
            chained = true;
            if (!prev.equals(expected)) {
                return new Check(null, where + ": the chain breaks here: 'prev' is not the sha256 of the line before it"
                        + " (a line before this one was changed, removed, added or moved)", true);
            }
            if (END.equals(node.path("type").asText())) {
                String digest = node.path("digest").asText("");
                if (!digest.equals(expected)) {
                    return new Check(null, where + ": the end line's digest is not the chain's", true);
                }
                seal = new Seal(digest, node.path("endedAt").asText(null), count);
            }
            expected = sha256(line);
            count++;
        }
        return new Check(seal, null, chained);
    }

    static String sha256(String line) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256")
                    .digest(line.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java runtime", e);
        }
    }
}
