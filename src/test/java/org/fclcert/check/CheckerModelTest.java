package org.fclcert.check;

import static org.fclcert.check.ModelFixtures.nested;
import static org.fclcert.check.ModelFixtures.rule;
import static org.fclcert.check.ModelFixtures.tempValve;
import static org.fclcert.check.ModelFixtures.validRules;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Limits;
import org.fclcert.model.Rule;
import org.junit.jupiter.api.Test;

/** Checker behaviour on hand-built models: rule catalogue, nesting limit, no stack overflow. */
class CheckerModelTest {
    private final Checker checker = new Checker();

    @Test
    void everyCodeIsOwnedByExactlyOneRule() {
        Set<String> codes = new HashSet<>();
        for (CheckRule rule : Checker.standardRules()) {
            assertTrue(codes.add(rule.code()), "two rules own " + rule.code());
            assertTrue(!rule.asserts().isBlank(), rule.code());
        }
        Set<String> expected = new HashSet<>();
        for (int i = 1; i <= 31; i++) {
            expected.add(String.format("FCL-C%03d", i));
        }
        for (int i = 1; i <= 4; i++) {
            expected.add(String.format("FCL-W%03d", i));
        }
        expected.add("FCL-C040");   // named shapes (dialect readers): parameter count
        expected.add("FCL-C041");   // named shapes: parameter order and signs
        assertEquals(expected, codes);
    }

    @Test
    void theHandBuiltValidProgramHasNoFindings() {
        assertEquals(List.of(), checker.check(tempValve(validRules())));
    }

    @Test
    void nestingAtTheLimitIsAccepted() {
        List<Rule> rules = new ArrayList<>(validRules());
        rules.add(rule("3", nested(Limits.MAX_NESTING_DEPTH, 23), "valve", "closed", 23));
        assertEquals(List.of(), checker.check(tempValve(rules)));
    }

    @Test
    void nestingOneBeyondTheLimitIsReportedAtTheFirstParenthesisTooDeep() {
        List<Rule> rules = new ArrayList<>(validRules());
        rules.add(rule("3", nested(Limits.MAX_NESTING_DEPTH + 1, 23), "valve", "closed", 23));
        List<Diagnostic> found = checker.check(tempValve(rules));
        assertEquals(1, found.size(), found::toString);
        assertEquals("FCL-C026", found.get(0).code());
        // the parenthesis at depth d opens at column 16 + d; depth 1001 is the first one too deep
        assertEquals(23, found.get(0).location().line());
        assertEquals(16 + Limits.MAX_NESTING_DEPTH + 1, found.get(0).location().column());
    }

    @Test
    void hundredThousandNestedParenthesesGiveOneDiagnosticAndNoStackOverflow() {
        List<Rule> rules = new ArrayList<>(validRules());
        rules.add(rule("3", nested(100_000, 23), "valve", "closed", 23));
        List<Diagnostic> found = checker.check(tempValve(rules));
        assertEquals(List.of("FCL-C026"), found.stream().map(Diagnostic::code).toList());
        FeatureReport features = new FeatureDetector().detect(tempValve(rules));
        assertEquals(100_000, features.uses().stream().filter(u -> u.feature().id().equals("E-PARENS")).count());
    }

    @Test
    void aHundredThousandRuleBlockIsCheckedAndDetected() {
        List<Rule> rules = new ArrayList<>(validRules());
        for (int i = 3; i <= 100_002; i++) {
            rules.add(rule(Integer.toString(i), ModelFixtures.is("temp", i % 2 == 0 ? "hot" : "cold", i), "valve",
                    i % 2 == 0 ? "closed" : "open", i));
        }
        assertEquals(List.of(), checker.check(tempValve(rules)));
        FeatureReport features = new FeatureDetector().detect(tempValve(rules));
        assertEquals(100_002, features.uses().stream().filter(u -> u.feature().id().equals("B-ONE-SUBCONCLUSION"))
                .count());
    }
}
