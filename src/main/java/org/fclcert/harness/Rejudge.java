package org.fclcert.harness;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.model.ConformanceLevel;

/**
 * Judges a run's results again from their evidence: each case line's recorded replies ({@link Exchange}) are
 * replayed ({@link ReplayIut}) through the very judging code of the run, on the corpus case prepared as the run
 * prepared it — its fresh vectors and disguise regenerated from the run seed ({@link FreshEvidence}). The result of
 * that judging replaces the line's own: a status, message or any other judged part that differs is an
 * inconsistency, and so is evidence that does not answer the requests judging makes, a case not in the corpus, a
 * case line without evidence, and a header that does not describe the corpus (its digest, its number of cases and
 * Basic Level cases, the plan of each case). A case line without evidence that is skipped stays skipped (a skip is
 * never a pass); one that claims anything else becomes skipped ("not judged: no evidence").
 *
 * <p>Both axes are re-judged: a presented case's semantic axis ({@code --present-as}) went over the same disguise,
 * and its exchanges are part of the case's evidence.
 */
public final class Rejudge {
    private Rejudge() {
    }

    /** The re-judged results, in the order read, and every inconsistency found (empty: the file is consistent). */
    public record Outcome(List<CaseResult> results, List<String> inconsistencies) {
        public Outcome {
            results = List.copyOf(results);
            inconsistencies = List.copyOf(inconsistencies);
        }

        public boolean consistent() {
            return inconsistencies.isEmpty();
        }
    }

    /** What a case line is replaced by when it keeps no evidence but claims a verdict. */
    public static final String NO_EVIDENCE = "not judged: the case line keeps no evidence (replies)";

    /** Re-judges {@code file} against {@code corpus} (which must be the run's: its digest is checked). */
    public static Outcome of(ResultsFile file, Corpus corpus) {
        List<String> problems = new ArrayList<>();
        RunHeader h = file.header();
        if (!corpus.sha256().equals(h.corpus().sha256())) {
            problems.add("the corpus " + corpus.directory() + " has sha256 " + corpus.sha256() + ", the run header says "
                    + h.corpus().sha256() + ": not the run's corpus");
            return new Outcome(file.results(), problems);
        }
        int basic = (int) corpus.cases().stream()
                .filter(c -> c.level() == ConformanceLevel.BASIC && c.interpretation().isEmpty()).count();
        if (h.corpus().cases() != corpus.cases().size() || h.corpus().basicCases() != basic) {
            problems.add("the run header says the corpus has " + h.corpus().cases() + " cases, " + h.corpus().basicCases()
                    + " of the Basic Level; it has " + corpus.cases().size() + " and " + basic);
        }
        for (PlannedCase p : h.selection().planned()) {
            Optional<CorpusCase> c = corpus.byId(p.id());
            if (c.isEmpty() || !RunCases.from(c.get()).plan().equals(p)) {
                problems.add("the run header plans case " + p.id() + (c.isEmpty() ? ", which the corpus does not have"
                        : " otherwise than the corpus describes it"));
            }
        }
        if (h.provenance() == null || h.provenance().seed() == null) {
            problems.add("the run header has no run seed: the evidence cannot be judged again");
            return new Outcome(file.results(), problems);
        }
        long seed;
        try {
            seed = RunSeed.parse(h.provenance().seed());
        } catch (NumberFormatException e) {
            problems.add("the run seed '" + h.provenance().seed() + "' is not a number");
            return new Outcome(file.results(), problems);
        }
        // the semantic axis is judged again too: its exchanges are part of each case's evidence
        Presenter presenter = null;
        if (h.presentAs() != null) {
            Optional<org.fclcert.syntax.dialect.Dialect> dialect = org.fclcert.syntax.dialect.Dialect.byCliName(h.presentAs());
            if (dialect.isEmpty()) {
                problems.add("the run header presents as '" + h.presentAs() + "', which is no dialect of this fclcert");
                return new Outcome(file.results(), problems);
            }
            presenter = new Presenter(dialect.get());
        }
        // the dialect cases the run sent as written are those the header's implementation reads, as in the run
        CaseRunner runner = new CaseRunner(new ReferenceExportCheck(), presenter)
                .readingAs(h.iut() == null ? null : h.iut().spec());
        List<CaseResult> out = new ArrayList<>();
        for (CaseResult recorded : file.results()) {
            Optional<CorpusCase> c = corpus.byId(recorded.id());
            if (c.isEmpty()) {
                problems.add("case " + recorded.id() + ": not a case of the corpus");
                out.add(CaseResult.skipped(recorded.plan(), NO_EVIDENCE));
                continue;
            }
            if (recorded.replies() == null) {
                if (recorded.status() != CaseStatus.SKIPPED) {
                    problems.add("case " + recorded.id() + ": the line says " + recorded.status().name().toLowerCase()
                            + " but keeps no evidence");
                    out.add(CaseResult.skipped(recorded.plan(), NO_EVIDENCE));
                } else {
                    out.add(recorded);
                }
                continue;
            }
            CaseResult judged = judge(runner, RunCases.from(c.get()), recorded, seed, problems);
            out.add(judged);
        }
        return new Outcome(out, problems);
    }

