package org.fclcert.report;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.corpus.BundledCorpus;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusException;
import org.fclcert.harness.Rejudge;
import org.fclcert.harness.ResultsChain;
import org.fclcert.harness.ResultsFile;
import org.fclcert.harness.ResultsWriter;
import org.fclcert.model.Limits;

/**
 * Reports rebuilt and checked from the record, never from what a file says of itself: {@link #rebuild} reads
 * {@code results.jsonl}, follows its hash chain ({@link ResultsChain}), finds the run's corpus and recomputes its
 * digest, judges every case line's evidence again ({@link Rejudge}) and builds the report from those judgements —
 * {@code report --from}, {@code compare} and {@code fclcert:verify} use it; {@link #verify} also renders that report
 * again and compares it with the {@code report.json}, {@code report.md}, {@code report.html} and {@code junit.xml}
 * of the directory ({@code report --verify}), naming the first inconsistency.
 */
public final class ReportVerifier {
    private ReportVerifier() {
    }

    /**
     * A report rebuilt from its results: {@code inconsistencies} (empty when the results are consistent: chain
     * intact, corpus the run's, every line what its evidence gives) and {@code notes} (a run that did not finish).
     */
    public record Rebuilt(Report report, List<String> inconsistencies, List<String> notes) {
        public Rebuilt {
            inconsistencies = List.copyOf(inconsistencies);
            notes = List.copyOf(notes);
        }

        public boolean consistent() {
            return inconsistencies.isEmpty();
        }
    }

    /**
     * Rebuilds the report of {@code results} (a {@code results.jsonl}), with {@code corpusDir} the corpus to judge
     * by (null: the one the run header names — {@code bundled}, or a directory — else the built-in one when it has
     * the run's digest); {@code generatedAt} the report's time.
     */
    public static Rebuilt rebuild(Path results, Path corpusDir, Instant generatedAt)
            throws IOException, ResultsFile.InvalidResultsException {
        String name = results.getFileName() == null ? results.toString() : results.getFileName().toString();
        List<String> lines = new String(Limits.readFile(results), StandardCharsets.UTF_8).lines().toList();
        ResultsFile file = ResultsFile.read(results);
        List<String> inconsistencies = new ArrayList<>();
        List<String> notes = new ArrayList<>();
        ResultsChain.Check chain = ResultsChain.check(name, lines);
        if (file.header().provenance() == null) {
            // no seed, no evidence (certify --no-fresh-evidence, or an older fclcert): nothing to judge again; the
            // report says UNVERIFIED and issues no Basic verdict (Origin), and verify refuses it
            if (chain.chained() && !chain.intact()) {
                notes.add(chain.firstBreak());   // no verdict is issued from such results either way
            }
            notes.add(name + ": UNVERIFIED: the results carry no run seed and no evidence; the reports issue no verdict");
            Report report = Origin.apply(ReportBuilder.build(file, generatedAt), null, chain.intact() ? chain.seal() : null,
                    "not recomputed: the results carry no evidence", List.of());
            return new Rebuilt(report, inconsistencies, notes);
        }
        if (!chain.intact()) {
            inconsistencies.add(chain.firstBreak());
        } else if (chain.seal() == null) {
            notes.add(name + ": no end line: the run did not finish (killed, or stopped before its reports), so it has"
                    + " no digest");
        }
        String version = file.header().toolkit().version();
        if (!version.equals(org.fclcert.model.Toolkit.version())) {
            // judging again proves a verdict only under the judging code that gave it
            inconsistencies.add("the results say they were made by fclcert " + version + "; this is fclcert "
                    + org.fclcert.model.Toolkit.version() + ", whose judging is not that version's: check them with"
                    + " the fclcert that made them");
        } else if (file.header().provenance() != null && file.header().provenance().toolkit() != null
                && !version.equals(file.header().provenance().toolkit().version())) {
            inconsistencies.add("the run header names fclcert " + version + " but its provenance measured "
                    + file.header().provenance().toolkit().version());
        }
        Optional<Corpus> corpus = corpus(file, corpusDir, inconsistencies);
        Rejudge.Outcome judged = corpus.map(c -> Rejudge.of(file, c)).orElse(null);
        List<String> warnings = new ArrayList<>();
        Report report;
        if (judged == null) {
            report = ReportBuilder.build(file, generatedAt);
            warnings.add("UNVERIFIED: the run's corpus was not found, so no verdict could be recomputed from evidence;"
                    + " the verdicts below are the results file's own claims");
        } else {
            inconsistencies.addAll(judged.inconsistencies());
            report = ReportBuilder.build(file.header(), judged.results(), file.problems(), file.dataCheckList(),
                    generatedAt);
        }
        if (!inconsistencies.isEmpty()) {
            warnings.add("INCONSISTENT: the results file does not hold up: " + inconsistencies.get(0)
                    + (inconsistencies.size() > 1 ? " (and " + (inconsistencies.size() - 1) + " more)" : ""));
        }
        report = Origin.apply(report, file.header().provenance(), chain.intact() ? chain.seal() : null,
                judged == null ? "not recomputed: the corpus was not found" : Origin.REJUDGED, warnings);
        return new Rebuilt(report, inconsistencies, notes);
    }

