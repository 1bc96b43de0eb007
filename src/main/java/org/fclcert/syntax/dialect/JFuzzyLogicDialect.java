package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Hedge;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Range;
import org.fclcert.model.ShapeKind;
import org.fclcert.model.Term;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;
import org.fclcert.syntax.dialect.DialectReader.Giveaway;

/**
 * jFuzzyLogic's dialect: the standard's grammar plus {@code //} and {@code /* *\/} comments, RANGE in
 * FUZZIFY and after a declaration, named shapes in any case ({@link ShapeNames#JFUZZYLOGIC}), {@code function}
 * output terms (Takagi–Sugeno), ACCU PROBOR and SUM, METHOD COGF and MM, and what it supplies when a setting
 * is left out: ACCU SUM, METHOD CoG, DEFAULT NC and, for an output without RANGE, the universe its terms span
 * (points: first to last x; Gaussian mean ± 4 sd). Where it gives a program another meaning (coupled AND/OR,
 * one priority for AND and OR, case-sensitive names, NSUM as BSUM) the reader warns.
 */
final class JFuzzyLogicDialect extends LibraryDialect {
    private static final DialectLexer.Style STYLE = new DialectLexer.Style(false, true, false, "jFuzzyLogic");

    @Override
    Dialect dialect() {
        return Dialect.JFUZZYLOGIC;
    }

    @Override
    DialectLexer.Style lexing() {
        return STYLE;
    }

    @Override
    ShapeNames.Table shapes() {
        return ShapeNames.JFUZZYLOGIC;
    }

    @Override
    void checkName(DialectParser p, Token t) {
        if (t.text().startsWith("_")) {
            p.error(t, DialectCode.NOT_IN_DIALECT, "jFuzzyLogic rejects names starting with '_'");
        }
    }

    @Override
    boolean firstOfRepeatedTerms() {
        return false;
    }

    @Override
    boolean variablesAsPoints() {
        return true;
    }

    /**
     * jFuzzyLogic finds a variable named in a point only once a FUZZIFY or DEFUZZIFY block of it has been read:
     * its VAR sections create no variables (a defect of the build, a dangling else), so it fails to load such a
     * program ("Cannot find variable"). A located error, with the fix.
     */
    @Override
    void pointVariable(DialectParser p, Token name) {
        if (!DialectTermParser.blockRead(p, name.text())) {
            p.error(name, DialectCode.NOT_IN_DIALECT, "jFuzzyLogic cannot load this: it finds '" + name.text() + "' in a"
                    + " point only once a FUZZIFY or DEFUZZIFY block of it has been read (its VAR sections create no"
                    + " variables); add 'FUZZIFY " + name.text() + " ... END_FUZZIFY' before this block");
        }
    }

    @Override
    boolean rangeInFuzzify() {
        // measured: the jFuzzyLogic jar refuses it before or after the terms ("mismatched input 'RANGE' expecting
        // END_FUZZIFY"); an input's RANGE goes after its declaration in VAR_INPUT
        return false;
    }

    @Override
    boolean rangeAfterDeclaration() {
        return true;
    }

    @Override
    boolean defuzzifyStatement(DialectParser p, Token t, DialectParser.Output out) {
        if (!t.is("ACCU")) {
            return false;
        }
        p.accumulation();
        p.error(t, DialectCode.NOT_IN_DIALECT, "jFuzzyLogic takes ACCU in the RULEBLOCK");
        return true;
    }

    @Override
    String defuzzifyStatements() {
        return "TERM, RANGE, METHOD, DEFAULT or END_DEFUZZIFY";
    }

    @Override
    Optional<DefuzzificationMethod> method(DialectParser p, Token w, String upper) {
        return Optional.ofNullable(switch (upper) {
            case "COG" -> DefuzzificationMethod.COG;
            case "COGS" -> DefuzzificationMethod.COGS;
            case "COA" -> DefuzzificationMethod.COA;
            case "LM" -> DefuzzificationMethod.LM;
            case "RM" -> DefuzzificationMethod.RM;
            case "MM" -> {
                p.feature(Feature.O_METHOD_MM, p.at(w));
                yield DefuzzificationMethod.MOM;
            }
            case "COGF" -> {
                p.feature(Feature.O_METHOD_COGF, p.at(w));
                yield DefuzzificationMethod.COG;
            }
            default -> null;
        });
    }

