package org.fclcert.write;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Hedge;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.ShapeKind;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.ShapeNames;

/**
 * Writes a program as fuzzylite 6 reads FCL, in the layout of fuzzylite's own exporter: two-space indentation,
 * one statement per line, {@code RANGE := (a .. b);}, {@code METHOD : COG;} and {@code ACCU} inside DEFUZZIFY,
 * rules on one line with lower-case keywords and no {@code ;}, subconclusions joined by {@code and}, one
 * {@code with} per rule. What fuzzylite's FCL cannot say: local variables (substituted by their initial values,
 * which is exact), initial values of inputs and outputs, weights and points given by inputs, bare-variable
 * subconditions and subconclusions, two accumulations for one output. A rule whose subconclusions have
 * different weights is written once per weight. NOT is pushed down to the subconditions ({@code is not}).
 */
public final class FuzzyliteWriter implements DialectWriter {
    private static final String IN = "  ";
    /** Words fuzzylite's rule parser takes as keywords or hedges wherever they stand. */
    private static final Set<String> RULE_WORDS = Set.of("if", "is", "and", "or", "then", "with", "very", "somewhat",
            "extremely", "seldom", "any", "not");

    @Override
    public Dialect dialect() {
        return Dialect.FUZZYLITE;
    }

    @Override
    public Written write(Program program) {
        Findings findings = new Findings("fuzzylite");
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < program.functionBlocks().size(); i++) {
            FunctionBlock fb = program.functionBlocks().get(i);
            if (i > 0) {
                out.append('\n');
                findings.differs(fb.location(), WriterCode.FIRST_BLOCK_ONLY, "fuzzylite builds only the first function"
                        + " block of a program; '" + fb.name() + "' is written but fuzzylite does not build it");
            }
            OutputConditions.check(program, fb, findings, Boolean.FALSE);
            functionBlock(new BlockContext(fb, findings), out);
        }
        return new Written(Dialect.FUZZYLITE, out.toString(), findings.losses(), findings.differences());
    }

    private void functionBlock(BlockContext cx, StringBuilder out) {
        FunctionBlock fb = cx.fb;
        out.append("FUNCTION_BLOCK ").append(fb.name()).append("\n\n");
        for (VariableKind kind : List.of(VariableKind.INPUT, VariableKind.OUTPUT)) {
            List<Variable> vs = fb.variables(kind);
            if (vs.isEmpty()) {
                continue;
            }
            out.append(kind.keyword()).append('\n');
            for (Variable v : vs) {
                name(cx, v.name(), v.location());
                out.append(IN).append(v.name()).append(": ").append(v.type().name()).append(";\n");
                initialValue(cx, v);
                if (v.type() != DataType.REAL && v.type() != DataType.LREAL) {
                    cx.findings.differs(v.location(), WriterCode.IGNORED_BY_LIBRARY, "fuzzylite computes '" + v.name()
                            + "' as a real number; fclcert rounds a " + v.type().name() + " to an integer");
                }
            }
            out.append("END_VAR\n\n");
        }
        fb.options().forEach(o -> cx.findings.differs(o.location(), WriterCode.LEFT_OUT, "fuzzylite has no OPTIONS"
                + " block; it is left out (fclcert gives it no meaning)"));
        for (Fuzzification f : fb.fuzzifications()) {
            out.append("FUZZIFY ").append(cx.variable(f.variable())).append('\n');
            f.declaredRange().ifPresent(r -> out.append(IN).append("RANGE := (").append(LibraryText.number(r.min()))
                    .append(" .. ").append(LibraryText.number(r.max())).append(");\n"));
            for (Term t : f.terms()) {
                term(cx, t, true, out);
            }
            out.append("END_FUZZIFY\n\n");
        }
        Map<String, Located<AccumulationMethod>> accumulations = cx.accumulations();
        for (Defuzzification d : fb.defuzzifications()) {
            defuzzify(cx, d, accumulations.get(Names.key(d.variable())), out);
        }
        for (RuleBlock rb : fb.ruleBlocks()) {
            ruleBlock(cx, rb, out);
        }
        out.append("END_FUNCTION_BLOCK\n");
    }

    static void initialValue(BlockContext cx, Variable v) {
        if (v.initialValue().isPresent() && v.initialValue().get().value() != 0) {
            cx.findings.lost(v.initialValue().get().location(), WriterCode.INITIAL_VALUE, cx.findings.library()
                    + " rejects initial values; '" + v.name() + "' starts at 0 instead of "
                    + LibraryText.number(v.initialValue().get()));
        }
    }

    static void name(BlockContext cx, String name, org.fclcert.model.SourceLocation at) {
        if (RULE_WORDS.contains(name)) {
            cx.findings.lost(at, WriterCode.NAME, "'" + name + "' is a keyword or hedge of fuzzylite's rules; a rule"
                    + " naming it is read otherwise");
        }
    }

    private static void term(BlockContext cx, Term t, boolean input, StringBuilder out) {
        name(cx, t.name(), t.location());
        out.append(IN).append("TERM ").append(t.name()).append(" := ");
        MembershipFunction f = t.function();
        if (f instanceof MembershipFunction.Singleton s) {
            out.append(cx.numberText(s.value(), 0, WriterCode.POINT_VARIABLE, "singleton '" + t.name() + "'"));
            if (input) {
                cx.findings.differs(t.location(), WriterCode.IGNORED_BY_LIBRARY, "fuzzylite reads the number term '"
                        + t.name() + "' of an input as a constant degree (its Constant term), not as a singleton");
            }
        } else if (f instanceof MembershipFunction.Points p) {
            out.append(LibraryText.points(p.points(), cx, t.name()));
            LibraryText.verticalEdge(cx, t, p);
        } else if (f instanceof MembershipFunction.Computed c) {
            out.append(LibraryText.fuzzyliteComputed(cx, c).orElseGet(() -> {
                LibraryText.computedLost(cx, t, c, "fuzzylite's FCL as fclcert writes it (Constant or Linear)");
                return "Constant 0";
            }));
        } else {
            MembershipFunction.NamedShape n = (MembershipFunction.NamedShape) f;
            out.append(LibraryText.shape(ShapeNames.fuzzylite(n.kind(), n.parameters())));
        }
        out.append(";\n");
    }

    private static void defuzzify(BlockContext cx, Defuzzification d, Located<AccumulationMethod> accu,
            StringBuilder out) {
        String name = cx.variable(d.variable());
        out.append("DEFUZZIFY ").append(name).append('\n');
        double[] span = cx.outputSpan(d);
        out.append(IN).append("RANGE := (").append(d.range().map(r -> LibraryText.number(r.min()))
                .orElse(LibraryText.number(span[0]))).append(" .. ").append(d.range().map(r -> LibraryText
                        .number(r.max())).orElse(LibraryText.number(span[1]))).append(");\n");
        for (Term t : d.terms()) {
            term(cx, t, false, out);
        }
        DefuzzificationMethod m = d.method().map(Located::value).orElse(DefuzzificationMethod.COG);
        out.append(IN).append("METHOD : ").append(LibraryText.method(m)).append(";\n");
        defuzzificationNotes(cx, d, m, "100 samples of the RANGE");
        AccumulationMethod a = accu == null ? AccumulationMethod.MAX : accu.value();
        // fuzzylite's names: ASUM for PROBOR, the class name UnboundedSum for SUM (its FCL has no word for it), the
        // others (MAX, BSUM, NSUM, ESUM, HSUM, DSUM, NMAX) as the model's
        out.append(IN).append("ACCU : ").append(switch (a) {
            case PROBOR -> "ASUM";
            case SUM -> "UnboundedSum";
            default -> a.name();
        }).append(";\n");
        if (a == AccumulationMethod.NSUM) {
            // measured on the semantic axis: fuzzylite 6.0 fails E-ACCU-NSUM-002 and O-ACCU-NSUM-081 with BSUM's
            // values, jfuzzylite 6.0.1 passes both and E-ACCU-NSUM-001 (its NormalizedSum normalises)
            cx.findings.differs(accu.location(), WriterCode.NSUM, "fuzzylite 6.0 (the C++ library) computes ACCU NSUM"
                    + " of '" + name + "' as BSUM (jfuzzylite 6.0.1 computes the standard's NSUM)");
        }
        Optional<DefaultValue> def = d.defaultValue();
        if (def.isPresent() && def.get() instanceof DefaultValue.Constant c) {
            out.append(IN).append("DEFAULT := ").append(Double.isNaN(c.value().value()) ? "nan"
                    : LibraryText.number(c.value())).append(";\n");
        } else if (def.isPresent()) {
            // fuzzylite keeps the previous value with LOCK : PREVIOUS and gives DEFAULT before the first one,
            // which is the output's initial value in fclcert (0: fuzzylite has no initial values)
            out.append(IN).append("DEFAULT := 0;\n").append(IN).append("LOCK : PREVIOUS;\n");
        }
        out.append("END_DEFUZZIFY\n\n");
    }

    /**
     * What fuzzylite computes otherwise than the standard for output {@code d} defuzzified by {@code m}, or cannot
     * say; {@code samples} says how the library samples (its FCL and FLL readers sample alike).
     */
    static void defuzzificationNotes(BlockContext cx, Defuzzification d, DefuzzificationMethod m, String samples) {
        String name = cx.variable(d.variable());
        if (cx.pointTerms(d.variable()) && LibraryText.sampled(m)) {
            cx.findings.differs(d.method().map(Located::location).orElse(d.location()), WriterCode.SAMPLED,
                    "fuzzylite 6 computes " + m.keyword() + " of '" + name + "' from " + samples + ", not exactly");
        }
        if (!cx.pointTerms(d.variable()) && m != DefuzzificationMethod.COGS && m != DefuzzificationMethod.COGSS) {
            cx.findings.differs(d.method().map(Located::location).orElse(d.location()), WriterCode.IGNORED_BY_LIBRARY,
                    "fuzzylite takes number terms as constants: its " + m.keyword() + " of the singletons of '" + name
                            + "' is not the standard's");
        }
        if (m == DefuzzificationMethod.TSUKAMOTO && !d.terms().stream().allMatch(t -> t.function()
                instanceof MembershipFunction.NamedShape s && s.kind().monotonic())) {
            cx.findings.lost(d.method().get().location(), WriterCode.METHOD, "fuzzylite applies Tsukamoto's method"
                    + " only to outputs whose terms are all monotonic shapes (Ramp, Sigmoid, SShape, ZShape, Concave);"
                    + " '" + name + "' is written with COGS, which fuzzylite then reads otherwise");
        }
        if (m == DefuzzificationMethod.TSUKAMOTO && d.terms().stream().anyMatch(t -> t.function()
                instanceof MembershipFunction.NamedShape s && (s.kind() == ShapeKind.S_SHAPE
                        || s.kind() == ShapeKind.Z_SHAPE || s.kind() == ShapeKind.CONCAVE))) {
            cx.findings.differs(d.method().get().location(), WriterCode.TSUKAMOTO_INVERSE, "fuzzylite 6.0 inverts"
                    + " SShape, ZShape and Concave terms wrongly in Tsukamoto's method (fixed in fuzzylite 7): its '"
                    + name + "' differs from fclcert's");
        }
        if (m == DefuzzificationMethod.TSUKAMOTO && d.terms().stream().anyMatch(t -> t.function()
                instanceof MembershipFunction.NamedShape s && s.kind() == ShapeKind.SIGMOID)) {
            // measured on O-TSUKAMOTO-002 (pyfuzzylite 8.0.6 answers z = Infinity where fclcert gives the RANGE's end)
            cx.findings.differs(d.method().get().location(), WriterCode.TSUKAMOTO_INVERSE, "a Sigmoid never reaches"
                    + " degree 1 or 0, so at those degrees Tsukamoto's method has no point on it: fclcert takes the end of"
                    + " the RANGE of '" + name + "', pyfuzzylite 8 gives an infinite value");
        }
        if (m == DefuzzificationMethod.COGS || m == DefuzzificationMethod.TSUKAMOTO) {
            for (Term t : d.terms()) {
                if (cx.conclusions(d.variable(), t.name()) > 1) {
                    cx.findings.differs(d.method().map(Located::location).orElse(d.location()), WriterCode.COGS_PER_RULE,
                            "term '" + t.name() + "' of '" + name + "' is concluded by several rules: fuzzylite's COGS"
                                    + " weighs each rule's degree, fclcert (Table 5) the term's accumulated degree");
                    break;
                }
            }
        }
    }

    private static void ruleBlock(BlockContext cx, RuleBlock rb, StringBuilder out) {
        List<RuleLines.Line> lines = RuleLines.of(cx, rb, true);
        if (lines.isEmpty()) {
            // every rule was lost (and said so): fuzzylite would take the empty block's ACCU from no output
            return;
        }
        out.append("RULEBLOCK ").append(rb.name()).append('\n');
        AndAlgorithm and = rb.and().map(Located::value).orElse(rb.or().map(o -> o.value().pair()).orElse(null));
        OrAlgorithm or = rb.or().map(Located::value).orElse(rb.and().map(a -> a.value().pair()).orElse(null));
        if (and != null) {
            out.append(IN).append("AND : ").append(and.name()).append(";\n");
            out.append(IN).append("OR : ").append(or.name()).append(";\n");
        }
        // fuzzylite needs an activation even for singletons (MIN, fclcert's reading of a block without ACT)
        out.append(IN).append("ACT : ").append(rb.activation().map(a -> a.value().name()).orElse("MIN")).append(";\n");
        ActivationMethod act = rb.activation().map(Located::value).orElse(ActivationMethod.MIN);
        for (RuleLines.Line line : lines) {
            out.append(IN).append("RULE ").append(line.name()).append(" : ").append(rule(cx, line, and, or, act))
                    .append('\n');
        }
        out.append("END_RULEBLOCK\n\n");
    }

    /**
     * A rule as fuzzylite's rule parser reads it, in its FCL and in FLL alike: {@code if CONDITION then v is t and ...
     * [with w]}, noting a weight fuzzylite folds in before activation.
     */
    static String rule(BlockContext cx, RuleLines.Line line, AndAlgorithm and, OrAlgorithm or, ActivationMethod act) {
        StringBuilder r = new StringBuilder("if ").append(LibraryConditions.fuzzylite(line.condition(), cx, and, or,
                line.rule().name())).append(" then ");
        for (int i = 0; i < line.group().parts().size(); i++) {
            Subconclusion s = line.group().parts().get(i);
            r.append(i == 0 ? "" : " and ").append(cx.variable(s.variable())).append(" is ");
            for (Hedge h : RuleLines.writtenHedges(line.group(), i)) {
                r.append(h.word()).append(' ');
            }
            r.append(cx.term(s.variable(), s.term().orElseThrow()));
            if (!s.hedges().isEmpty() && line.group().value() != 1) {
                cx.findings.differs(s.location(), WriterCode.WEIGHT_BEFORE_ACTIVATION, "fuzzylite hedges the weighted"
                        + " degree of rule " + line.rule().name() + ", h(w·d); fclcert weighs the hedged degree, w·h(d)");
            }
            RuleLines.noteWeightBeforeActivation(cx, act, line, s, "fuzzylite");
        }
        line.group().weight().ifPresent(w -> r.append(" with ").append(w));
        return r.toString();
    }
}
