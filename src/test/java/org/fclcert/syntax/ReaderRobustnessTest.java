package org.fclcert.syntax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.model.Condition;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Limits;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.junit.jupiter.api.Test;

/**
 * No input makes the reader throw, hang or overflow the stack: mutated programs, deep nesting, huge
 * programs and garbage all give diagnostics (or a program) and nothing else.
 */
class ReaderRobustnessTest {
    private static final Pattern CODE = Pattern.compile("FCL-(S\\d{3}|W1\\d{2})");
    private static final Pattern TOKEN = Pattern.compile(
            "\\(\\*|\\*\\)|:=|\\.\\.|[A-Za-z_][A-Za-z0-9_]*|[+-]?[0-9][0-9_.#A-Fa-fEe+-]*|\\S");
    private static final List<String> INSERTIONS = List.of(
            "(", ")", ";", ":", ":=", ",", "..", "=", "(*", "*)", "IF", "THEN", "IS", "NOT", "AND", "OR", "WITH",
            "RULE", "TERM", "END_VAR", "END_FUZZIFY", "END_DEFUZZIFY", "END_RULEBLOCK", "END_FUNCTION_BLOCK",
            "FUNCTION_BLOCK", "VAR_INPUT", "FUZZIFY", "DEFUZZIFY", "RULEBLOCK", "OPTIONS", "END_OPTIONS", "RANGE",
            "METHOD", "DEFAULT", "NC", "MAX", "REAL", "0", "1.5", ".5", "5.", "1E5", "16#FF", "2#12", "a__b", "x_",
            "RULE1", "#", "$", "\"", "\u00e9", "\u0000", "((((", "))))");

    private final StrictReader reader = new StrictReader();

    /** Reads and checks that the result is well formed: located, coded diagnostics; program iff no error. */
    private ReadResult readSafely(String text) {
        ReadResult r = reader.read("m.fcl", text);
        assertEquals(r.hasErrors(), r.program().isEmpty(), () -> "program iff no error: " + r.diagnostics());
        long errors = r.diagnostics().stream().filter(Diagnostic::isError).count();
        assertTrue(errors <= ReaderDiagnostics.MAX_ERRORS + 1, "errors are capped");
        for (Diagnostic d : r.diagnostics()) {
            assertTrue(CODE.matcher(d.code()).matches(), d::toString);
            assertFalse(d.code().equals(SyntaxCode.INTERNAL_ERROR.code()), () -> "internal error on:\n" + text + "\n" + d);
            assertTrue(d.location().line() >= 1 && d.location().column() >= 1, d::toString);
            assertFalse(d.message().isBlank());
            // no raw ANTLR wording leaks out
            for (String raw : List.of("mismatched input", "expecting {", "extraneous input", "<missing", "no viable")) {
                assertFalse(d.message().contains(raw), d::toString);
            }
        }
        return r;
    }

    private static List<int[]> tokenSpans(String text) {
        List<int[]> spans = new ArrayList<>();
        Matcher m = TOKEN.matcher(text);
        while (m.find()) {
            spans.add(new int[] {m.start(), m.end()});
        }
        return spans;
    }

    private static String mutate(String text, int kind, Random random) {
        List<int[]> spans = tokenSpans(text);
        int[] span = spans.get(random.nextInt(spans.size()));
        switch (kind) {
            case 0: // delete one to three tokens
                int[] last = spans.get(Math.min(spans.size() - 1, spans.indexOf(span) + random.nextInt(3)));
                return text.substring(0, span[0]) + text.substring(last[1]);
            case 1: // insert a token
                String insert = INSERTIONS.get(random.nextInt(INSERTIONS.size()));
                String glue = random.nextBoolean() ? " " : "";
                return text.substring(0, span[0]) + insert + glue + text.substring(span[0]);
            case 2: // truncate
                return text.substring(0, random.nextInt(text.length()));
            case 3: // overwrite a few characters with random bytes (as Latin-1 characters)
                StringBuilder sb = new StringBuilder(text);
                for (int i = 0, n = 1 + random.nextInt(8); i < n; i++) {
                    sb.setCharAt(random.nextInt(sb.length()), (char) random.nextInt(256));
                }
                return sb.toString();
            default: // swap two neighbouring tokens
                int i = spans.indexOf(span);
                if (i + 1 >= spans.size()) {
                    return text;
                }
                int[] next = spans.get(i + 1);
                return text.substring(0, span[0]) + text.substring(next[0], next[1])
                        + text.substring(span[1], next[0]) + text.substring(span[0], span[1]) + text.substring(next[1]);
        }
    }

