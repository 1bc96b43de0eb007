package org.fclcert.syntax;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.misc.ParseCancellationException;
import org.junit.jupiter.api.Test;

/**
 * {@link Keywords#isSoft} against the grammar it mirrors: a keyword is soft exactly when the parser generated
 * from Fcl.g4 (its softKeyword rule) parses it as a term's name.
 */
class KeywordsTest {
    @Test
    void theSoftKeywordsAreTheOnesTheGrammarTakesAsNames() {
        int soft = 0;
        for (int type = 1; Keywords.isKeyword(type); type++) {
            String spelling = Keywords.spelling(type);
            String text = "FUNCTION_BLOCK f\nVAR_INPUT x : REAL; END_VAR\nFUZZIFY x\nTERM " + spelling
                    + " := (0, 1) (1, 0);\nEND_FUZZIFY\nEND_FUNCTION_BLOCK\n";
            boolean parsed = parses(text);
            assertEquals(parsed, Keywords.isSoft(type), spelling);
            soft += parsed ? 1 : 0;
        }
        assertEquals(28, soft);   // Fcl.g4's softKeyword rule lists 28 keywords
        assertEquals(true, parses("FUNCTION_BLOCK f END_FUNCTION_BLOCK"));
    }

    private static boolean parses(String text) {
        FclParser parser = new FclParser(new CommonTokenStream(new FclLexer(CharStreams.fromString(text))));
        parser.removeErrorListeners();
        parser.setErrorHandler(new BailErrorStrategy());
        try {
            parser.program();
            return true;
        } catch (ParseCancellationException e) {
            return false;
        }
    }
}
