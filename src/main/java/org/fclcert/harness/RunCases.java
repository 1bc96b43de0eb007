package org.fclcert.harness;

import java.util.List;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.model.Feature;

/** Turns corpus cases into the runner's cases (the one place that knows the corpus record's shape). */
public final class RunCases {
    private RunCases() {
    }

    public static RunCase from(CorpusCase c) {
        return new RunCase(c.id(), c.title(), c.level(), ids(c.features()), ids(c.tests()), c.flags(), c.block(),
                c.vectors(), c.expectedError(), tolerance(c), c.program(), c.path().toString());
    }

    public static List<RunCase> from(List<CorpusCase> cases) {
        return cases.stream().map(RunCases::from).toList();
    }

    private static List<String> ids(List<Feature> features) {
        return features.stream().map(Feature::id).toList();
    }

    private static OutputTolerance tolerance(CorpusCase c) {
        return Tolerances.exact(); // TODO adapt to the corpus's tolerance classes when they land
    }
}