    private static CaseResult judge(CaseRunner runner, RunCase c, CaseResult recorded, long seed, List<String> problems) {
        FreshEvidence.Prepared p = FreshEvidence.prepare(c, seed);
        ReplayIut replay = new ReplayIut(recorded.replies());
        CaseResult judged;
        try {
            judged = runner.run(new DisguisedIut(replay, p.disguise()), p.sent(), replay, p.plain(), p.disguise().twin(),
                    p.disguise()).result();
        } catch (RuntimeException e) {
            problems.add("case " + c.id() + ": its evidence cannot be judged: " + e);
            return CaseResult.skipped(recorded.plan(), NO_EVIDENCE);
        }
        judged = p.noted(judged, seed);
        // the run's statistics (its time, breakdowns and restarts) are carried as recorded: no verdict reads them
        judged = new CaseResult(judged.plan(), judged.verdict(), judged.evidence(), judged.export(),
                new CaseResult.Setup(judged.setup().block(), judged.setup().tolerance(), judged.setup().program(),
                        recorded.setup().durationMs(), recorded.setup().crashes(), recorded.setup().restarts()),
                judged.presented(), recorded.replies());
        if (replay.mismatch() != null) {
            problems.add("case " + c.id() + ": the evidence does not answer the requests of this case under the run's"
                    + " seed: " + replay.mismatch());
        }
        String difference = firstDifference(recorded, judged);
        if (difference != null) {
            problems.add("case " + c.id() + ": " + difference);
        }
        return judged;
    }

    /** The first field in which the line differs from the judging of its evidence, in words; null when none. */
    private static String firstDifference(CaseResult recorded, CaseResult judged) {
        ObjectNode a = (ObjectNode) Json.mapper().valueToTree(recorded);
        ObjectNode b = (ObjectNode) Json.mapper().valueToTree(judged);
        for (ObjectNode n : List.of(a, b)) {
            n.remove("durationMs");
        }
        if (!a.path("status").equals(b.path("status"))) {
            return "the line says " + a.path("status").asText() + ", its evidence judged again gives "
                    + b.path("status").asText() + " (" + b.path("message").asText() + ")";
        }
        Iterator<Map.Entry<String, JsonNode>> fields = b.fields();
        while (fields.hasNext()) {
            Map.Entry<String, JsonNode> f = fields.next();
            if (!f.getValue().equals(a.get(f.getKey()))) {
                return "the line's '" + f.getKey() + "' is not what its evidence judged again gives";
            }
        }
        Iterator<String> names = a.fieldNames();
        while (names.hasNext()) {
            String name = names.next();
            if (!b.has(name)) {
                return "the line has a '" + name + "' its evidence judged again does not give";
            }
        }
        return null;
    }
}
