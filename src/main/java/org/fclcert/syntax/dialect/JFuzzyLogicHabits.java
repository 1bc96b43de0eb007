package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;
import org.fclcert.syntax.dialect.DialectReader.Giveaway;

/**
 * The giveaways of jFuzzyLogic that lie in a block's shape rather than in one word: what its users leave out
 * because jFuzzyLogic supplies it (METHOD, DEFAULT; weight 1, as for FFLL), a RANGE left out where only
 * jFuzzyLogic implies one (point terms not falling to 0 at both ends, Gaussians; weight 2: the first construct of
 * issue 13's survey), and statements in an order the standard does not allow but its grammar does (weight 1).
 */
final class JFuzzyLogicHabits {
    private JFuzzyLogicHabits() {
    }

    static List<Giveaway> of(List<Token> t) {
        List<Giveaway> out = new ArrayList<>();
        for (int i = 0; i < t.size(); i++) {
            if (t.get(i).is("DEFUZZIFY")) {
                i = defuzzify(t, i, out);
            } else if (t.get(i).is("RULEBLOCK")) {
                i = ruleBlock(t, i, out);
            }
        }
        return out;
    }

    /** One DEFUZZIFY block from token {@code start}; returns the index of its last token. */
    private static int defuzzify(List<Token> t, int start, List<Giveaway> out) {
        boolean method = false;
        boolean dflt = false;
        boolean range = false;
        boolean implied = false;
        boolean disordered = false;
        int i = start + 1;
        for (; i < t.size() && !t.get(i).is("END_DEFUZZIFY") && !t.get(i).is("END_FUNCTION_BLOCK")
                && !t.get(i).is("RULEBLOCK") && !t.get(i).is("FUZZIFY"); i++) {
            Token tok = t.get(i);
            if (tok.kind() != Kind.WORD) {
                continue;
            }
            disordered |= tok.is("TERM") && (method || dflt) || tok.is("METHOD") && dflt;
            method |= tok.is("METHOD");
            dflt |= tok.is("DEFAULT");
            range |= tok.is("RANGE");
            if (tok.is("TERM")) {
                implied |= notFallingToZero(t, i);
            }
        }
        int line = t.get(start).line();
        if (!method) {
            out.add(new Giveaway("no METHOD", line, 1));
        }
        if (!dflt) {
            out.add(new Giveaway("no DEFAULT", line, 1));
        }
        if (!range && implied) {
            out.add(new Giveaway("no RANGE over terms not falling to 0", line, 2));
        }
        if (disordered) {
            out.add(new Giveaway("DEFUZZIFY statements out of order", line, 1));
        }
        return i;
    }

    /** A term {@code TERM n := (x, y) ... (x, y)} whose first or last degree is not 0, or a Gaussian. */
    private static boolean notFallingToZero(List<Token> t, int term) {
        int i = term + 1;
        while (i < t.size() && t.get(i).kind() != Kind.ASSIGN && t.get(i).kind() != Kind.SEMI) {
            i++;
        }
        if (i + 1 >= t.size() || t.get(i).kind() != Kind.ASSIGN) {
            return false;
        }
        if (t.get(i + 1).is("gauss") || t.get(i + 1).is("gauss2")) {
            return true;
        }
        String first = null;
        String last = null;
        for (int j = i + 1; j + 4 < t.size() && t.get(j).kind() == Kind.LPAREN; j += 5) {
            if (t.get(j + 2).kind() != Kind.COMMA || t.get(j + 4).kind() != Kind.RPAREN) {
                return false;
            }
            last = t.get(j + 3).text();
            first = first == null ? last : first;
        }
        return first != null && (!zero(first) || !zero(last));
    }

    private static boolean zero(String number) {
        try {
            return Double.parseDouble(number) == 0;
        } catch (NumberFormatException e) {
            return true;        // a variable's name: no sign either way
        }
    }

    /** One RULEBLOCK: AND/OR after ACT or ACCU, or ACT after ACCU, which jFuzzyLogic's grammar takes. */
    private static int ruleBlock(List<Token> t, int start, List<Giveaway> out) {
        boolean act = false;
        boolean accu = false;
        boolean disordered = false;
        int i = start + 1;
        for (; i < t.size() && !t.get(i).is("END_RULEBLOCK") && !t.get(i).is("END_FUNCTION_BLOCK")
                && !t.get(i).is("RULE"); i++) {
            Token tok = t.get(i);
            boolean setting = i + 1 < t.size() && t.get(i + 1).kind() == Kind.COLON;
            if (!setting) {
                continue;
            }
            disordered |= (tok.is("AND") || tok.is("OR")) && (act || accu) || tok.is("ACT") && accu;
            act |= tok.is("ACT");
            accu |= tok.is("ACCU");
        }
        if (disordered) {
            out.add(new Giveaway("RULEBLOCK settings out of order", t.get(start).line(), 1));
        }
        return i;
    }
}
