package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Condition;
import org.fclcert.model.Feature;
import org.fclcert.model.Hedge;
import org.fclcert.model.Operand;
import org.fclcert.model.Rule;
import org.fclcert.model.Subconclusion;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;

/**
 * The rules of a library dialect ({@code RULE n : IF condition THEN conclusion [WITH w];}), read for the
 * {@link DialectParser}: conditions with the standard's priorities, hedges and conclusion separators as
 * the {@link LibraryDialect} says; a dialect that reads a rule from one line ends it with its line.
 */
final class DialectRuleParser {
    private final DialectParser p;
    private final LibraryDialect dialect;
    /** For one-line dialects: the line the current rule is on; tokens on later lines end it. 0 outside rules. */
    private int ruleLine;
    /** Rules of the current block labelled by a number that is no rule number of the standard, with the label. */
    private final java.util.Map<Rule, Token> oddLabels = new java.util.IdentityHashMap<>();

    DialectRuleParser(DialectParser parser) {
        this.p = parser;
        this.dialect = parser.dialect;
    }

    /** The next token of the current rule, or null when a one-line rule's line has ended. */
    private Token ruleToken() {
        Token t = p.peek();
        return dialect.oneLineStatements() && ruleLine > 0 && t.line() != ruleLine ? null : t;
    }

    private boolean ruleWord(String word) {
        Token t = ruleToken();
        if (t == null || !t.is(word)) {
            return false;
        }
        if (dialect.lowerCaseRuleKeywords() && !t.text().equals(dialect.ruleKeyword(word))) {
            p.error(t, DialectCode.NOT_IN_DIALECT, p.library + " silently drops a rule that writes '" + t.text()
                    + "': its rule keywords are lower case ('" + dialect.ruleKeyword(word) + "')");
        }
        return true;
    }

    private Token ruleExpectWord(String word) {
        if (!ruleWord(word)) {
            throw ruleFail("'" + dialect.ruleKeyword(word) + "'");
        }
        return p.next();
    }

    private DialectParser.Skip ruleFail(String expected) {
        Token t = ruleToken();
        if (t == null) {
            p.error(p.peek(), DialectCode.STATEMENT_SPANS_LINES, p.library + " reads a rule from one line; expected "
                    + expected + " before the end of line " + ruleLine);
            return new DialectParser.Skip();
        }
        return p.fail(t, expected);
    }

    Rule rule() {
        Token kw = p.next();
        ruleLine = kw.line();
        try {
            Token n = ruleToken();
            String ruleName;
            Token oddLabel = null;
            if (n != null && n.kind() == Kind.NUMBER) {
                p.next();
                ruleName = n.text().replaceFirst("^[+]?0*(?=\\d)", "");
                oddLabel = ruleName.matches("\\d+") ? null : n;
            } else if (n != null && n.kind() == Kind.WORD) {
                ruleName = p.next().text();
            } else {
                throw ruleFail("a rule number or name");
            }
            Token colon = ruleToken();
            if (colon == null || colon.kind() != Kind.COLON) {
                throw ruleFail("':'");
            }
            p.next();
            ruleExpectWord("IF");
            Condition condition = orCondition(0);
            ruleExpectWord("THEN");
            List<Subconclusion> conclusion = conclusion();
            Token end = ruleToken();
            if (end != null && end.kind() == Kind.SEMI) {
                p.next();
            } else if (dialect.oneLineStatements() && end == null) {
                p.feature(Feature.O_RULE_WITHOUT_SEMICOLON, p.at(kw));
            } else if (end == null || end.kind() == Kind.EOF) {
                throw p.fail(p.peek(), "';' at the end of the rule");
            } else {
                throw p.fail(end, "';' at the end of the rule");
            }
            Rule rule = new Rule(ruleName, condition, conclusion, p.at(kw));
            if (oddLabel != null) {
                oddLabels.put(rule, oddLabel);
            }
            return rule;
        } finally {
            ruleLine = 0;
        }
    }

