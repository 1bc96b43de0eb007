package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * FFLL's cheap first look ({@link FfllSignals}) never hides a giveaway the full read finds: on every FCL text
 * at hand (the corpus, the test resources, FFLL's and fuzzylite's examples) and on one text of each FFLL
 * construct, a text it passes over has no giveaway by the full read.
 */
class FfllSignalsTest {
    private static final String STANDARD = """
            FUNCTION_BLOCK tank
            VAR_INPUT level, flow : REAL; END_VAR
            VAR_OUTPUT valve : REAL; END_VAR
            FUZZIFY level TERM low := (0, 1) (10, 0); TERM high := (0, 0) (10, 1); END_FUZZIFY
            FUZZIFY flow TERM slow := (0, 1) (5, 0); TERM fast := (0, 0) (5, 1); END_FUZZIFY
            DEFUZZIFY valve TERM shut := 0; TERM open := 100; METHOD : COGS; DEFAULT := 0; END_DEFUZZIFY
            RULEBLOCK r
            AND : MIN;
            ACCU : MAX;
            RULE 1 : IF level IS low AND NOT flow IS fast THEN valve IS open WITH 0.5; (* an IF without IS: x *)
            RULE 2 : IF (level IS high) OR flow IS NOT slow THEN valve IS shut;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    private static void agrees(String name, String text) {
        if (!FfllSignals.possible(text)) {
            assertEquals(List.of(), FfllReader.readGiveaways(text), name + ": passed over, but the full read finds");
        }
    }

    @Test
    void aStandardProgramIsPassedOverAndHasNoGiveaway() {
        assertFalse(FfllSignals.possible(STANDARD));
        assertEquals(List.of(), FfllReader.readGiveaways(STANDARD));
    }

    @Test
    void aRuleRunningIntoTheNextRulesOutTheTermOnlyConstructs() {
        // one ';' forgotten: the full read has a syntax error, so no program and no term-only giveaway; the
        // first look passes over it (it once read every such text, 200 ms for 10 000 rules)
        String runsOn = STANDARD.replace("WITH 0.5;", "WITH 0.5");
        assertFalse(FfllSignals.possible(runsOn));
        assertEquals(List.of(), FfllReader.readGiveaways(runsOn));
        // even with a term-only subcondition, in the same rule or another
        for (String text : List.of(runsOn.replace("IF level IS low AND", "IF low AND"),
                runsOn.replace("THEN valve IS shut", "THEN shut"),
                STANDARD.replace("THEN valve IS shut;", "THEN valve IS shut").replace("IF level IS low AND", "IF low AND"))) {
            assertFalse(FfllSignals.possible(text), text);
            assertEquals(List.of(), FfllReader.readGiveaways(text), text);
        }
        // but what the token filter finds alone still counts: ACCUM is looked at and found
        String accum = runsOn.replace("ACCU : MAX", "ACCUM : MAX");
        assertTrue(FfllSignals.possible(accum));
        assertFalse(FfllReader.readGiveaways(accum).isEmpty());
    }

    @Test
    void eachFfllConstructIsLookedAtAndFound() {
        List<String> ffll = List.of(
                STANDARD.replace("ACCU : MAX", "ACCUM : MAX"),
                STANDARD.replace("VAR_INPUT level", "VAR_INPUT RETAIN level"),
                STANDARD.replace("level, flow : REAL", "level, flow REAL"),
                STANDARD.replace("DEFAULT := 0; END_DEFUZZIFY", "DEFAULT := 0; END_FUZZIFY"),
                STANDARD.replace("DEFAULT := 0", "DEFAULT : = 0"),
                STANDARD.replace("IF level IS low AND", "IF low AND"),
                STANDARD.replace("THEN valve IS open", "THEN open"),
                STANDARD.replace("VAR_OUTPUT valve : REAL; END_VAR", "VAR_OUTPUT valve : REAL; (* RANGE(0 .. 100) *) END_VAR"),
                STANDARD.replace("DEFUZZIFY valve TERM shut := 0; TERM open := 100; METHOD : COGS; DEFAULT := 0; END_DEFUZZIFY",
                        "FUZZIFY valve TERM shut := 0; TERM open := 100; END_FUZZIFY"));
        for (String text : ffll) {
            assertTrue(FfllSignals.possible(text), text);
            assertFalse(FfllReader.readGiveaways(text).isEmpty(), text);
        }
    }

    @Test
    void noTextAtHandIsPassedOverWithAGiveaway() throws IOException {
        List<Path> files = TextsAtHand.files(".fcl");
        assertTrue(files.size() > 100, "FCL texts found: " + files.size());
        int passedOver = 0;
        int found = 0;
        for (Path f : files) {
            String text = new String(Files.readAllBytes(f), StandardCharsets.UTF_8);
            agrees(f.toString(), text);
            passedOver += FfllSignals.possible(text) ? 0 : 1;
            found += FfllReader.readGiveaways(text).isEmpty() ? 0 : 1;
        }
        // both sides occur, so the agreement above is tested on texts of each kind
        assertTrue(passedOver > 50, "passed over: " + passedOver + " of " + files.size());
        assertTrue(found > 0, "texts with FFLL giveaways: " + found);
    }
}
