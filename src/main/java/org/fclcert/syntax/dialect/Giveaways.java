package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;
import org.fclcert.syntax.dialect.DialectReader.Giveaway;

/**
 * The constructs that give the jFuzzyLogic or the fuzzylite dialect away, found on the tokens alone
 * (no parse, so any text works): for jFuzzyLogic its shape names, {@code /* *\/} comments, PROBOR,
 * COGF and a METHOD MM; for fuzzylite its capitalised shape names, {@code #} comments, hedges after
 * {@code is}, rules without {@code ;}, {@code ENABLED}, {@code LOCK}, {@code nan} / {@code inf},
 * COGSS and ACCU inside DEFUZZIFY. Comments written {@code //} are shared by both and count for neither.
 */
final class Giveaways {
    private static final Set<String> JFL_SHAPES = Set.of("trian", "trape", "gauss", "gauss2", "gbell", "sigm",
            "dsigm", "cosine", "singletons");
    private static final Set<String> FL_SHAPES = Set.of("Triangle", "Trapezoid", "Rectangle", "Ramp", "Gaussian",
            "GaussianProduct", "Bell", "Sigmoid", "SigmoidDifference", "SigmoidProduct", "Cosine", "SShape", "ZShape",
            "PiShape", "Discrete", "Constant", "Linear", "Spike", "Concave");
    private static final Set<String> HEDGES = Set.of("very", "somewhat", "extremely", "seldom", "any");

    private Giveaways() {
    }

    static List<Giveaway> find(String text, boolean fuzzylite) {
        List<Giveaway> out = new ArrayList<>();
        try {
            DialectLexer lexer = DialectLexer.lex(text == null ? "" : text, fuzzylite);
            for (DialectLexer.Comment c : lexer.comments) {
                if (fuzzylite && c.style().equals("#")) {
                    out.add(new Giveaway("'#' comment", c.line()));
                } else if (!fuzzylite && c.style().equals("/* */")) {
                    out.add(new Giveaway("'/* */' comment", c.line()));
                }
            }
            List<Token> t = lexer.tokens;
            boolean inDefuzzify = false;
            for (int i = 0; i < t.size(); i++) {
                Token tok = t.get(i);
                Token prev = i > 0 ? t.get(i - 1) : null;
                Token next = i + 1 < t.size() ? t.get(i + 1) : tok;
                boolean afterAssign = prev != null && prev.kind() == Kind.ASSIGN;
                boolean afterColon = prev != null && prev.kind() == Kind.COLON;
                if (tok.is("DEFUZZIFY")) {
                    inDefuzzify = true;
                } else if (tok.is("END_DEFUZZIFY")) {
                    inDefuzzify = false;
                }
                if (tok.kind() != Kind.WORD && tok.kind() != Kind.NUMBER) {
                    continue;
                }
                String w = tok.text();
                if (fuzzylite) {
                    if (afterAssign && FL_SHAPES.contains(w)) {
                        out.add(new Giveaway("shape '" + w + "'", tok.line()));
                    } else if (prev != null && prev.text().equals("is") && HEDGES.contains(w)) {
                        out.add(new Giveaway("hedge '" + w + "'", tok.line()));
                    } else if ((w.equals("ENABLED") || w.equals("LOCK")) && next.kind() == Kind.COLON) {
                        out.add(new Giveaway("'" + w + "'", tok.line()));
                    } else if (w.equals("nan") || w.endsWith("inf") && (tok.kind() == Kind.NUMBER || w.equals("inf"))) {
                        out.add(new Giveaway("'" + w + "'", tok.line()));
                    } else if (afterColon && w.equals("COGSS")) {
                        out.add(new Giveaway("METHOD COGSS", tok.line()));
                    } else if (inDefuzzify && w.equals("ACCU")) {
                        out.add(new Giveaway("ACCU inside DEFUZZIFY", tok.line()));
                    } else if (w.equals("RULE") && ruleWithoutSemicolon(t, i)) {
                        out.add(new Giveaway("rule without ';'", tok.line()));
                    }
                } else {
                    if (afterAssign && JFL_SHAPES.contains(w)) {
                        out.add(new Giveaway("shape '" + w + "'", tok.line()));
                    } else if (afterColon && (w.equalsIgnoreCase("PROBOR") || w.equalsIgnoreCase("COGF"))) {
                        out.add(new Giveaway("'" + w + "'", tok.line()));
                    } else if (afterColon && w.equalsIgnoreCase("MM") && i > 1 && t.get(i - 2).is("METHOD")) {
                        out.add(new Giveaway("METHOD MM", tok.line()));
                    }
                }
            }
        } catch (RuntimeException e) {
            // never throws: what was found so far is the answer
        }
        out.sort(Comparator.comparingInt(Giveaway::line));
        return List.copyOf(out);
    }

    /** A RULE whose line holds no ';' and whose next token is on a later line. */
    private static boolean ruleWithoutSemicolon(List<Token> t, int i) {
        int line = t.get(i).line();
        for (int j = i + 1; j < t.size(); j++) {
            Token x = t.get(j);
            if (x.line() != line || x.kind() == Kind.EOF) {
                // the rule really ends with its line only when the next line starts the next rule or ends the
                // block; a standard rule continued on the next line ('AND ...', 'THEN ...') is no giveaway
                return j > i + 1 && (x.kind() == Kind.EOF || x.is("RULE") || x.is("END_RULEBLOCK"));
            }
            if (x.kind() == Kind.SEMI) {
                return false;
            }
        }
        return false;
    }
}
