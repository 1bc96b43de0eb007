package org.fclcert.harness;

import java.time.Instant;
import java.util.List;
import org.fclcert.iut.IutInfo;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Toolkit;

/** Builds the header of a run from what the implementation said and what was selected. */
public final class RunHeaders {
    private RunHeaders() {
    }

    /**
     * @param spec      the {@code --iut} spec that reaches the implementation again
     * @param classpath the {@code --classpath} given, or null
     * @param all       every case of the corpus (the Basic verdict needs to know how many Basic cases it has)
     * @param selected  the cases that will run, in order
     * @param filters   the filters as given: levels, features, case globs
     */
    public static RunHeader of(IutInfo info, String spec, String classpath, String corpusDir, String sha256,
            List<RunCase> all, List<RunCase> selected, List<List<String>> filters) {
        return of(info, spec, classpath, corpusDir, sha256, all, selected, filters, null);
    }

    /** As above, with the front end's command that reruns one case ({@link RunHeader.Toolkit#rerun}; null: none). */
    public static RunHeader of(IutInfo info, String spec, String classpath, String corpusDir, String sha256,
            List<RunCase> all, List<RunCase> selected, List<List<String>> filters, String rerun) {
        int basic = (int) all.stream().filter(c -> c.level() == ConformanceLevel.BASIC && !c.interpretation()).count();
        return new RunHeader(
                new RunHeader.Iut(info.name(), info.version(), info.command(), spec, classpath, info.claims(),
                        info.declaredLimits()),
                new RunHeader.Toolkit(Toolkit.version(), rerun),
                new RunHeader.CorpusInfo(corpusDir, all.size(), sha256, basic, rowCases(all)),
                new RunHeader.Selection(filters.get(0), filters.get(1), filters.get(2),
                        selected.stream().map(RunCase::plan).toList()),
                Instant.now().toString());
    }

    /** Per feature row, the cases of its level or below (not interpretation) whose {@code tests} name it. */
    static java.util.Map<String, Integer> rowCases(List<RunCase> all) {
        java.util.Map<String, Integer> rows = new java.util.TreeMap<>();
        for (RunCase c : all) {
            if (c.interpretation()) {
                continue;
            }
            for (String t : c.tests()) {
                org.fclcert.model.Feature.byId(t.toUpperCase(java.util.Locale.ROOT))
                        .filter(f -> c.level().compareTo(f.level()) <= 0)
                        .ifPresent(f -> rows.merge(f.id(), 1, Integer::sum));
            }
        }
        return rows;
    }
}