    @Test
    void mutatedProgramsGiveOnlyDiagnostics() {
        Random random = new Random(20_261_122L);
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            int reads = 0;
            for (String name : FclTestPrograms.ALL) {
                String original = FclTestPrograms.text(name);
                for (int kind = 0; kind < 5; kind++) {
                    for (int n = 0; n < 80; n++) {
                        String text = mutate(original, kind, random);
                        // sometimes mutate twice, so that mistakes meet
                        if (random.nextInt(4) == 0) {
                            text = mutate(text, random.nextInt(5), random);
                        }
                        readSafely(text);
                        reads++;
                    }
                }
            }
            assertEquals(FclTestPrograms.ALL.size() * 5 * 80, reads);
        });
    }

    @Test
    void randomTextGivesOnlyDiagnostics() {
        Random random = new Random(7L);
        String alphabet = "();:=,.#*+-_ \n\tabcxyzRULEIFTHENAND0123456789";
        assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            for (int n = 0; n < 300; n++) {
                StringBuilder sb = new StringBuilder();
                for (int i = 0, len = random.nextInt(400); i < len; i++) {
                    sb.append(n % 2 == 0 ? alphabet.charAt(random.nextInt(alphabet.length())) : (char) random.nextInt(0x3000));
                }
                readSafely("FUNCTION_BLOCK f\n" + sb);
                readSafely(sb.toString());
            }
        });
    }

    /** A rule whose condition is {@code depth} parentheses around one subcondition. */
    private static String nested(int depth) {
        return StrictReaderTest.minimal("RULE 1 : IF " + "(".repeat(depth) + "x IS a" + ")".repeat(depth)
                + " THEN y IS b;");
    }

    @Test
    void nestingAtTheLimitIsRead() {
        ReadResult r = readSafely(nested(Limits.MAX_NESTING_DEPTH));
        Condition c = r.program().orElseThrow().functionBlocks().get(0).ruleBlocks().get(0).rules().get(0).condition();
        int depth = 0;
        while (c instanceof Condition.Parenthesized p) {
            depth++;
            c = p.inner();
        }
        assertEquals(Limits.MAX_NESTING_DEPTH, depth);
        assertInstanceOf(Condition.TermSubcondition.class, c);
    }

    @Test
    void nestingAtTheLimitWithAnErrorInsideIsReported() {
        String text = StrictReaderTest.minimal("RULE 1 : IF " + "(".repeat(Limits.MAX_NESTING_DEPTH) + "x IS"
                + ")".repeat(Limits.MAX_NESTING_DEPTH) + " THEN y IS b;");
        List<Diagnostic> d = readSafely(text).diagnostics();
        assertEquals("FCL-S024", d.get(0).code());
    }

    @Test
    void hundredThousandNestedParenthesesGiveOneClearError() {
        assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            ReadResult r = readSafely(nested(100_000));
            assertEquals(1, r.diagnostics().size(), () -> r.diagnostics().toString());
            Diagnostic d = r.diagnostics().get(0);
            assertEquals("FCL-S008", d.code());
            // line 7 is 'RULE 1 : IF (((...': the 1001st '(' is at column 13 + 1000
            assertEquals(7, d.location().line());
            assertEquals(13 + Limits.MAX_NESTING_DEPTH, d.location().column());
            // and unclosed ones as well
            assertEquals("FCL-S008", readSafely("(".repeat(100_000)).diagnostics().get(0).code());
        });
    }

    @Test
    void aHundredThousandRuleBlockOfTenMegabytesIsRead() {
        StringBuilder rules = new StringBuilder();
        for (int i = 1; i <= 100_000; i++) {
            rules.append("RULE ").append(i)
                    .append(" : IF x IS a AND (x IS NOT a OR NOT x IS a) THEN y IS b WITH 0.5; (* rule ").append(i)
                    .append(" *)\n");
        }
        String text = StrictReaderTest.minimal(rules.toString());
        assertTrue(text.length() > 9_000_000, "about 10 MB: " + text.length());
        assertTimeoutPreemptively(Duration.ofSeconds(120), () -> {
            ReadResult r = readSafely(text);
            RuleBlock block = r.program().orElseThrow().functionBlocks().get(0).ruleBlocks().get(0);
            assertEquals(100_000, block.rules().size());
            assertEquals("100000", block.rules().get(99_999).name());
        });
    }

    @Test
    void anAndChainOfAHundredThousandSubconditionsIsRead() {
        String chain = String.join(" AND ", java.util.Collections.nCopies(100_000, "x IS a"));
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            Program p = readSafely(StrictReaderTest.minimal("RULE 1 : IF " + chain + " THEN y IS b;")).program()
                    .orElseThrow();
            Condition.And and = assertInstanceOf(Condition.And.class,
                    p.functionBlocks().get(0).ruleBlocks().get(0).rules().get(0).condition());
            assertEquals(100_000, and.operands().size());
        });
    }

    @Test
    void tenMegabytesOfGarbageStopEarlyWithCappedErrors() {
        Random random = new Random(3L);
        StringBuilder garbage = new StringBuilder(10_000_000);
        for (int i = 0; i < 10_000_000; i++) {
            garbage.append((char) random.nextInt(128));
        }
        assertTimeoutPreemptively(Duration.ofSeconds(120), () -> {
            ReadResult r = readSafely(garbage.toString());
            assertTrue(r.diagnostics().stream().anyMatch(d -> d.code().equals("FCL-S099")));
            // two million stray ';' are one mistake: recovery skips them until something fits
            ReadResult semicolons = readSafely("FUNCTION_BLOCK f\n" + "; ".repeat(2_000_000));
            assertEquals(List.of("FCL-S034"), semicolons.diagnostics().stream().map(Diagnostic::code).toList());
        });
    }
}