    /**
     * The block's rules, those labelled by a number other than an unsigned integer ({@code RULE 1.5},
     * {@code 1.0E2}, {@code -3}, {@code 1e309}) given the smallest rule number no other rule of the block uses.
     * jFuzzyLogic's grammar takes any of its numbers as a rule's label and keeps it as text, fuzzylite skips the
     * label: to both it only names the rule, so renumbering changes no meaning, and the standard's rule number
     * (5.4) is what fmt and convert can write.
     */
    List<Rule> relabelled(List<Rule> rules) {
        if (oddLabels.isEmpty()) {
            return rules;
        }
        java.util.Set<java.math.BigInteger> used = new java.util.HashSet<>();
        for (Rule r : rules) {
            if (!oddLabels.containsKey(r) && r.name().matches("\\d+")) {
                used.add(new java.math.BigInteger(r.name()));
            }
        }
        List<Rule> out = new ArrayList<>(rules.size());
        java.math.BigInteger next = java.math.BigInteger.ONE;
        for (Rule r : rules) {
            Token label = oddLabels.get(r);
            if (label == null) {
                out.add(r);
                continue;
            }
            while (used.contains(next)) {
                next = next.add(java.math.BigInteger.ONE);
            }
            used.add(next);
            p.warn(p.at(label), DialectCode.TOLERATED, p.library + " takes any number as a rule's label ('RULE "
                    + label.text() + "'), where the standard numbers rules with unsigned integers (5.4); the label"
                    + " only names the rule: read as RULE " + next);
            out.add(new Rule(next.toString(), r.condition(), r.conclusion(), r.location()));
        }
        oddLabels.clear();
        return out;
    }

    private Condition orCondition(int depth) {
        Token first = ruleToken();
        List<Condition> operands = new ArrayList<>();
        operands.add(andCondition(depth));
        while (ruleWord("OR")) {
            p.next();
            Token at = ruleToken();
            Condition operand = andCondition(depth);
            if (dialect.oneAndOrPriority() && operand instanceof Condition.And && at != null) {
                p.warn(p.at(at), DialectCode.AND_OR_PRIORITY, p.library + " reads '... OR " + at.text()
                        + " AND ...' as '(... OR ...) AND ...' (one priority, left to right); fclcert binds AND"
                        + " tighter (Table 6)");
            }
            operands.add(operand);
        }
        return operands.size() == 1 ? operands.get(0) : new Condition.Or(operands, p.at(first));
    }

    private Condition andCondition(int depth) {
        Token first = ruleToken();
        List<Condition> operands = new ArrayList<>();
        operands.add(factor(depth));
        while (ruleWord("AND")) {
            p.next();
            operands.add(factor(depth));
        }
        return operands.size() == 1 ? operands.get(0) : new Condition.And(operands, p.at(first));
    }

    private Condition factor(int depth) {
        Token t = ruleToken();
        if (t == null) {
            throw ruleFail("a condition");
        }
        if (depth > DialectParser.MAX_NESTING) {
            p.error(t, DialectCode.UNSUPPORTED, "parentheses nested deeper than " + DialectParser.MAX_NESTING);
            throw new DialectParser.Skip();
        }
        if (dialect.notOperator() && t.is("NOT")) {
            p.next();
            Condition inner = factor(depth + 1);
            return new Condition.Not(inner, p.at(t));
        }
        if (t.kind() == Kind.LPAREN) {
            p.next();
            Condition inner = orCondition(depth + 1);
            Token close = ruleToken();
            if (close == null || close.kind() != Kind.RPAREN) {
                throw ruleFail("')'");
            }
            p.next();
            return new Condition.Parenthesized(inner, p.at(t));
        }
        if (t.kind() != Kind.WORD) {
            throw ruleFail("a subcondition 'variable IS term'");
        }
        String variable = p.next().text();
        if (!ruleWord("IS")) {
            p.error(t, DialectCode.NOT_IN_DIALECT, p.library + " does not take a bare variable as a condition;"
                    + " write 'variable " + dialect.ruleKeyword("IS") + " term'");
            throw new DialectParser.Skip();
        }
        p.next();
        List<Hedge> hedges = new ArrayList<>();
        boolean negated = false;
        while (true) {
            Token h = ruleToken();
            if (h == null || h.kind() != Kind.WORD) {
                throw ruleFail("a term");
            }
            Optional<Hedge> hedge = dialect.hedge(h);
            if (hedge.isEmpty()) {
                break;
            }
            p.next();
            if (hedge.get() == Hedge.NOT && hedges.isEmpty() && !negated) {
                negated = true;             // the standard's IS NOT
            } else {
                hedges.add(hedge.get());
            }
            if (hedge.get() == Hedge.ANY) {
                if (negated || hedges.size() > 1) {
                    p.error(h, DialectCode.UNSUPPORTED, "fclcert reads 'any' only alone ('" + variable + " is any')");
                    throw new DialectParser.Skip();
                }
                return new Condition.TermSubcondition(variable, "", false, hedges, p.at(t));
            }
        }
        String term = p.next().text();
        return new Condition.TermSubcondition(variable, term, negated, hedges, p.at(t));
    }