    /** The corpus the run used, or empty with the reason among {@code inconsistencies}. */
    private static Optional<Corpus> corpus(ResultsFile file, Path corpusDir, List<String> inconsistencies) {
        String want = file.header().corpus().sha256();
        List<String> tried = new ArrayList<>();
        List<Path> candidates = new ArrayList<>();
        if (corpusDir != null) {
            candidates.add(corpusDir);
        } else {
            String dir = file.header().corpus().dir();
            if (dir != null && !dir.equals(BundledCorpus.NAME) && Files.isDirectory(Path.of(dir))) {
                candidates.add(Path.of(dir));
            }
            try {
                candidates.add(BundledCorpus.directory());
            } catch (CorpusException e) {
                tried.add("the built-in corpus: " + e.getMessage());
            }
        }
        for (Path dir : candidates) {
            try {
                Corpus c = Corpus.load(dir);
                if (c.sha256().equals(want)) {
                    return Optional.of(c);
                }
                tried.add(dir + " has sha256 " + c.sha256());
            } catch (CorpusException | RuntimeException e) {
                tried.add(dir + " cannot be read: " + e.getMessage().lines().findFirst().orElse(""));
            }
        }
        inconsistencies.add("the run's corpus (sha256 " + want + ") was not found: " + String.join("; ", tried)
                + (corpusDir == null ? " (give it with --corpus)" : ""));
        return Optional.empty();
    }

    /** A directory checked: its inconsistencies (empty: it holds up) and the report rebuilt from its results (or null). */
    public record Verified(List<String> inconsistencies, Report report) {
        public Verified {
            inconsistencies = List.copyOf(inconsistencies);
        }
    }

    /** As {@link #check}, the inconsistencies alone. */
    public static List<String> verify(Path dir, Path corpusDir) throws IOException {
        return check(dir, corpusDir).inconsistencies();
    }

    /**
     * Checks a report directory: the results rebuilt ({@link #rebuild}) must be consistent and sealed, and the four
     * reports must be exactly what that rebuilt report renders to (with the generation time of {@code report.json}).
     * Returns every inconsistency found, the first one first (none when the directory holds up), with the rebuilt report.
     */
    public static Verified check(Path dir, Path corpusDir) throws IOException {
        Path results = dir.resolve(ResultsWriter.FILE_NAME);
        if (!Files.isRegularFile(results)) {
            return new Verified(List.of(results + ": no such file"), null);
        }
        Path json = dir.resolve(ReportFiles.JSON);
        Report written;
        try {
            written = Files.isRegularFile(json) ? JsonReport.read(json) : null;
        } catch (IOException e) {
            return new Verified(List.of(json + ": not a report: " + e.getMessage().lines().findFirst().orElse("")), null);
        }
        if (written == null) {
            return new Verified(List.of(json + ": no such file"), null);
        }
        Rebuilt rebuilt;
        try {
            rebuilt = rebuild(results, corpusDir, Instant.parse(written.generatedAt()));
        } catch (ResultsFile.InvalidResultsException e) {
            return new Verified(List.of(e.getMessage()), null);
        } catch (RuntimeException e) {
            return new Verified(List.of(json + ": its generation time '" + written.generatedAt() + "' cannot be read"), null);
        }
        List<String> out = new ArrayList<>(rebuilt.inconsistencies());
        if (rebuilt.report().origin().provenance() == null) {
            out.add(results + ": the results carry no run seed and no evidence: nothing in them can be verified");
        }
        if (rebuilt.report().origin().digest() == null) {
            out.addAll(rebuilt.notes());
        }
        if (!out.isEmpty()) {
            return new Verified(out, rebuilt.report());
        }
        Report r = rebuilt.report();
        // a live run's reports say how they were judged: rebuild with the same words, all else must match
        Report asWritten = written.origin() == null ? r : Origin.apply(strip(r), r.origin().provenance(),
                new ResultsChain.Seal(r.origin().digest(), r.origin().endedAt(), 0), written.origin().verification(),
                List.of());
        compare(out, json, JsonReport.text(asWritten));
        compare(out, dir.resolve(ReportFiles.MARKDOWN), MarkdownReport.render(asWritten));
        compare(out, dir.resolve(ReportFiles.HTML), HtmlReport.render(asWritten));
        compare(out, dir.resolve(ReportFiles.JUNIT), JunitReport.render(asWritten));
        return new Verified(out, rebuilt.report());
    }

    /** The report without its origin's warnings (Origin.apply works them out again). */
    private static Report strip(Report r) {
        return new Report(r.formatVersion(), r.generatedAt(), r.iut(), r.toolkit(), r.corpus(), r.run(), r.summary(),
                r.rejections(), r.basicLevel(), r.features(), r.dataCheckList(), r.interpretation(), r.claims(),
                r.causes(), r.cases(), r.semantic(), null);
    }

    private static void compare(List<String> out, Path file, String expected) throws IOException {
        if (!Files.isRegularFile(file)) {
            out.add(file + ": no such file");
            return;
        }
        List<String> have = new String(Limits.readFile(file), StandardCharsets.UTF_8).lines().toList();
        List<String> want = expected.lines().toList();
        for (int i = 0; i < Math.max(have.size(), want.size()); i++) {
            String a = i < have.size() ? have.get(i) : "(end of file)";
            String b = i < want.size() ? want.get(i) : "(end of file)";
            if (!a.equals(b)) {
                out.add(file + ":" + (i + 1) + ": not what the results give: the file has '" + shorten(a)
                        + "', the results give '" + shorten(b) + "'");
                return;
            }
        }
    }

    private static String shorten(String s) {
        String t = s.strip();
        return t.length() > 120 ? t.substring(0, 120) + "…" : t;
    }
}
