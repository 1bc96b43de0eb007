package org.fclcert.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import java.util.ArrayList;
import java.util.List;
import org.fclcert.harness.Provenance;
import org.fclcert.harness.ResultsChain;
import org.fclcert.probe.DataCheckEntry;

/**
 * Where a report comes from and what backs it ({@code report.json}'s {@code origin}): the run's provenance as
 * measured ({@link Provenance}: seed, fclcert build, corpus identity, machine, the implementation's files and its
 * claimed name), when it ended, the digest of its {@code results.jsonl} ({@link ResultsChain}), how its verdicts
 * were reached ({@code verification}), and the warnings its headline must carry ({@code warnings}: a custom
 * corpus, a conformant verdict next to an empty Table 11, results that could not be verified).
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record Origin(Provenance provenance, String endedAt, String digest, String verification,
        List<String> warnings) {

    public Origin {
        warnings = warnings == null ? List.of() : List.copyOf(warnings);
    }

    /** How a live run's verdicts were reached. */
    public static final String JUDGED_LIVE = "judged as the run went; each case line keeps the implementation's replies";
    /** How verdicts rebuilt from evidence were reached. */
    public static final String REJUDGED = "every verdict recomputed by judging each case line's recorded replies"
            + " again against the corpus and the run's fresh vectors (regenerated from the seed); the chain and the"
            + " corpus hash checked";

    /**
     * {@code report} with its origin: the provenance of {@code provenance} (null: a run without one), the seal of
     * its results (null: none), {@code verification}; a custom corpus that lacks built-in Basic Level cases turns
     * the Basic verdict into "not determined"; the headline warnings are worked out here.
     */
    public static Report apply(Report report, Provenance provenance, ResultsChain.Seal seal, String verification,
            List<String> moreWarnings) {
        List<String> warnings = new ArrayList<>();
        Report.BasicLevel basic = report.basicLevel();
        List<Report.FeatureRow> features = report.features();
        if (provenance != null && provenance.corpus() != null && !provenance.corpus().builtIn()) {
            Provenance.CorpusIdentity c = provenance.corpus();
            warnings.add("a custom corpus (" + report.corpus().cases() + " cases, sha256 " + c.sha256() + "), not the"
                    + " fclcert conformance corpus built into this fclcert: the results say nothing of the built-in"
                    + " corpus's cases");
            if (!c.missingBasic().isEmpty()) {
                List<String> named = c.missingBasic().subList(0, Math.min(5, c.missingBasic().size()));
                basic = new Report.BasicLevel(false, basic.required(), basic.run(), basic.passed(),
                        "the custom corpus does not hold " + c.missingBasic().size() + " of the built-in"
                        + " Basic Level cases unchanged (" + String.join(", ", named)
                        + (c.missingBasic().size() > named.size() ? ", …" : "") + "); a Basic Level verdict is issued"
                        + " only when every built-in Basic Level case was run");
            }
            if (!c.missingExtension().isEmpty()) {
                List<String> named = c.missingExtension().subList(0, Math.min(5, c.missingExtension().size()));
                warnings.add("Extension Level (Table 9): " + Report.BasicLevel.NOT_DETERMINED + ": the custom corpus"
                        + " does not hold " + c.missingExtension().size() + " of the built-in Extension Level cases"
                        + " unchanged (" + String.join(", ", named) + (c.missingExtension().size() > named.size()
                        ? ", …" : "") + "); an Extension Level verdict is issued only when every built-in Extension"
                        + " Level case was run");
                features = features.stream().map(Origin::extensionNotDetermined).toList();
            }
        }
        if (basic.conformant() && emptyTable11(report.dataCheckList())) {
            warnings.add("CONTRADICTION: a conformant verdict next to an empty or all-zero Table 11: nothing shows the"
                    + " implementation can load a program it was not shown before"
                    + (report.dataCheckList().isEmpty() ? " (the data check list was not measured)" : ""));
        }
        if (provenance == null) {
            warnings.add("UNVERIFIED: these results carry no run seed and no evidence (written without fresh vectors"
                    + " and disguise); nothing in them can be checked again");
            basic = new Report.BasicLevel(false, basic.required(), basic.run(), basic.passed(), "not determined: the"
                    + " results carry no run seed and no evidence, so no verdict can be issued from them ("
                    + basic.reason() + ")");
        }
        warnings.addAll(moreWarnings);
        Origin origin = new Origin(provenance, seal == null ? null : seal.endedAt(), seal == null ? null : seal.digest(),
                verification, warnings);
        return new Report(report.formatVersion(), report.generatedAt(), report.iut(), report.toolkit(), report.corpus(),
                report.run(), report.summary(), report.rejections(), basic, features, report.dataCheckList(),
                report.interpretation(), report.claims(), report.causes(), report.cases(), report.semantic(), origin);
    }

    /** A Table 9 row whose verdict a custom corpus cannot give: not determined (its counts kept). */
    private static Report.FeatureRow extensionNotDetermined(Report.FeatureRow r) {
        if (r.table() != 9 || r.status() == FeatureStatus.NOT_DETERMINED || r.status() == FeatureStatus.NOT_TESTED) {
            return r;
        }
        return new Report.FeatureRow(r.id(), r.table(), r.level(), r.element(), r.description(),
                FeatureStatus.NOT_DETERMINED, r.passed(), r.failed(), r.errored(), r.skipped(), r.cases(), r.notPassed(),
                r.semantic(), r.required(), r.run(), r.notCounted());
    }

    /** Table 11 empty, or every measured value 0 or none. */
    static boolean emptyTable11(List<DataCheckEntry> entries) {
        return entries.stream().allMatch(e -> DataCheckEntry.NOT_MEASURED.equals(e.bound())
                || e.value() == null || e.value().isBlank() || e.value().strip().matches("0+(\\.0+)?|none|\\[\\]"));
    }

    /** The lines a rendering shows of the origin, before any escaping (the caller escapes each). */
    public List<String> lines() {
        List<String> out = new ArrayList<>();
        if (provenance != null) {
            Provenance p = provenance;
            out.add("Run seed: " + p.seed() + " (certify --seed " + p.seed() + " replays the fresh vectors and disguises)");
            if (p.toolkit() != null) {
                out.add("fclcert " + p.toolkit().version() + ", commit " + p.toolkit().commit() + ", "
                        + p.toolkit().jar() + " sha256 " + p.toolkit().jarSha256());
            }
            if (p.corpus() != null) {
                out.add("Corpus: " + p.corpus().description() + ", sha256 " + p.corpus().sha256());
            }
            out.add("Machine: " + p.os() + "; " + p.jvm());
            if (p.iut() != null) {
                Provenance.IutIdentity i = p.iut();
                out.add("Implementation, as measured: " + i.kind() + (i.executable() == null ? "" : ", executable "
                        + i.executable()));
                i.files().forEach(f -> out.add("  " + f.path() + ": sha256 " + f.sha256()));
                out.add("Implementation, as it names itself (a claim, not measured): " + i.claimedName() + " "
                        + i.claimedVersion());
            }
        }
        if (endedAt != null) {
            out.add("Ended: " + endedAt);
        }
        out.add("results.jsonl digest: " + (digest == null ? "none (the results are not sealed)" : digest)
                + " (proves the reports and the results file are of one run and unedited since, not who made them)");
        if (verification != null) {
            out.add("Verdicts: " + verification);
        }
        return out;
    }
}
