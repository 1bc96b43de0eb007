package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.antlr.v4.runtime.CommonToken;
import org.antlr.v4.runtime.Token;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.Literal;
import org.fclcert.model.Names;
import org.fclcert.model.Range;
import org.fclcert.model.SourceLocation;
import org.fclcert.syntax.FclLexer;
import org.fclcert.syntax.ReaderOptions;

/**
 * The token-level part of the FFLL reader: the constructs FFLL writes differently from the standard at the
 * level of single words, turned into the strict tokens that mean the same, each recorded as an Open Level
 * feature where it was written; and the facts the model pass needs that the strict model does not keep
 * (ranges written in comments, how METHOD was spelled). One instance per read (it keeps state).
 *
 * <ul>
 *   <li>{@code ACCUM:} becomes {@code ACCU:} (O-ACCUM);</li>
 *   <li>{@code name REAL;} gets its missing ':' (O-DECLARATION-WITHOUT-COLON);</li>
 *   <li>{@code VAR_INPUT RETAIN} / {@code NON_RETAIN}: the qualifier is dropped (O-VAR-RETAIN);</li>
 *   <li>{@code (* RANGE(lo .. hi) *)} in a declaration is kept as that variable's range (O-RANGE-COMMENT);
 *       a declaration without one gets FCL-D118 (FFLL does not load it);</li>
 *   <li>END_FUZZIFY closing a DEFUZZIFY is recorded (O-END-FUZZIFY; the builder accepts it);</li>
 *   <li>{@code FUNCTION_BLOCK} without a name gets the name {@code function_block} (O-UNNAMED-BLOCK), and
 *       {@code : =} becomes {@code :=} (O-SPACED-ASSIGN), as FFLL's API sample writes them;</li>
 *   <li>a subconclusion in parentheses, {@code THEN (valve IS open)} as FFLL's writer writes it, loses them
 *       (FCL-D121);</li>
 *   <li>an empty statement in a RULEBLOCK ({@code ;} after a comment), as FFLL's writer closes its
 *       {@code (* RULE n : No Rule Specified *)} lines, is dropped;</li>
 *   <li>{@code DEFUZZIFY x} naming no declared variable, in a block with one output, is read as that output's
 *       DEFUZZIFY: FFLL skips the name and defuzzifies its one output (its own sample files do this; FCL-D122).</li>
 * </ul>
 */
final class FfllTokens implements ReaderOptions.TokenFilter {
    private static final String NUMBER = "([+-]?[0-9]+(?:\\.[0-9]+)?(?:[eE][+-]?[0-9]+)?)";
    private static final Pattern RANGE_COMMENT = Pattern.compile(
            "\\(\\*\\s*RANGE\\s*\\(\\s*" + NUMBER + "\\s*\\.\\.\\s*" + NUMBER + "\\s*\\)\\s*\\*\\)",
            Pattern.CASE_INSENSITIVE);
    private static final Pattern RANGE_WORD = Pattern.compile("\\(\\*\\s*RANGE\\b", Pattern.CASE_INSENSITIVE);

    /** A range written in a declaration's comment. */
    record RangeComment(Range range, SourceLocation location) {
    }

    private final List<FeatureUse> features = new ArrayList<>();
    /** Per function block (in order), variable key to its range comment. */
    private final List<Map<String, RangeComment>> ranges = new ArrayList<>();
    /** METHOD words as written, by the location of their METHOD keyword ("line:col"). */
    private final Map<String, String> methodSpelling = new HashMap<>();

    private final List<FeatureUse> momMethods = new ArrayList<>();

    List<FeatureUse> features() {
        return features;
    }

    /** Where METHOD names MoM (for auto-detection; the model records the method itself). */
    List<FeatureUse> momMethods() {
        return momMethods;
    }

    Map<String, RangeComment> ranges(int functionBlock) {
        return functionBlock < ranges.size() ? ranges.get(functionBlock) : Map.of();
    }

    String methodSpelling(SourceLocation methodKeyword) {
        return methodSpelling.get(methodKeyword.line() + ":" + methodKeyword.column());
    }