    @Override
    String methodNames() {
        return "COG, COGF, COGS, COA, LM, RM, MM";
    }

    @Override
    Optional<AccumulationMethod> accumulation(String upper) {
        return Optional.ofNullable(switch (upper) {
            case "MAX" -> AccumulationMethod.MAX;
            case "BSUM" -> AccumulationMethod.BSUM;
            case "NSUM" -> AccumulationMethod.NSUM;
            case "SUM" -> AccumulationMethod.SUM;
            case "PROBOR" -> AccumulationMethod.PROBOR;
            default -> null;
        });
    }

    @Override
    String accumulationNames() {
        return "MAX, BSUM, NSUM, PROBOR, SUM";
    }

    @Override
    String orAlgorithm(String upper) {
        // its grammar's OR: MAX, ASUM, BSUM, DMAX, NIPMAX, EINSTEIN (PROBOR is an ACCU, HAMACHER an AND there)
        return switch (upper) {
            case "DMAX" -> "DSUM";
            case "NIPMAX" -> "NMAX";
            case "EINSTEIN" -> "ESUM";
            case "PROBOR", "HAMACHER", "ESUM", "HSUM", "DSUM", "NMAX" -> "not " + upper;
            default -> upper;
        };
    }

    @Override
    String andAlgorithm(String upper) {
        // its grammar's AND: MIN, PROD, BDIF, DMIN, NIPMIN, HAMACHER (EINSTEIN is an OR there)
        return switch (upper) {
            case "DMIN" -> "DPROD";
            case "NIPMIN" -> "NMIN";
            case "HAMACHER" -> "HPROD";
            case "EINSTEIN", "EPROD", "HPROD", "DPROD", "NMIN" -> "not " + upper;
            default -> upper;
        };
    }

    @Override
    String andNames() {
        return "MIN, PROD, BDIF, DMIN, NIPMIN, HAMACHER";
    }

    @Override
    String orNames() {
        return "MAX, ASUM, BSUM, DMAX, NIPMAX, EINSTEIN";
    }

    @Override
    Optional<MembershipFunction> specialTerm(DialectParser p, Token t, DialectParser.TermContext where) {
        if (t.is("singletons")) {
            List<Point> pts = p.points();
            if (pts.size() != 1 || !(pts.get(0).degree() instanceof Literal d) || d.value() != 1) {
                p.error(t, DialectCode.UNSUPPORTED, "fclcert reads 'singletons' only as one singleton (x, 1);"
                        + " jFuzzyLogic's several (x, y) pairs are a discrete set fclcert does not evaluate");
                throw new DialectParser.Skip();
            }
            p.feature(Feature.O_SHAPE_SINGLETONS, p.at(t));
            return Optional.of(new MembershipFunction.Singleton(pts.get(0).x()));
        }
        if (t.is("singleton")) {
            return Optional.of(new MembershipFunction.Singleton(p.number(false)));
        }
        if (t.is("function") && p.peek().kind() == Kind.EXPRESSION) {
            return Optional.of(FuzzyliteDialect.computed(p, t, p.next(), where, "function"));
        }
        return Optional.empty();
    }

    @Override
    Optional<Hedge> hedge(Token t) {
        return t.is("NOT") ? Optional.of(Hedge.NOT) : Optional.empty();
    }

    @Override
    boolean notOperator() {
        return true;
    }

    @Override
    boolean conclusionSeparator(DialectParser p, Token t) {
        return t.kind() == Kind.COMMA;
    }

    @Override
    boolean oneAndOrPriority() {
        return true;
    }

