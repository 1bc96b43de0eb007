package org.fclcert.check;

import static org.fclcert.check.ModelFixtures.nested;
import static org.fclcert.check.ModelFixtures.rule;
import static org.fclcert.check.ModelFixtures.tempValve;
import static org.fclcert.check.ModelFixtures.validRules;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.fclcert.cli.DiagnosticCatalogue;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Limits;
import org.fclcert.model.Rule;
import org.junit.jupiter.api.Test;

/** Checker behaviour on hand-built models: the rules and their codes, nesting limit, no stack overflow. */
class CheckerModelTest {
    private final Checker checker = new Checker();

    @Test
    void everyCheckCodeOfTheCatalogueIsOwnedByExactlyOneRegisteredRuleInCodeOrder() {
        List<String> catalogued = DiagnosticCatalogue.all().stream().filter(c -> c instanceof CheckCode)
                .map(DiagnosticCode::code).toList();
        List<String> owned = Checker.standardRules().stream().map(CheckRule::code).toList();
        assertEquals(catalogued, owned);
        assertEquals(owned.size(), Set.copyOf(owned).size(), "two rules own one code: " + owned);
        assertEquals(owned.stream().sorted().toList(), owned, "standardRules() lists the rules in code order");
        for (CheckRule rule : Checker.standardRules()) {
            assertTrue(!rule.asserts().isBlank(), rule.code());
            assertEquals(rule.diagnosticCode().severity(), rule.severity(), rule.code());
        }
        // the catalogue's check family as docs/diagnostics.md has it (DiagnosticCatalogueDocTest compares
        // the rest): at least the 31 errors of the standard's own rules and the 4 warnings
        assertTrue(owned.containsAll(List.of("FCL-C001", "FCL-C031", "FCL-C040", "FCL-C041", "FCL-W001", "FCL-W004")));
    }

    @Test
    void everyRuleClassOfThePackageIsRegistered() throws IOException {
        Set<String> registered = new HashSet<>();
        Checker.standardRules().forEach(r -> registered.add(r.getClass().getSimpleName()));
        Pattern rule = Pattern.compile("public final class (\\w+) implements (CheckRule|FunctionBlockRule)\\b");
        Set<String> declared = new HashSet<>();
        try (Stream<Path> files = Files.list(Path.of("src/main/java/org/fclcert/check"))) {
            for (Path f : files.toList()) {
                Matcher m = rule.matcher(Files.readString(f));
                if (m.find()) {
                    declared.add(m.group(1));
                }
            }
        }
        assertEquals(declared, registered, "a rule class not in Checker.standardRules() never runs");
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
