package org.fclcert.write;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.MembershipFunction.NamedShape;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.ShapeNames;

/**
 * Writes a program as jFuzzyLogic reads FCL: four-space indentation, {@code RANGE := (a .. b);}, terms as point
 * lists or jFuzzyLogic's shape names, every setting jFuzzyLogic would otherwise supply itself written out
 * (ACCU, whose absence jFuzzyLogic reads as a plain sum; METHOD; DEFAULT, whose absence it reads as NC), one
 * {@code WITH} at the end of a rule, every AND or OR inside another operator in parentheses (jFuzzyLogic gives
 * them one priority). What jFuzzyLogic's FCL cannot say: local variables (substituted by their initial values,
 * exact), initial values, weights and points given by inputs, bare variables, hedges, an AND and an OR that are
 * not a pair of Table 3 (jFuzzyLogic couples them), COGSS and the shapes it lacks.
 */
public final class JFuzzyLogicWriter implements DialectWriter {
    private static final String IN = "    ";

    @Override
    public Dialect dialect() {
        return Dialect.JFUZZYLOGIC;
    }

    @Override
    public Written write(Program program) {
        Findings findings = new Findings("jFuzzyLogic");
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < program.functionBlocks().size(); i++) {
            if (i > 0) {
                out.append('\n');
            }
            OutputConditions.check(program, program.functionBlocks().get(i), findings, Boolean.TRUE);
            BlockContext cx = new BlockContext(program.functionBlocks().get(i), findings);
            cx.spelling = n -> n.startsWith("_") || RESERVED.contains(n.toUpperCase(java.util.Locale.ROOT)) ? "u" + n : n;
            functionBlock(cx, out);
        }
        return new Written(Dialect.JFUZZYLOGIC, out.toString(), findings.losses(), findings.differences());
    }

    private void functionBlock(BlockContext cx, StringBuilder out) {
        FunctionBlock fb = cx.fb;
        name(cx, fb.name(), fb.location());
        out.append("FUNCTION_BLOCK ").append(cx.spelling.apply(fb.name())).append("\n\n");
        for (VariableKind kind : List.of(VariableKind.INPUT, VariableKind.OUTPUT)) {
            List<Variable> vs = fb.variables(kind);
            if (vs.isEmpty()) {
                continue;
            }
            out.append(kind.keyword()).append('\n');
            for (Variable v : vs) {
                name(cx, v.name(), v.location());
                // jFuzzyLogic's grammar has the type REAL only; fclcert computes REAL and LREAL alike
                out.append(IN).append(cx.variable(v.name())).append(" : REAL;\n");
                // jFuzzyLogic takes an input's RANGE after its declaration (its grammar refuses one in FUZZIFY)
                fb.fuzzification(v.name()).flatMap(Fuzzification::declaredRange).ifPresent(r -> out.append(IN)
                        .append("RANGE := (").append(LibraryText.number(r.min())).append(" .. ")
                        .append(LibraryText.number(r.max())).append(");\n"));
                if (v.type().isInteger()) {
                    cx.findings.lost(v.location(), WriterCode.TYPE, "jFuzzyLogic declares"
                            + " REAL variables only; '" + v.name() + "' is written as REAL, so the rounding of a "
                            + v.type().name() + " to an integer is lost");
                }
                FuzzyliteWriter.initialValue(cx, v);
            }
            out.append("END_VAR\n\n");
        }
        fb.options().forEach(o -> cx.findings.differs(o.location(), WriterCode.LEFT_OUT, "jFuzzyLogic has no OPTIONS"
                + " block; it is left out (fclcert gives it no meaning)"));
        for (Fuzzification f : fb.fuzzifications()) {
            out.append("FUZZIFY ").append(cx.variable(f.variable())).append('\n');
            double[] span = cx.inputSpan(f);
            for (Term t : f.terms()) {
                term(cx, t, span, out);
            }
            out.append("END_FUZZIFY\n\n");
        }
        for (Defuzzification d : fb.defuzzifications()) {
            defuzzify(cx, d, out);
        }
        for (RuleBlock rb : fb.ruleBlocks()) {
            ruleBlock(cx, rb, out);
        }
        out.append("END_FUNCTION_BLOCK\n");
    }

    /** Words of jFuzzyLogic's grammar (any case) that it does not take as names. */
    private static final java.util.Set<String> RESERVED = java.util.Set.of("ABS", "ACCU", "ACT", "AND", "ASUM",
            "BDIF", "BSUM", "COA", "COG", "COGF", "COGS", "COS", "COSINE", "DEFAULT", "DEFUZZIFY", "DMAX", "DMIN",
            "DSIGM", "EINSTEIN", "END_DEFUZZIFY", "END_FUNCTION_BLOCK", "END_FUZZIFY", "END_RULEBLOCK", "END_VAR",
            "EXP", "FUNCTION", "FUNCTION_BLOCK", "FUZZIFY", "GAUSS", "GAUSS2", "GBELL", "HAMACHER", "IF", "IS", "LM",
            "LN", "LOG", "MAX", "METHOD", "MIN", "MM", "NC", "NIPMAX", "NIPMIN", "NOT", "NSUM", "OR", "PROBOR", "PROD",
            "RANGE", "REAL", "RM", "RULE", "RULEBLOCK", "SIGM", "SIN", "SINGLETONS", "SUM", "TAN", "TERM", "THEN",
            "TRAPE", "TRIAN", "VAR_INPUT", "VAR_OUTPUT", "WITH");

    private static void name(BlockContext cx, String name, SourceLocation at) {
        if (name.startsWith("_")) {
            cx.findings.lost(at, WriterCode.NAME, "jFuzzyLogic rejects names starting with '_': '" + name
                    + "' is written as 'u" + name + "'");
        } else if (RESERVED.contains(name.toUpperCase(java.util.Locale.ROOT))) {
            cx.findings.lost(at, WriterCode.NAME, "'" + name + "' is a word of jFuzzyLogic's grammar, not a name there;"
                    + " it is written as 'u" + name + "'");
        }
    }

    private static void term(BlockContext cx, Term t, double[] span, StringBuilder out) {
        name(cx, t.name(), t.location());
        out.append(IN).append("TERM ").append(cx.spelling.apply(t.name())).append(" := ");
        MembershipFunction f = t.function();
        if (f instanceof MembershipFunction.Singleton s) {
            out.append(cx.numberText(s.value(), 0, WriterCode.POINT_VARIABLE, "singleton '" + t.name() + "'"));
        } else if (f instanceof MembershipFunction.Points p) {
            out.append(LibraryText.points(p.points(), cx, t.name()));
            LibraryText.verticalEdge(cx, t, p);
        } else if (f instanceof MembershipFunction.Computed c) {
            LibraryText.computedLost(cx, t, c, "jFuzzyLogic's FCL as fclcert writes it");
            out.append('0');
        } else {
            out.append(shape(cx, t, (NamedShape) f, span));
        }
        out.append(";\n");
    }

    /** A shape jFuzzyLogic names (ShapeNames.JFUZZYLOGIC: its names, orders and cosine's half width), else points. */
    private static String shape(BlockContext cx, Term t, NamedShape n, double[] span) {
        Optional<ShapeNames.Written> named = ShapeNames.jfuzzylogic(n.kind(), n.parameters());
        if (named.isPresent() && n.parameters().size() == n.kind().arity()) {
            return LibraryText.shape(named.get());
        }
        Optional<List<org.fclcert.model.Point>> exact = ShapePoints.exact(n);
        if (exact.isPresent()) {
            return LibraryText.points(exact.get(), cx, t.name());
        }
        ShapePoints.Approximation a = ShapePoints.approximate(n, span[0], span[1], 101);
        cx.findings.lost(t.location(), WriterCode.SHAPE, "jFuzzyLogic has no " + n.kind() + " shape; term '" + t.name()
                + "' is written as 101 points, membership error up to " + LibraryText.upTo3Digits(a.maxError()));
        return LibraryText.points(a.points(), cx, t.name());
    }

    private static void defuzzify(BlockContext cx, Defuzzification d, StringBuilder out) {
        String name = cx.variable(d.variable());
        out.append("DEFUZZIFY ").append(name).append('\n');
        double[] span = cx.outputSpan(d);
        out.append(IN).append("RANGE := (").append(d.range().map(r -> LibraryText.number(r.min()))
                .orElse(LibraryText.number(span[0]))).append(" .. ").append(d.range().map(r -> LibraryText
                        .number(r.max())).orElse(LibraryText.number(span[1]))).append(");\n");
        for (Term t : d.terms()) {
            term(cx, t, span, out);
        }
        DefuzzificationMethod m = d.method().map(Located::value).orElse(DefuzzificationMethod.COG);
        if (m == DefuzzificationMethod.COGSS) {
            cx.findings.lost(d.method().get().location(), WriterCode.METHOD, "jFuzzyLogic has no COGSS; '" + name
                    + "' is written with COGS");
            m = DefuzzificationMethod.COGS;
        } else if (m == DefuzzificationMethod.TSUKAMOTO) {
            cx.findings.lost(d.method().get().location(), WriterCode.METHOD, "jFuzzyLogic has no Tsukamoto method; '"
                    + name + "' is written with COG");
            m = DefuzzificationMethod.COG;
        }
        out.append(IN).append("METHOD : ").append(LibraryText.method(m)).append(";\n");
        if (cx.pointTerms(d.variable()) && LibraryText.sampled(m)) {
            cx.findings.differs(d.method().map(Located::location).orElse(d.location()), WriterCode.SAMPLED,
                    "jFuzzyLogic computes " + m.keyword() + " of '" + name + "' from 1000 samples of the RANGE, not"
                            + " exactly (a narrow term between samples can be missed; LM, RM and MM take the maxima"
                            + " among the samples)");
        } else if (!cx.pointTerms(d.variable()) && m != DefuzzificationMethod.COGS) {
            cx.findings.differs(d.method().map(Located::location).orElse(d.location()), WriterCode.NOT_LOADED,
                    "jFuzzyLogic's " + m.keyword() + " is continuous: it fails to evaluate '" + name + "', whose terms"
                            + " are singletons");
        }
        Optional<DefaultValue> def = d.defaultValue();
        if (def.isPresent() && def.get() instanceof DefaultValue.Constant c && Double.isNaN(c.value().value())) {
            cx.findings.lost(c.location(), WriterCode.DEFAULT, "jFuzzyLogic has no DEFAULT := nan; '" + name
                    + "' is written with DEFAULT := 0");
            def = Optional.empty();
        }
        String value = def.map(v -> v instanceof DefaultValue.Constant c ? LibraryText.number(c.value()) : "NC")
                .orElse("0");
        out.append(IN).append("DEFAULT := ").append(value).append(";\n");
        out.append("END_DEFUZZIFY\n\n");
    }

    /** jFuzzyLogic's names of the AND and OR algorithms it has, and the OR it couples with each AND. */
    private static final Map<AndAlgorithm, String> JFL_AND = Map.of(AndAlgorithm.MIN, "MIN", AndAlgorithm.PROD, "PROD",
            AndAlgorithm.BDIF, "BDIF", AndAlgorithm.DPROD, "DMIN", AndAlgorithm.NMIN, "NIPMIN", AndAlgorithm.HPROD, "HAMACHER");
    private static final Map<OrAlgorithm, String> JFL_OR = Map.of(OrAlgorithm.MAX, "MAX", OrAlgorithm.ASUM, "ASUM",
            OrAlgorithm.BSUM, "BSUM", OrAlgorithm.DSUM, "DMAX", OrAlgorithm.NMAX, "NIPMAX", OrAlgorithm.ESUM, "EINSTEIN");
    private static final Map<AndAlgorithm, OrAlgorithm> JFL_PARTNER = Map.of(AndAlgorithm.MIN, OrAlgorithm.MAX,
            AndAlgorithm.PROD, OrAlgorithm.ASUM, AndAlgorithm.BDIF, OrAlgorithm.BSUM, AndAlgorithm.DPROD, OrAlgorithm.DSUM,
            AndAlgorithm.NMIN, OrAlgorithm.NMAX, AndAlgorithm.HPROD, OrAlgorithm.ESUM);

    private static void ruleBlock(BlockContext cx, RuleBlock rb, StringBuilder out) {
        out.append("RULEBLOCK ").append(cx.spelling.apply(rb.name())).append('\n');
        AndAlgorithm and = rb.and().map(Located::value).orElse(null);
        OrAlgorithm or = rb.or().map(Located::value).orElse(null);
        if (and != null && JFL_AND.get(and) == null || and == null && or != null && JFL_OR.get(or) == null) {
            var at = and != null ? rb.and().get().location() : rb.or().get().location();
            cx.findings.lost(at, WriterCode.OPERATOR, "jFuzzyLogic has no " + (and != null ? "AND " + and : "OR " + or)
                    + "; rule block '" + rb.name() + "' is written with AND MIN");
            and = AndAlgorithm.MIN;
            or = null;
        }
        if (and != null && or != null && JFL_PARTNER.get(and) != or) {
            cx.findings.lost(rb.or().get().location(), WriterCode.OPERATOR, "jFuzzyLogic couples AND and OR (declaring"
                    + " one sets the other to its partner): AND " + and + " with OR " + or + " cannot be said; written:"
                    + " AND " + and + " and OR " + JFL_PARTNER.get(and));
            or = JFL_PARTNER.get(and);
        }
        if (and != null) {
            out.append(IN).append("AND : ").append(JFL_AND.get(and)).append(";\n");
        }
        if (or != null) {
            out.append(IN).append("OR : ").append(JFL_OR.get(or)).append(";\n");
        }
        rb.activation().ifPresent(a -> {
            if (!a.value().standard()) {
                cx.findings.lost(a.location(), WriterCode.OPERATOR, "jFuzzyLogic has no ACT " + a.value()
                        + "; rule block '" + rb.name() + "' is written with MIN");
            }
            out.append(IN).append("ACT : ").append(a.value().standard() ? a.value().name() : "MIN").append(";\n");
        });
        AccumulationMethod a = rb.accumulation().map(Located::value).orElse(AccumulationMethod.MAX);
        if (a.otherNorm().isPresent()) {
            cx.findings.lost(rb.accumulation().get().location(), WriterCode.ACCUMULATION, "jFuzzyLogic has no ACCU "
                    + a + "; rule block '" + rb.name() + "' is written with MAX");
            a = AccumulationMethod.MAX;
        }
        out.append(IN).append("ACCU : ").append(a.name()).append(";\n");
        if (a == AccumulationMethod.NSUM) {
            cx.findings.differs(rb.accumulation().get().location(), WriterCode.NSUM, "jFuzzyLogic computes ACCU NSUM"
                    + " of rule block '" + rb.name() + "' as BSUM");
        }
        org.fclcert.model.ActivationMethod act = rb.activation().map(Located::value)
                .filter(org.fclcert.model.ActivationMethod::standard).orElse(org.fclcert.model.ActivationMethod.MIN);
        for (RuleLines.Line line : RuleLines.of(cx, rb, false)) {
            StringBuilder r = new StringBuilder(IN).append("RULE ").append(line.name()).append(" : IF ")
                    .append(LibraryConditions.jfuzzylogic(line.condition(), cx, line.rule().name())).append(" THEN ");
            for (int i = 0; i < line.group().parts().size(); i++) {
                Subconclusion s = line.group().parts().get(i);
                r.append(i == 0 ? "" : ", ").append(cx.variable(s.variable())).append(" IS ")
                        .append(cx.term(s.variable(), s.term().orElseThrow()));
                RuleLines.noteWeightBeforeActivation(cx, act, line, s, "jFuzzyLogic");
            }
            line.group().weight().ifPresent(w -> r.append(" WITH ").append(w));
            out.append(r).append(";\n");
        }
        out.append("END_RULEBLOCK\n\n");
    }
}