    private enum Decl { START, NAME, AFTER_COMMA, TYPE }

    /** One declaration line being read: its names and where its range comment is. */
    private static final class Declaration {
        final List<Token> names = new ArrayList<>();
        int semiLine = -1;
        boolean ranged;
    }

    @Override
    public List<Token> filter(List<Token> tokens, ReaderOptions.Report report) {
        List<Token> out = new ArrayList<>(tokens.size() + 8);
        boolean inVar = false;
        boolean inDefuzzify = false;
        boolean inOptions = false;
        Decl state = Decl.START;
        Declaration current = null;
        List<Declaration> section = new ArrayList<>();
        Map<String, RangeComment> fbRanges = new HashMap<>();
        boolean afterThen = false;
        boolean inRuleBlock = false;
        int previous = -1;
        java.util.Set<Integer> dropped = new java.util.HashSet<>();
        List<String> declared = new ArrayList<>();
        List<String> outputs = new ArrayList<>();
        boolean inOutputs = false;
        for (int i = 0; i < tokens.size(); i++) {
            Token t = tokens.get(i);
            int type = t.getType();
            if (t.getChannel() == Token.DEFAULT_CHANNEL) {
                int before = previous;
                previous = type;
                if (dropped.contains(i)) {
                    continue;
                }
                if (type == FclLexer.SEMI && before == FclLexer.SEMI && inRuleBlock) {
                    // FFLL's writer closes its '(* RULE n : No Rule Specified *)' lines with ';': an empty statement
                    continue;
                }
                if (type == FclLexer.RULEBLOCK) {
                    inRuleBlock = true;
                } else if (type == FclLexer.END_RULEBLOCK) {
                    inRuleBlock = false;
                }
                if (type == FclLexer.THEN) {
                    afterThen = true;
                } else if (type == FclLexer.SEMI || type == FclLexer.END_RULEBLOCK) {
                    afterThen = false;
                } else if (afterThen && type == FclLexer.LPAREN && (before == FclLexer.THEN || before == FclLexer.COMMA)) {
                    int close = closing(tokens, i);
                    if (close > 0) {
                        report.warning(t, DialectCode.FFLL_PARENTHESISED_SUBCONCLUSION, "a subconclusion in"
                                + " parentheses, as FFLL writes it; the standard writes none there (5.4); read without them");
                        dropped.add(close);
                        continue;
                    }
                }
            }
            if (inOptions) {
                inOptions = type != FclLexer.END_OPTIONS && type != FclLexer.END_OPTION
                        && type != FclLexer.END_FUNCTION_BLOCK;
                out.add(t);
                continue;
            }
            if (type == FclLexer.COMMENT) {
                if (inVar) {
                    rangeComment(t, current, section, fbRanges, report);
                }
                out.add(t);
                continue;
            }
            switch (type) {
                case FclLexer.FUNCTION_BLOCK -> {
                    declared = new ArrayList<>();
                    outputs = new ArrayList<>();
                    fbRanges = new HashMap<>();
                    ranges.add(fbRanges);
                    Token next = next(tokens, i);
                    if (next != null && next.getType() != FclLexer.IDENT && next.getType() != FclLexer.ANY) {
                        // FFLL's API sample: FUNCTION_BLOCK without a name; read as 'function_block'
                        features.add(new FeatureUse(Feature.O_UNNAMED_BLOCK, report.at(t)));
                        out.add(t);
                        CommonToken name = new CommonToken(t);
                        name.setType(FclLexer.IDENT);
                        name.setText("function_block");
                        out.add(name);
                        continue;
                    }
                }
                case FclLexer.COLON -> {
                    Token next = next(tokens, i);
                    if (next != null && next.getType() == FclLexer.EQUALS) {
                        // FFLL's API sample: TERM x : = (...), the ':=' with a blank inside
                        features.add(new FeatureUse(Feature.O_SPACED_ASSIGN, report.at(t)));
                        CommonToken assign = new CommonToken(t);
                        assign.setType(FclLexer.ASSIGN);
                        assign.setText(":=");
                        out.add(assign);
                        i = tokens.indexOf(next);
                        continue;
                    }
                }
                case FclLexer.OPTIONS, FclLexer.OPTION -> inOptions = true;
                case FclLexer.VAR_INPUT, FclLexer.VAR_OUTPUT, FclLexer.VAR -> {
                    inVar = true;
                    inOutputs = type == FclLexer.VAR_OUTPUT;
                    state = Decl.START;
                    current = null;
                    section = new ArrayList<>();
                    out.add(t);
                    Token next = next(tokens, i);
                    if (next != null && next.getType() == FclLexer.IDENT && isRetain(next.getText())) {
                        features.add(new FeatureUse(Feature.O_VAR_RETAIN, report.at(next)));
                        i = tokens.indexOf(next);   // drop the qualifier
                    }
                    continue;
                }
                case FclLexer.END_VAR -> {
                    inVar = false;
                    for (Declaration d : section) {
                        if (!d.ranged && !d.names.isEmpty()) {
                            Token at = d.names.get(0);
                            report.warning(at, DialectCode.FFLL_NO_RANGE_COMMENT, "'" + at.getText()
                                    + "' has no '(* RANGE(lo .. hi) *)' comment, without which FFLL does not load"
                                    + " the program; fclcert reads it as IEC 61131-7 does");
                        }
                    }
                }
                case FclLexer.DEFUZZIFY -> {
                    inDefuzzify = true;
                    Token name = next(tokens, i);
                    if (name != null && name.getType() == FclLexer.IDENT && outputs.size() == 1
                            && declared.stream().noneMatch(d -> Names.same(d, name.getText()))) {
                        report.warning(name, DialectCode.FFLL_DEFUZZIFY_NAME_IGNORED, "'" + name.getText() + "' is not a"
                                + " declared variable; FFLL skips the name after DEFUZZIFY and defuzzifies its one output,"
                                + " so this is read as DEFUZZIFY " + outputs.get(0));
                        out.add(t);
                        CommonToken renamed = new CommonToken(name);
                        renamed.setText(outputs.get(0));
                        out.add(renamed);
                        i = tokens.indexOf(name);
                        continue;
                    }
                }
                case FclLexer.END_DEFUZZIFY, FclLexer.FUZZIFY, FclLexer.RULEBLOCK, FclLexer.END_FUNCTION_BLOCK ->
                        inDefuzzify = false;
                case FclLexer.END_FUZZIFY -> {
                    if (inDefuzzify) {
                        features.add(new FeatureUse(Feature.O_END_FUZZIFY, report.at(t)));
                    }
                    inDefuzzify = false;
                }
                case FclLexer.METHOD -> {
                    Token colon = next(tokens, i);
                    Token word = colon == null ? null : next(tokens, tokens.indexOf(colon));
                    if (colon != null && colon.getType() == FclLexer.COLON && word != null) {
                        SourceLocation at = report.at(t);
                        methodSpelling.put(at.line() + ":" + at.column(), word.getText());
                        if (word.getText().equalsIgnoreCase("MoM")) {
                            momMethods.add(new FeatureUse(Feature.O_MOM, at));
                        }
                    }
                }
                case FclLexer.IDENT -> {
                    Token next = next(tokens, i);
                    if (!inVar && t.getText().equalsIgnoreCase("ACCUM") && next != null
                            && next.getType() == FclLexer.COLON) {
                        features.add(new FeatureUse(Feature.O_ACCUM, report.at(t)));
                        CommonToken accu = new CommonToken(t);
                        accu.setType(FclLexer.ACCU);
                        out.add(accu);
                        continue;
                    }
                }
                default -> {
                }
            }
            if (inVar && type != FclLexer.END_VAR) {
                switch (state) {
                    case START, AFTER_COMMA -> {
                        if (nameLike(t)) {
                            if (state == Decl.START) {
                                current = new Declaration();
                                section.add(current);
                            }
                            current.names.add(t);
                            declared.add(t.getText());
                            if (inOutputs) {
                                outputs.add(t.getText());
                            }
                            state = Decl.NAME;
                        }
                    }
                    case NAME -> {
                        if (type == FclLexer.COMMA) {
                            state = Decl.AFTER_COMMA;
                        } else if (type == FclLexer.COLON) {
                            state = Decl.TYPE;
                        } else if (nameLike(t)) {
                            features.add(new FeatureUse(Feature.O_DECLARATION_WITHOUT_COLON, report.at(t)));
                            CommonToken colon = new CommonToken(t);
                            colon.setType(FclLexer.COLON);
                            colon.setText(":");
                            out.add(colon);
                            state = Decl.TYPE;
                        } else {
                            state = Decl.TYPE;   // malformed: the strict parser reports it
                        }
                    }
                    case TYPE -> {
                        if (type == FclLexer.SEMI) {
                            current.semiLine = t.getLine();
                            state = Decl.START;
                        }
                    }
                    default -> {
                    }
                }
            }
            out.add(t);
        }
        return out;
    }

