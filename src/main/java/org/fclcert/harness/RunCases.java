package org.fclcert.harness;

import java.util.List;
import java.util.Optional;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.corpus.OutputScales;
import org.fclcert.corpus.Tolerance;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Program;

/** Turns corpus cases into the runner's cases (the one place that knows the corpus record's shape). */
public final class RunCases {
    private RunCases() {
    }

    public static RunCase from(CorpusCase c) {
        return new RunCase(c.id(), c.title(), c.level(), ids(c.features()), ids(c.tests()), c.flags(), c.block(),
                c.vectors(), c.expectReject() ? c.expectedError() : Optional.empty(), tolerance(c), c.programText(),
                c.path().toString(), c.dialect());
    }

    public static List<RunCase> from(List<CorpusCase> cases) {
        return cases.stream().map(RunCases::from).toList();
    }

    private static List<String> ids(List<Feature> features) {
        return features.stream().map(Feature::id).toList();
    }

    /**
     * The case's tolerance class with the output widths of its own program (the continuous class is a
     * fraction of each output's width); the exact class and negative cases need no widths.
     */
    private static OutputTolerance tolerance(CorpusCase c) {
        if (c.expectReject() || c.tolerance() == Tolerance.EXACT) {
            return new CorpusTolerance(c.tolerance(), OutputScales.none());
        }
        Analysis analysis = Analysis.analyze(c.reader(), c.path().toString(), c.programText());
        OutputScales scales = analysis.program().flatMap(p -> block(p, c.block())).map(OutputScales::of)
                .orElse(OutputScales.none());
        return new CorpusTolerance(c.tolerance(), scales);
    }

    private static Optional<FunctionBlock> block(Program p, Optional<String> name) {
        return name.isPresent() ? p.functionBlock(name.get()) : p.functionBlocks().stream().findFirst();
    }
}
