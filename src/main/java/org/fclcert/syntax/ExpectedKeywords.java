package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.Parser;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.IntervalSet;
import org.antlr.v4.runtime.misc.ParseCancellationException;

/**
 * The keywords the grammar allows next after a text, for an editor's completion: Fcl.g4 is asked, not a list
 * kept beside it. The text is parsed to its end; the tokens the parser expects where the text stops are the
 * answer. Keywords the grammar takes only to report them (a keyword as a name, {@code END_FUZZIFY} closing a
 * DEFUZZIFY, 5.4's {@code OPTION} spelling) are left out, so only what strict FCL allows is offered.
 */
public final class ExpectedKeywords {
    private ExpectedKeywords() {
    }

    /** The keywords (as the standard spells them) that may follow {@code prefix}, in the grammar's token order. */
    public static List<String> after(String prefix) {
        FclLexer lexer = new FclLexer(CharStreams.fromString(prefix));
        lexer.removeErrorListeners();
        FclParser parser = new FclParser(new CommonTokenStream(lexer));
        parser.removeErrorListeners();
        // SLL: no full-context retries, so a deeply nested or long broken text costs one pass
        parser.getInterpreter().setPredictionMode(PredictionMode.SLL);
        IntervalSet[] atEnd = {null};
        parser.addErrorListener(new BaseErrorListener() {
            @Override
            public void syntaxError(Recognizer<?, ?> recognizer, Object offending, int line, int column, String msg,
                    RecognitionException e) {
                if (atEnd[0] == null && offending instanceof Token t && t.getType() == Token.EOF) {
                    atEnd[0] = e != null && e.getExpectedTokens() != null ? e.getExpectedTokens()
                            : ((Parser) recognizer).getExpectedTokens();
                    // that is the answer: stop here rather than let the recovery unwind every open rule, which
                    // walks the whole rule stack at each level (quadratic in the nesting: 5 000 '(' took seconds)
                    throw new ParseCancellationException("the expected tokens at the end are known");
                }
            }
        });
        try {
            parser.program();
        } catch (ParseCancellationException stop) {
            // thrown above, once the answer is known
        }
        if (atEnd[0] == null) {
            // the text is a whole program: what may follow is another function block
            return List.of(Keywords.spelling(FclLexer.FUNCTION_BLOCK));
        }
        boolean nameExpected = atEnd[0].contains(FclLexer.IDENT);
        List<String> out = new ArrayList<>();
        for (int type : atEnd[0].toArray()) {
            if (!Keywords.isKeyword(type) || (nameExpected && Keywords.isSoft(type)) || tolerated(type, atEnd[0])) {
                continue;
            }
            out.add(Keywords.spelling(type));
        }
        return out;
    }

    /** Spellings the grammar accepts only to report them as errors. */
    private static boolean tolerated(int type, IntervalSet expected) {
        return (type == FclLexer.END_FUZZIFY && expected.contains(FclLexer.END_DEFUZZIFY))
                || type == FclLexer.OPTION || type == FclLexer.END_OPTION;
    }
}
