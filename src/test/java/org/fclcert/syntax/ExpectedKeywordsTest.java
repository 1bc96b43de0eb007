package org.fclcert.syntax;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/** The keywords Fcl.g4 allows after a text, as completion offers them. */
class ExpectedKeywordsTest {
    private static final String RULE = "FUNCTION_BLOCK f\nRULEBLOCK r\nRULE 1 : IF ";

    private static Set<String> after(String text) {
        return new TreeSet<>(ExpectedKeywords.after(text));
    }

    @Test
    void afterAVariableOfAConditionTheOperatorsAndThen() {
        // subcondition ::= name (IS NOT? name)?; then AND, OR, and at the top of the condition THEN
        assertEquals(Set.of("IS", "AND", "OR", "THEN"), after(RULE + "x"));
        // inside parentheses ')' may close it (not a keyword), THEN may not follow yet
        assertEquals(Set.of("IS", "AND", "OR"), after(RULE + "(x"));
    }

    @Test
    void deepNestingGivesTheSameAnswer() throws Exception {
        // 5 000 '(' once took seconds: the recovery after the end unwound every open rule, walking the rule
        // stack at each level; the answer is known at the end of the text and the parse stops there.
        // On a thread with a large stack, as the language server's (the parser recurses per level)
        Object[] got = new Object[2];
        Thread t = new Thread(null, () -> {
            got[0] = after(RULE + "(".repeat(5000) + "x");
            got[1] = ExpectedKeywords.after(RULE + "(".repeat(5000) + "x IS");
        }, "deep", 256L << 20);
        t.start();
        t.join();
        assertEquals(Set.of("IS", "AND", "OR"), got[0]);
        assertEquals(List.of("NOT"), got[1]);
    }
}
