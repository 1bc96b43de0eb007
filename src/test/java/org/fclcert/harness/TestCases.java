package org.fclcert.harness;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.corpus.ExpectedError;
import org.fclcert.corpus.Vector;
import org.fclcert.model.ConformanceLevel;

/** Builds runner cases directly, for tests that do not need the corpus loader. */
public final class TestCases {
    private TestCases() {
    }

    public static Vector step(Map<String, Double> in, Map<String, Double> out) {
        return new Vector(in, out);
    }

    public static RunCase positive(String id, ConformanceLevel level, List<String> tests, List<String> flags,
            List<Vector> vectors) {
        return new RunCase(id, "title of " + id, level, tests, tests, flags, Optional.empty(), vectors,
                Optional.empty(), Tolerances.exact(), "FUNCTION_BLOCK fb\nEND_FUNCTION_BLOCK\n", id + ".fcl");
    }

    public static RunCase positive(String id, List<Vector> vectors) {
        return positive(id, ConformanceLevel.BASIC, List.of("B-COGS"), List.of(), vectors);
    }

    public static RunCase negative(String id, String code, int line) {
        return new RunCase(id, "title of " + id, ConformanceLevel.BASIC, List.of("B-FB"), List.of("B-FB"),
                List.of(), Optional.empty(), List.of(), Optional.of(new ExpectedError(code, line)),
                Tolerances.exact(), "FUNCTION_BLOCK fb\n", id + ".fcl");
    }

    public static RunCase withTolerance(RunCase c, OutputTolerance t) {
        return new RunCase(c.id(), c.title(), c.level(), c.features(), c.tests(), c.flags(), c.block(), c.vectors(),
                c.expectedError(), t, c.program(), c.source());
    }
}