    @Override
    void finishOutput(DialectParser p, DialectParser.Output out) {
        if (out.method.isEmpty()) {
            p.warn(out.start, DialectCode.SUPPLIED_SETTING, "no METHOD: jFuzzyLogic uses CoG, and so does fclcert");
            p.feature(Feature.O_IMPLICIT_SETTING, out.start);
            out.method = Optional.of(new Located<>(DefuzzificationMethod.COG, out.start));
        }
        if (out.defaultValue.isEmpty()) {
            p.warn(out.start, DialectCode.SUPPLIED_SETTING,
                    "no DEFAULT: jFuzzyLogic keeps the previous value when no rule fires; read as DEFAULT NC");
            p.feature(Feature.O_IMPLICIT_SETTING, out.start);
            out.defaultValue = Optional.of(new DefaultValue.NoChange(out.start));
        }
        if (out.range.isEmpty()) {
            Range declared = p.declaredRanges.get(Names.key(out.variable));
            out.range = declared != null ? Optional.of(declared) : impliedUniverse(p, out);
        }
    }

    /**
     * jFuzzyLogic's universe of an output without RANGE: from the least to the greatest x its terms reach
     * (a Gaussian reaching mean ± 4 sd), over which it defuzzifies. Needed only when a term does not fall to 0
     * at both ends of its points or is a smooth shape; empty otherwise (then the range changes nothing).
     */
    private static Optional<Range> impliedUniverse(DialectParser p, DialectParser.Output out) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        boolean needed = false;
        for (Term t : out.terms) {
            List<Point> pts = null;
            if (t.function() instanceof MembershipFunction.Points points) {
                pts = points.points();
            } else if (t.function() instanceof MembershipFunction.NamedShape shape) {
                Optional<List<Point>> exact = shape.points();
                if (exact.isPresent()) {
                    pts = exact.get();
                } else if (shape.parameters().size() == shape.kind().arity()
                        && (shape.kind() == ShapeKind.GAUSSIAN || shape.kind() == ShapeKind.GAUSSIAN_PRODUCT)) {
                    double[] v = shape.values();
                    double last = shape.kind() == ShapeKind.GAUSSIAN ? v[0] + 4 * v[1] : v[2] + 4 * v[3];
                    lo = Math.min(lo, v[0] - 4 * v[1]);
                    hi = Math.max(hi, last);
                    needed = true;
                    continue;
                } else {
                    return Optional.empty();       // FCL-C025 then asks for a RANGE
                }
            } else {
                return Optional.empty();           // singletons need no universe
            }
            if (pts.isEmpty() || !pts.stream().allMatch(pt -> pt.x() instanceof Literal && pt.degree() instanceof Literal)) {
                return Optional.empty();
            }
            for (Point pt : pts) {
                lo = Math.min(lo, ((Literal) pt.x()).value());
                hi = Math.max(hi, ((Literal) pt.x()).value());
            }
            needed |= ((Literal) pts.get(0).degree()).value() != 0 || ((Literal) pts.get(pts.size() - 1).degree()).value() != 0;
        }
        if (!needed || !(lo < hi)) {
            return Optional.empty();
        }
        p.feature(Feature.O_IMPLIED_RANGE, out.start);
        p.warn(out.start, DialectCode.IMPLIED_RANGE, "no RANGE: jFuzzyLogic defuzzifies '" + out.variable
                + "' over the span of its terms, [" + num(lo) + ", " + num(hi) + "]; the standard needs a RANGE"
                + " here (read as RANGE := (" + num(lo) + " .. " + num(hi) + "))");
        return Optional.of(new Range(Literal.of(lo), Literal.of(hi), out.start));
    }

    private static String num(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v) : String.valueOf(v);
    }

    /** jFuzzyLogic's De Morgan partner of an AND or OR: its HAMACHER goes with EINSTEIN, else Table 3's pairs. */
    private static OrAlgorithm partner(AndAlgorithm and) {
        return and == AndAlgorithm.HPROD ? OrAlgorithm.ESUM : and.pair();
    }

    private static AndAlgorithm partner(OrAlgorithm or) {
        return or == OrAlgorithm.ESUM ? AndAlgorithm.HPROD : or.pair();
    }

    @Override
    void finishRuleBlock(DialectParser p, DialectParser.Block b) {
        // jFuzzyLogic couples HAMACHER (AND) with EINSTEIN (OR), not with the Hamacher sum: say the partner
        if (b.and.isPresent() != b.or.isPresent()) {
            if (b.and.isPresent() && b.and.get().value() == AndAlgorithm.HPROD) {
                b.or = Optional.of(new Located<>(OrAlgorithm.ESUM, b.and.get().location()));
                p.feature(Feature.O_UNPAIRED_OPERATORS, b.start);
            } else if (b.or.isPresent() && b.or.get().value() == OrAlgorithm.ESUM) {
                b.and = Optional.of(new Located<>(AndAlgorithm.HPROD, b.or.get().location()));
                p.feature(Feature.O_UNPAIRED_OPERATORS, b.start);
            }
        } else if (b.and.isPresent() && b.and.get().value() == AndAlgorithm.HPROD && b.or.get().value() == OrAlgorithm.ESUM) {
            p.feature(Feature.O_UNPAIRED_OPERATORS, b.start);
        }
        if (b.and.isPresent() && b.or.isPresent() && partner(b.and.get().value()) != b.or.get().value()) {
            boolean orLast = "OR".equals(b.lastOperator);
            var later = orLast ? b.or.get().location() : b.and.get().location();
            String effective = orLast ? "AND as " + partner(b.or.get().value()) : "OR as " + partner(b.and.get().value());
            p.warn(later, DialectCode.COUPLED_AND_OR, "jFuzzyLogic couples AND and OR: the later declaration"
                    + " makes it evaluate " + effective + "; fclcert reads AND " + b.and.get().value() + " and OR "
                    + b.or.get().value() + " as written");
        }
        if (b.and.isEmpty() && b.or.isEmpty() && b.rules.stream().anyMatch(r -> andOr(r.condition()))) {
            p.warn(b.start, DialectCode.SUPPLIED_SETTING, "no AND or OR: jFuzzyLogic connects subconditions by MIN"
                    + " and MAX; read as AND : MIN (and its pair OR : MAX)");
            p.feature(Feature.O_IMPLICIT_SETTING, b.start);
            b.and = Optional.of(new Located<>(AndAlgorithm.MIN, b.start));
        }
        if (b.accu.isEmpty()) {
            p.warn(b.start, DialectCode.SUPPLIED_SETTING, "no ACCU: jFuzzyLogic accumulates by a plain sum; read as ACCU SUM");
            p.feature(Feature.O_IMPLICIT_SETTING, b.start);
            b.accu = Optional.of(new Located<>(AccumulationMethod.SUM, b.start));
        }
    }

    @Override
    FunctionBlock finishFunctionBlock(DialectParser p, FunctionBlock fb) {
        CaseSensitivity.warn(fb, p::warn);
        outputConditions(p, fb);
        return fb;
    }

    /**
     * 'output IS term' in a condition: jFuzzyLogic sets every output to its DEFAULT before its rule blocks run
     * (with DEFAULT NC it keeps its last value), so the condition reads that value, never what other rules conclude
     * in this evaluation: rule blocks do not chain. Read so (O-OUTPUT-VALUE-CONDITION), with FCL-W313.
     */
    private static void outputConditions(DialectParser p, FunctionBlock fb) {
        for (org.fclcert.model.RuleBlock rb : fb.ruleBlocks()) {
            for (org.fclcert.model.Rule r : rb.rules()) {
                outputConditions(p, fb, r.condition());
            }
        }
    }

    private static void outputConditions(DialectParser p, FunctionBlock fb, Condition c) {
        if (c instanceof Condition.TermSubcondition t) {
            // a term the output does not have is left to the checks (FCL-C027)
            fb.defuzzification(t.variable()).filter(d -> d.terms().stream().anyMatch(x -> Names.same(x.name(), t.term())))
                    .ifPresent(d -> {
                p.feature(Feature.O_OUTPUT_VALUE_CONDITION, t.location());
                String start = d.defaultValue().filter(v -> v instanceof DefaultValue.Constant)
                        .map(v -> "its DEFAULT " + num(((DefaultValue.Constant) v).value().value()))
                        .orElse("the value of the last evaluation (DEFAULT NC)");
                p.warn(t.location(), DialectCode.OUTPUT_AT_START, "'" + t.variable() + " IS " + t.term() + "':"
                        + " jFuzzyLogic reads output '" + t.variable() + "' at its value when the evaluation begins, "
                        + start + ", not at what its rules conclude in this evaluation; read so (the standard reads"
                        + " only inputs in conditions, 5.2.4)");
            });
        } else if (c instanceof Condition.And a) {
            a.operands().forEach(x -> outputConditions(p, fb, x));
        } else if (c instanceof Condition.Or o) {
            o.operands().forEach(x -> outputConditions(p, fb, x));
        } else if (c instanceof Condition.Not n) {
            outputConditions(p, fb, n.operand());
        } else if (c instanceof Condition.Parenthesized q) {
            outputConditions(p, fb, q.inner());
        }
    }

    /**
     * jFuzzyLogic's giveaways: its shape names after ':=' (any case, weight 3), {@code /* *\/} comments (2),
     * ACCU PROBOR and METHOD COGF (3), METHOD MM (1: fuzzylite writes it too), a RANGE after a declaration (3),
     * {@code //} comments (1, once: fuzzylite's exporter writes one too, beside its many own giveaways; a text in
     * standard FCL but for its {@code //} comments is what jFuzzyLogic's users write), a FUNCTION_BLOCK without a
     * name (1); and the habits in a block's shape, {@link JFuzzyLogicHabits}.
     */
    @Override
    List<Giveaway> giveaways(Giveaways.Scan scan) {
        List<Giveaway> out = new ArrayList<>();
        scan.comments("/* */").forEach(line -> out.add(new Giveaway("'/* */' comment", line, 2)));
        scan.comments("//").stream().findFirst().ifPresent(line -> out.add(new Giveaway("'//' comment", line, 1)));
        List<Token> t = scan.tokens();
        out.addAll(JFuzzyLogicHabits.of(t));
        for (int i = 0; i < t.size(); i++) {
            Token tok = t.get(i);
            Token prev = i > 0 ? t.get(i - 1) : null;
            if (tok.kind() != Kind.WORD) {
                continue;
            }
            String w = tok.text();
            boolean afterAssign = prev != null && prev.kind() == Kind.ASSIGN;
            boolean afterColon = prev != null && prev.kind() == Kind.COLON;
            if (w.equalsIgnoreCase("FUNCTION_BLOCK") && i + 1 < t.size() && unnamedBlockFollows(t.get(i + 1))) {
                out.add(new Giveaway("FUNCTION_BLOCK without a name", tok.line(), 1));
            } else if (afterAssign && shapes().kind(w).isPresent() || afterAssign && w.equalsIgnoreCase("singletons")) {
                out.add(new Giveaway("shape '" + w + "'", tok.line(), 3));
            } else if (afterColon && (w.equalsIgnoreCase("PROBOR") || w.equalsIgnoreCase("COGF"))) {
                out.add(new Giveaway("'" + w + "'", tok.line(), 3));
            } else if (afterColon && w.equalsIgnoreCase("MM") && i > 1 && t.get(i - 2).is("METHOD")) {
                out.add(new Giveaway("METHOD MM", tok.line(), 1));
            } else if (w.equalsIgnoreCase("RANGE") && scan.inVarSection(i)) {
                out.add(new Giveaway("RANGE in a VAR section", tok.line(), 3));
            }
        }
        return out;
    }

    /** Whether a condition joins subconditions by AND or OR anywhere. */
    private static boolean andOr(Condition c) {
        if (c instanceof Condition.Not n) {
            return andOr(n.operand());
        }
        if (c instanceof Condition.Parenthesized q) {
            return andOr(q.inner());
        }
        return c instanceof Condition.And || c instanceof Condition.Or;
    }

    /** The token after FUNCTION_BLOCK starts its body: the block has no name. */
    static boolean unnamedBlockFollows(Token next) {
        return next.is("VAR_INPUT") || next.is("VAR_OUTPUT") || next.is("VAR") || next.is("FUZZIFY")
                || next.is("DEFUZZIFY") || next.is("RULEBLOCK") || next.is("END_FUNCTION_BLOCK");
    }
}