    private void rangeComment(Token comment, Declaration current, List<Declaration> section,
            Map<String, RangeComment> fbRanges, ReaderOptions.Report report) {
        String text = comment.getText();
        if (!RANGE_WORD.matcher(text).lookingAt()) {
            return;
        }
        Declaration owner = null;
        for (Declaration d : section) {
            if (d.semiLine == comment.getLine() || (d == current && d.semiLine < 0)) {
                owner = d;
            }
        }
        Matcher m = RANGE_COMMENT.matcher(text);
        if (!m.matches()) {
            if (owner != null) {
                owner.ranged = true;   // one message for one comment: no FCL-D118 on top
            }
            report.error(comment, DialectCode.FFLL_MALFORMED_RANGE_COMMENT, "this comment starts with RANGE"
                    + " but is not '(* RANGE(lo .. hi) *)' with two numbers: FFLL cannot read the variable's range");
            return;
        }
        if (owner == null || owner.ranged) {
            return;   // a RANGE comment on a line of its own belongs to no declaration: an ordinary comment
        }
        owner.ranged = true;
        SourceLocation at = report.at(comment);
        double lo = Double.parseDouble(m.group(1));
        double hi = Double.parseDouble(m.group(2));
        Range range = new Range(literal(m.group(1), lo, at), literal(m.group(2), hi, at), at);
        features.add(new FeatureUse(Feature.O_RANGE_COMMENT, at));
        for (Token name : owner.names) {
            fbRanges.putIfAbsent(Names.key(name.getText()), new RangeComment(range, at));
        }
    }

