package org.fclcert.write;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.FllReader;
import org.fclcert.syntax.dialect.ShapeNames;

/**
 * Writes a program as fuzzylite's own format FLL ({@code .fll}), which fuzzylite 6 and pyfuzzylite 8 read: one
 * {@code Engine:} (the first function block; FLL holds one engine), then each input, output and rule block as
 * {@code key: value} lines in the order of fuzzylite's exporter. The norms, defuzzifiers and term classes are named
 * by {@link FllReader}'s tables, so what is written reads back by fclcert's FLL reader with the meaning fuzzylite
 * gives it (docs/dialects.md). FLL is fuzzylite's engine, so it says what fuzzylite's FCL says
 * ({@link FuzzyliteWriter}) and computes the same differences, with two more things it cannot say: a singleton term
 * is fuzzylite's {@code Constant}, which fclcert (as fuzzylite) evaluates per rule where the standard's CoGS
 * weighs each term's accumulated degree, and a number term of an input is no FLL term at all.
 */
public final class FllWriter implements DialectWriter {
    private static final String IN = "  ";
    private static final String SAMPLES = "100 samples of the range (pyfuzzylite 8: 1000)";

    @Override
    public Dialect dialect() {
        return Dialect.FLL;
    }

    @Override
    public Written write(Program program) {
        Findings findings = new Findings("fuzzylite");
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < program.functionBlocks().size(); i++) {
            FunctionBlock fb = program.functionBlocks().get(i);
            if (i > 0) {
                findings.lost(fb.location(), WriterCode.STRUCTURE, "an FLL file holds one engine: function block '"
                        + fb.name() + "' is left out (only the first, '" + program.functionBlocks().get(0).name()
                        + "', is written)");
                continue;
            }
            OutputConditions.check(program, fb, findings, Boolean.FALSE);
            engine(new BlockContext(fb, findings), out);
        }
        return new Written(Dialect.FLL, out.toString(), findings.losses(), findings.differences());
    }

    private static void engine(BlockContext cx, StringBuilder out) {
        FunctionBlock fb = cx.fb;
        out.append("Engine: ").append(fb.name()).append('\n');
        for (Variable v : fb.variables()) {
            FuzzyliteWriter.initialValue(cx, v);
            if (v.type() != DataType.REAL && v.type() != DataType.LREAL) {
                cx.findings.lost(v.location(), WriterCode.TYPE, "FLL declares no data types: '" + v.name()
                        + "' is a real number there, where a " + v.type().name() + " is rounded to an integer");
            }
        }
        fb.options().forEach(o -> cx.findings.differs(o.location(), WriterCode.LEFT_OUT, "FLL has no OPTIONS;"
                + " it is left out (fclcert gives it no meaning)"));
        for (Variable v : fb.variables(org.fclcert.model.VariableKind.INPUT)) {
            FuzzyliteWriter.name(cx, v.name(), v.location());
            out.append("InputVariable: ").append(v.name()).append('\n').append(IN).append("enabled: true\n");
            Optional<Fuzzification> f = fb.fuzzifications().stream().filter(x -> Names.same(x.variable(), v.name()))
                    .findFirst();
            f.flatMap(Fuzzification::declaredRange).ifPresent(r -> out.append(IN).append("range: ")
                    .append(LibraryText.number(r.min())).append(' ').append(LibraryText.number(r.max())).append('\n'));
            out.append(IN).append("lock-range: false\n");
            for (Term t : f.map(Fuzzification::terms).orElse(List.of())) {
                term(cx, t, true, out);
            }
        }
        Map<String, Located<AccumulationMethod>> accumulations = cx.accumulations();
        for (Variable v : fb.variables(org.fclcert.model.VariableKind.OUTPUT)) {
            Optional<Defuzzification> d = fb.defuzzifications().stream().filter(x -> Names.same(x.variable(),
                    v.name())).findFirst();
            if (d.isEmpty()) {
                cx.findings.lost(v.location(), WriterCode.STRUCTURE, "output '" + v.name() + "' has no DEFUZZIFY"
                        + " (its value is concluded directly); every output of FLL is defuzzified: it is left out");
                continue;
            }
            FuzzyliteWriter.name(cx, v.name(), v.location());
            out.append("OutputVariable: ").append(v.name()).append('\n').append(IN).append("enabled: true\n");
            output(cx, d.get(), accumulations.get(Names.key(v.name())), out);
        }
        for (RuleBlock rb : fb.ruleBlocks()) {
            ruleBlock(cx, rb, out);
        }
    }

    private static void term(BlockContext cx, Term t, boolean input, StringBuilder out) {
        FuzzyliteWriter.name(cx, t.name(), t.location());
        out.append(IN).append("term: ").append(t.name()).append(' ');
        MembershipFunction f = t.function();
        if (f instanceof MembershipFunction.Singleton s) {
            String x = cx.numberText(s.value(), 0, WriterCode.POINT_VARIABLE, "singleton '" + t.name() + "'");
            if (input) {
                // fuzzylite's Constant in an input is a constant degree; three points at x are the singleton as
                // fclcert reads them back, but fuzzylite's Discrete gives 0 at x (measured with fuzzylite 6.0)
                out.append("Discrete ").append(x).append(" 0 ").append(x).append(" 1 ").append(x).append(" 0");
                cx.findings.lost(t.location(), WriterCode.SHAPE, "FLL has no singleton for an input: '" + t.name()
                        + "' is written as a Discrete of three points at " + x + ", which fuzzylite 6.0 gives degree 0"
                        + " there");
            } else {
                out.append("Constant ").append(x);
            }
        } else if (f instanceof MembershipFunction.Points p) {
            out.append("Discrete");
            double previous = 0;
            for (Point pt : p.points()) {
                String x = cx.numberText(pt.x(), previous, WriterCode.POINT_VARIABLE, "a point of term '" + t.name()
                        + "'");
                previous = Double.parseDouble(x);
                out.append(' ').append(x).append(' ').append(cx.numberText(pt.degree(), 0, WriterCode.POINT_VARIABLE,
                        "a degree of term '" + t.name() + "'"));
            }
            LibraryText.verticalEdge(cx, t, p);
        } else if (f instanceof MembershipFunction.Computed c) {
            out.append(LibraryText.fuzzyliteComputed(cx, c).orElseGet(() -> {
                LibraryText.computedLost(cx, t, c, "FLL as fclcert writes it (Constant or Linear)");
                return "Constant 0";
            }));
        } else {
            MembershipFunction.NamedShape n = (MembershipFunction.NamedShape) f;
            out.append(LibraryText.shape(ShapeNames.fuzzylite(n.kind(), n.parameters())));
        }
        out.append('\n');
    }

    private static void output(BlockContext cx, Defuzzification d, Located<AccumulationMethod> accu,
            StringBuilder out) {
        String name = cx.variable(d.variable());
        double[] span = cx.outputSpan(d);
        out.append(IN).append("range: ").append(d.range().map(r -> LibraryText.number(r.min()))
                .orElse(LibraryText.number(span[0]))).append(' ').append(d.range().map(r -> LibraryText
                        .number(r.max())).orElse(LibraryText.number(span[1]))).append('\n');
        out.append(IN).append("lock-range: false\n");
        AccumulationMethod a = accu == null ? AccumulationMethod.MAX : accu.value();
        out.append(IN).append("aggregation: ").append(className(FllReader.S_NORMS,
                a == AccumulationMethod.PROBOR ? "ASUM" : a.name())).append('\n');
        if (a == AccumulationMethod.NSUM) {
            cx.findings.differs(accu.location(), WriterCode.NSUM, "fuzzylite's NormalizedSum of '" + name + "' is not"
                    + " the standard's NSUM: fuzzylite 6 computes it as BSUM, pyfuzzylite 8 normalises each pair of"
                    + " degrees as it aggregates them");
        }
        DefuzzificationMethod m = d.method().map(Located::value).orElse(DefuzzificationMethod.COG);
        // the sampled defuzzifiers take each library's own resolution (fuzzylite 6: 100, pyfuzzylite 8: 1000)
        out.append(IN).append("defuzzifier: ").append(className(FllReader.DEFUZZIFIERS, LibraryText.method(m)))
                .append('\n');
        FuzzyliteWriter.defuzzificationNotes(cx, d, m, SAMPLES);
        Optional<DefaultValue> def = d.defaultValue();
        if (def.isPresent() && def.get() instanceof DefaultValue.Constant c) {
            out.append(IN).append("default: ").append(Double.isNaN(c.value().value()) ? "nan"
                    : LibraryText.number(c.value())).append('\n');
            out.append(IN).append("lock-previous: false\n");
        } else if (def.isPresent()) {
            // NC: fuzzylite keeps the previous value and gives the default before the first one, which is the
            // output's initial value (0: fuzzylite has no initial values)
            out.append(IN).append("default: 0\n").append(IN).append("lock-previous: true\n");
        } else {
            out.append(IN).append("lock-previous: false\n");
        }
        for (Term t : d.terms()) {
            term(cx, t, false, out);
        }
    }

    private static void ruleBlock(BlockContext cx, RuleBlock rb, StringBuilder out) {
        List<RuleLines.Line> lines = RuleLines.of(cx, rb, true);
        if (lines.isEmpty()) {
            return;
        }
        out.append("RuleBlock: ").append(rb.name()).append('\n').append(IN).append("enabled: true\n");
        AndAlgorithm and = rb.and().map(Located::value).orElse(rb.or().map(o -> o.value().pair()).orElse(null));
        OrAlgorithm or = rb.or().map(Located::value).orElse(rb.and().map(a -> a.value().pair()).orElse(null));
        out.append(IN).append("conjunction: ").append(and == null ? "none" : className(FllReader.T_NORMS, and.name()))
                .append('\n');
        out.append(IN).append("disjunction: ").append(or == null ? "none" : className(FllReader.S_NORMS, or.name()))
                .append('\n');
        ActivationMethod act = rb.activation().map(Located::value).orElse(ActivationMethod.MIN);
        // fuzzylite needs an implication even for singletons (MIN, fclcert's reading of a block without ACT)
        out.append(IN).append("implication: ").append(className(FllReader.T_NORMS, act.name())).append('\n');
        out.append(IN).append("activation: General\n");
        for (RuleLines.Line line : lines) {
            out.append(IN).append("rule: ").append(FuzzyliteWriter.rule(cx, line, and, or, act)).append('\n');
        }
    }

    /** FLL's class name of the component fuzzylite's FCL calls {@code fclName}, read from the reader's table. */
    private static String className(Map<String, String> table, String fclName) {
        return table.entrySet().stream().filter(e -> e.getValue().equals(fclName)).map(Map.Entry::getKey).findFirst()
                .orElseThrow(() -> new IllegalStateException("FLL names no component " + fclName));
    }
}
