package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link DialectReaders#kept}: an edit it lets the language server keep auto's choice for gives the same choice
 * when the edited text is detected afresh, on every FCL, FLL and FIS text at hand and random digit edits of each;
 * and the edits it refuses include those that do change the choice.
 */
class DetectionKeptTest {
    /** What a choice shows and decides: the dialect, the giveaways with their lines, the close call, the message. */
    private static List<Object> shown(DialectReaders.Choice c) {
        return List.of(c.dialect(), c.giveaways(), c.tiedWith(), c.explanation(),
                c.problem().map(d -> d.diagnosticCode().code() + " " + d.location().line() + ":" + d.location().column()
                        + " " + d.message()).orElse(""));
    }

    private static String edit(String text, int from, int to, String inserted) {
        return text.substring(0, from) + inserted + text.substring(to);
    }

    @Test
    void aKeptChoiceIsTheChoiceOfTheEditedText() throws IOException {
        List<Path> files = TextsAtHand.files(".fcl", ".fll", ".fis");
        assertTrue(files.size() > 100, "texts found: " + files.size());
        Random random = new Random(31);
        int kept = 0;
        int refused = 0;
        java.util.Set<Dialect> keptIn = java.util.EnumSet.noneOf(Dialect.class);
        for (Path f : files) {
            String text = new String(Files.readAllBytes(f), StandardCharsets.UTF_8);
            DialectReaders.Detection before = DialectReaders.detect(text);
            assertEquals(shown(DialectReaders.auto(text)), shown(before.choice()), f.toString());
            List<Integer> digitsAt = new ArrayList<>();
            for (int i = 0; i < text.length(); i++) {
                if (Character.isDigit(text.charAt(i)) && text.charAt(i) < 128) {
                    digitsAt.add(i);
                }
            }
            for (int k = 0; k < Math.min(8, digitsAt.size()); k++) {
                int at = digitsAt.get(random.nextInt(digitsAt.size()));
                // one digit typed over, or two for one (a number grows)
                String inserted = random.nextBoolean() ? String.valueOf((char) ('0' + random.nextInt(10)))
                        : (random.nextInt(9) + 1) + "" + random.nextInt(10);
                if (!DialectReaders.kept(before, text, at, at + 1, inserted)) {
                    refused++;
                    continue;
                }
                kept++;
                keptIn.add(before.choice().dialect());
                String after = edit(text, at, at + 1, inserted);
                assertEquals(shown(before.choice()), shown(DialectReaders.auto(after)), f + ", offset " + at + " -> "
                        + inserted);
            }
        }
        // both outcomes occur, and kept choices of several dialects, so the agreement above is tested
        assertTrue(kept > 300, "kept " + kept);
        assertTrue(refused > 300, "refused " + refused);
        assertTrue(keptIn.size() >= 3, "kept in " + keptIn);
    }

    /** A jFuzzyLogic habit: a DEFUZZIFY term not falling to 0 at both ends, no RANGE (weight 2). */
    private static final String JFL = """
            FUNCTION_BLOCK tank
            VAR_INPUT level : REAL; END_VAR
            VAR_OUTPUT valve : REAL; END_VAR
            FUZZIFY level TERM low := (0, 1) (10, 0); TERM high := (0, 0) (10, 1); END_FUZZIFY
            DEFUZZIFY valve
            TERM open := (0, 0) (50, 1) (100, 1);
            METHOD : COG; DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK r
            AND : MIN;
            RULE 1 : IF level IS low THEN valve IS open WITH 0.5;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    @Test
    void aDegreeOfATermIsNotKeptForItCanChangeTheChoice() {
        DialectReaders.Detection before = DialectReaders.detect(JFL);
        assertEquals(Dialect.JFUZZYLOGIC, before.choice().dialect());
        int degree = JFL.indexOf("(100, 1)") + 6;
        assertFalse(DialectReaders.kept(before, JFL, degree, degree + 1, "0"));
        // and indeed: falling to 0 at the end, the term gives nothing away, and the text is standard FCL
        assertEquals(Dialect.STRICT, DialectReaders.auto(edit(JFL, degree, degree + 1, "0")).dialect());
        // a rule's weight is kept
        int weight = JFL.indexOf("0.5") + 2;
        assertTrue(DialectReaders.kept(before, JFL, weight, weight + 1, "7"));
        assertEquals(shown(before.choice()), shown(DialectReaders.auto(edit(JFL, weight, weight + 1, "7"))));
        // a comment between the statement before and the edit, as the 10 000-rule benchmark writes one: kept
        String commented = JFL.replace("AND : MIN;", "AND : MIN; (* the rules: *)");
        int w = commented.indexOf("0.5") + 2;
        assertTrue(DialectReaders.kept(DialectReaders.detect(commented), commented, w, w + 1, "7"));
        // but a ';' in a comment is no statement's end: the TERM before it is seen through the comment
        String hidden = JFL.replace("TERM open := (0, 0) (50, 1) (100, 1);", "TERM open := (0, 0) (* ; *) (50, 1) (100, 1);");
        int d = hidden.indexOf("(100, 1)") + 6;
        assertFalse(DialectReaders.kept(DialectReaders.detect(hidden), hidden, d, d + 1, "0"));
        String hiddenByLine = JFL.replace("TERM open := (0, 0) (50, 1) (100, 1);", "TERM open := (0, 0) // ;\n (50, 1) (100, 1);");
        int e = hiddenByLine.indexOf("(100, 1)") + 6;
        assertFalse(DialectReaders.kept(DialectReaders.detect(hiddenByLine), hiddenByLine, e, e + 1, "0"));
        // not a digit, or in a name, or beside a letter (an exponent): refused
        assertFalse(DialectReaders.kept(before, JFL, weight, weight + 1, "x"));
        assertFalse(DialectReaders.kept(before, JFL, weight - 2, weight + 1, "1"));   // '0.5' holds a '.'
    }

    @Test
    void aTextFfllsFullReadLookedAtIsNotKept() {
        String ffll = JFL.replace("AND : MIN;", "ACCUM : MAX;");
        DialectReaders.Detection before = DialectReaders.detect(ffll);
        assertTrue(before.ffllRead());
        int weight = ffll.indexOf("0.5") + 2;
        assertFalse(DialectReaders.kept(before, ffll, weight, weight + 1, "7"));
        assertNotEquals(before.choice().dialect(), Dialect.STRICT);
    }
}