    private static Literal literal(String text, double value, SourceLocation at) {
        boolean integral = !text.contains(".") && !text.toUpperCase(Locale.ROOT).contains("E");
        return new Literal(value, integral, at);
    }

    private static boolean isRetain(String word) {
        return word.equalsIgnoreCase("RETAIN") || word.equalsIgnoreCase("NON_RETAIN");
    }

    private static boolean nameLike(Token t) {
        return t.getType() == FclLexer.IDENT || (t.getType() >= FclLexer.RANGE && t.getType() <= FclLexer.ULINT
                && Character.isLetter(t.getText().charAt(0)));
    }

    /** The index of the ')' closing the '(' at {@code open}, before the statement's ';'; -1 when there is none. */
    private static int closing(List<Token> tokens, int open) {
        int depth = 0;
        for (int j = open; j < tokens.size(); j++) {
            Token u = tokens.get(j);
            if (u.getChannel() != Token.DEFAULT_CHANNEL) {
                continue;
            }
            if (u.getType() == FclLexer.LPAREN) {
                depth++;
            } else if (u.getType() == FclLexer.RPAREN && --depth == 0) {
                return j;
            } else if (u.getType() == FclLexer.SEMI || u.getType() == FclLexer.END_RULEBLOCK) {
                return -1;
            }
        }
        return -1;
    }

    /** The next token on the default channel after index i, or null. */
    private static Token next(List<Token> tokens, int i) {
        for (int j = i + 1; j < tokens.size(); j++) {
            if (tokens.get(j).getChannel() == Token.DEFAULT_CHANNEL) {
                return tokens.get(j);
            }
        }
        return null;
    }
}