    private List<Subconclusion> conclusion() {
        List<Token> starts = new ArrayList<>();
        List<String[]> parts = new ArrayList<>();
        List<List<Hedge>> hedgesOf = new ArrayList<>();
        List<Hedge> cumulative = new ArrayList<>();
        while (true) {
            Token v = ruleToken();
            if (v == null || v.kind() != Kind.WORD) {
                throw ruleFail("a subconclusion 'variable IS term'");
            }
            p.next();
            if (!ruleWord("IS")) {
                p.error(v, DialectCode.NOT_IN_DIALECT, p.library + " does not take a bare variable as a conclusion;"
                        + " write 'variable " + dialect.ruleKeyword("IS") + " term'");
                throw new DialectParser.Skip();
            }
            p.next();
            Token term = ruleToken();
            if (term == null || term.kind() != Kind.WORD) {
                throw ruleFail("a term");
            }
            List<Hedge> written = new ArrayList<>();
            while (dialect.hedge(term).isPresent() && ruleTokenAfter(term)) {
                if (!dialect.hedgesInConclusions()) {
                    p.error(term, DialectCode.UNSUPPORTED, "a hedge in a conclusion ('" + term.text() + "'): "
                            + p.library + " does not read it");
                    throw new DialectParser.Skip();
                }
                written.add(dialect.hedge(term).get());
                p.feature(Feature.O_HEDGE_IN_CONCLUSION, p.at(term));
                p.next();
                term = ruleToken();
                if (term == null || term.kind() != Kind.WORD) {
                    throw ruleFail("a term");
                }
            }
            // fuzzylite applies a conclusion's hedges to the rule's degree itself, so they also hold for every
            // later subconclusion of the rule; applyAll takes the list nearest-the-term first, hence the prepend
            cumulative.addAll(0, written);
            hedgesOf.add(List.copyOf(cumulative));
            p.next();
            starts.add(v);
            parts.add(new String[] {v.text(), term.text()});
            Token sep = ruleToken();
            if (sep != null && dialect.conclusionSeparator(p, sep)) {
                p.next();
            } else {
                break;
            }
        }
        Optional<Operand> weight = Optional.empty();
        if (ruleWord("WITH")) {
            p.next();
            Token w = ruleToken();
            if (w == null || w.kind() != Kind.NUMBER) {
                if (w != null && w.kind() == Kind.WORD) {
                    p.error(w, DialectCode.NOT_IN_DIALECT, p.library + " takes a number after WITH, not a variable");
                    throw new DialectParser.Skip();
                }
                throw ruleFail("a weight");
            }
            weight = Optional.of(p.number(false));
        }
        // the library weighs the whole rule: every subconclusion carries the weight
        List<Subconclusion> out = new ArrayList<>();
        for (int i = 0; i < parts.size(); i++) {
            out.add(new Subconclusion(parts.get(i)[0], Optional.of(parts.get(i)[1]), weight, hedgesOf.get(i),
                    p.at(starts.get(i))));
        }
        return out;
    }

    /** Whether a word follows {@code t} in the rule (so {@code t} is a hedge, not a term named like one). */
    private boolean ruleTokenAfter(Token t) {
        Token after = p.peek(1);
        return after.kind() == Kind.WORD && (!dialect.oneLineStatements() || after.line() == t.line())
                && !after.is("and") && !after.is("with") && !after.is("END_RULEBLOCK") && !after.is("RULE");
    }
}
