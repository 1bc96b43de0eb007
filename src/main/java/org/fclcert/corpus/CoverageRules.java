package org.fclcert.corpus;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;

/**
 * What the corpus as a whole must cover (issue 4): every Table 8 and Table 9 row is the {@code tests} target of
 * at least {@value #CASES_PER_ROW} positive cases; every Open Level feature of the catalogue that a standard-syntax
 * program can carry of at least one (dialect-syntax constructs, {@link Feature#dialectSyntax()}, are exempt);
 * at least {@value #NEGATIVE_CASES} negative cases.
 */
public final class CoverageRules {
    public static final int CASES_PER_ROW = 3;
    public static final int NEGATIVE_CASES = 40;

    private CoverageRules() {
    }

    /** Each shortfall as a sentence; empty when the corpus is complete. */
    public static List<String> gaps(List<CorpusCase> cases) {
        List<String> gaps = new ArrayList<>();
        for (Feature f : Feature.values()) {
            if (f.dialectSyntax()) {
                continue;   // only a case written in a dialect can carry it: not asked for (Feature#dialectSyntax)
            }
            long n = cases.stream().filter(c -> !c.expectReject() && c.tests().contains(f)).count();
            int needed = f.level() == ConformanceLevel.OPEN ? 1 : CASES_PER_ROW;
            if (n < needed) {
                gaps.add(f.id() + " (Table " + f.table() + ", " + f.description() + ") is the 'tests' target of " + n
                        + " positive case(s); at least " + needed + " needed");
            }
        }
        long negative = cases.stream().filter(CorpusCase::expectReject).count();
        if (negative < NEGATIVE_CASES) {
            gaps.add(negative + " negative case(s); at least " + NEGATIVE_CASES + " needed");
        }
        return gaps;
    }
}
