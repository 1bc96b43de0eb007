package org.fclcert.corpus;

import java.util.List;

/**
 * What {@link CorpusLint} found.
 *
 * @param cases          case files read (positive plus negative)
 * @param positive       positive cases (with vectors)
 * @param negative       negative cases ({@code expect: reject})
 * @param caseFindings   problems with individual case files, each located in its file
 * @param coverageGaps   shortfalls of the corpus as a whole (a feature row without enough cases, ...)
 */
public record LintReport(int cases, int positive, int negative, List<CorpusProblem> caseFindings,
                         List<String> coverageGaps) {
    public LintReport {
        caseFindings = List.copyOf(caseFindings);
        coverageGaps = List.copyOf(coverageGaps);
    }

    public boolean clean() {
        return caseFindings.isEmpty() && coverageGaps.isEmpty();
    }
}
