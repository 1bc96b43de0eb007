package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.fclcert.check.CoverageGaps;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.ShapeKind;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.FisReader;
import org.fclcert.syntax.dialect.ShapeNames;

/**
 * Writes a program as MATLAB's FIS text ({@code .fis}) in the layout of MATLAB's and Octave's {@code writefis}, as
 * the Octave fuzzy-logic-toolkit 0.4.6 and fuzzylite read it; fclcert's {@link FisReader} reads it back. FIS is far
 * narrower than FCL: one function block; one AND, OR, activation (ImpMethod), accumulation (AggMethod) and
 * defuzzification for the whole system; every output Mamdani (fuzzy sets) or every output Sugeno (constant
 * singletons); a rule is a flat AND or a flat OR of at most one {@code input IS [NOT] term} per input, concluding
 * at most one term per output, with one weight; no DEFAULT (where no rule fires Octave and fuzzylite give NaN).
 * Point terms are written as {@code trimf}/{@code trapmf} where their degrees are 0 and 1 in a triangle, trapezoid
 * or shoulder (a shoulder reaches to ±{@link Double#MAX_VALUE}, {@link #FAR}); other points
 * have no FIS function. Only the functions MATLAB and Octave both have are written, never fuzzylite's additions.
 * Everything else is listed as not expressible (FCL-X1nn) or as what Octave computes otherwise (FCL-X2nn).
 */
public final class FisWriter implements DialectWriter {
    /** What a message calls the format. */
    private static final String FIS = "MATLAB's FIS";
    /**
     * A shoulder is a trapezoid reaching to ±{@code FAR}, rising over [-FAR, -FAR / 2] (Octave refuses infinite
     * parameters and a vertical edge): exact for every input above -FAR / 2 (about -9e307), below +FAR / 2.
     */
    private static final double FAR = Double.MAX_VALUE;
    /** MATLAB's FIS functions the Octave toolkit 0.4.6 also has; fuzzylite's additions are not written. */
    private static final Set<String> OCTAVE_SHAPES = Set.of("trimf", "trapmf", "gaussmf", "gauss2mf", "gbellmf",
            "sigmf", "dsigmf", "psigmf", "smf", "zmf", "pimf");
    /** Norm names MATLAB and fuzzylite read that the Octave toolkit 0.4.6 has no function of. */
    private static final Set<String> NOT_IN_OCTAVE = Set.of("probor", "normalized_sum", "nilpotent_maximum",
            "nilpotent_minimum");

    @Override
    public Dialect dialect() {
        return Dialect.FIS;
    }

    @Override
    public Written write(Program program) {
        Findings findings = new Findings(FIS);
        FunctionBlock fb = program.functionBlocks().get(0);
        for (FunctionBlock other : program.functionBlocks().subList(1, program.functionBlocks().size())) {
            findings.lost(other.location(), WriterCode.STRUCTURE, "a FIS file holds one system: function block '"
                    + other.name() + "' is left out");
        }
        OutputConditions.check(program, fb, findings, null);
        BlockContext cx = new BlockContext(fb, findings);
        String text = new Block(cx).text();
        return new Written(Dialect.FIS, text, findings.losses(), findings.differences());
    }

    /** One FIS rule: the signed term index of each input and output (0: none), its weight and connective. */
    private record FisRule(long[] inputs, long[] outputs, String weight, boolean and) {
    }

    /** The system-wide settings, each taken from the first construct that states it. */
    private static final class Block {
        final BlockContext cx;
        final FunctionBlock fb;
        final List<Variable> inputs;
        final List<Variable> outputs;
        Boolean sugeno;
        /** Whether the output being written has the other kind of terms than the system's Type (a loss said). */
        boolean misfit;
        Located<DefuzzificationMethod> method;
        Located<AccumulationMethod> accumulation;
        final List<FisRule> rules = new ArrayList<>();

        Block(BlockContext cx) {
            this.cx = cx;
            this.fb = cx.fb;
            this.inputs = fb.variables(VariableKind.INPUT);
            this.outputs = fb.variables(VariableKind.OUTPUT);
        }

        String text() {
            fb.options().forEach(o -> cx.findings.differs(o.location(), WriterCode.LEFT_OUT, FIS + " has no OPTIONS"
                    + " block; it is left out (fclcert gives it no meaning)"));
            StringBuilder vars = new StringBuilder();
            for (int i = 0; i < inputs.size(); i++) {
                input(i, vars);
            }
            Map<String, Located<AccumulationMethod>> accumulations = cx.accumulations();
            for (int i = 0; i < outputs.size(); i++) {
                output(i, accumulations.get(Names.key(outputs.get(i).name())), vars);
            }
            Located<AndAlgorithm> and = null;
            Located<OrAlgorithm> or = null;
            Located<ActivationMethod> act = null;
            for (RuleBlock rb : fb.ruleBlocks()) {
                and = same(and, rb.and().orElse(null), "AndMethod", "AND");
                or = same(or, rb.or().orElse(null), "OrMethod", "OR");
                act = same(act, rb.activation().orElse(null), "ImpMethod", "ACT");
            }
            AndAlgorithm andValue = and != null ? and.value() : or != null ? or.value().pair() : AndAlgorithm.MIN;
            OrAlgorithm orValue = or != null ? or.value() : andValue.pair();
            ActivationMethod actValue = act == null ? ActivationMethod.MIN : act.value();
            for (RuleBlock rb : fb.ruleBlocks()) {
                rules(rb, andValue, orValue, actValue);
            }
            for (int i = 0; i < outputs.size(); i++) {
                defaultValue(outputs.get(i), andValue, orValue);
            }
            StringBuilder out = new StringBuilder("[System]\n");
            out.append("Name='").append(fb.name()).append("'\n");
            out.append("Type='").append(Boolean.TRUE.equals(sugeno) ? "sugeno" : "mamdani").append("'\n");
            out.append("Version=2.0\n");
            out.append("NumInputs=").append(inputs.size()).append('\n');
            out.append("NumOutputs=").append(outputs.size()).append('\n');
            out.append("NumRules=").append(rules.size()).append('\n');
            out.append("AndMethod='").append(norm(andValue.name(), true, and == null ? null : and.location()))
                    .append("'\n");
            out.append("OrMethod='").append(norm(orValue.name(), false, or == null ? null : or.location())).append("'\n");
            out.append("ImpMethod='").append(norm(actValue.name(), true, act == null ? null : act.location()))
                    .append("'\n");
            AccumulationMethod a = accumulation == null ? AccumulationMethod.MAX : accumulation.value();
            out.append("AggMethod='").append(norm(a == AccumulationMethod.PROBOR ? "ASUM" : a.name(), false,
                    accumulation == null ? null : accumulation.location())).append("'\n");
            DefuzzificationMethod m = method == null ? DefuzzificationMethod.COG : method.value();
            out.append("DefuzzMethod='").append(FisReader.fisDefuzzifier(LibraryText.method(m)).orElse("centroid"))
                    .append("'\n\n");
            out.append(vars);
            if (rules.isEmpty()) {
                return out.toString();    // no rule is left (each loss said): a [Rules] section would read as an empty rule block
            }
            out.append("[Rules]\n");
            for (FisRule r : rules) {
                StringBuilder line = new StringBuilder();
                for (long k : r.inputs()) {
                    line.append(line.isEmpty() ? "" : " ").append(k);
                }
                line.append(',');
                for (long k : r.outputs()) {
                    line.append(' ').append(k);
                }
                out.append(line).append(" (").append(r.weight()).append(") : ").append(r.and() ? 1 : 2).append('\n');
            }
            return out.toString();
        }

        /** The FIS name of a norm; fuzzylite's additions are lost, names Octave lacks noted. */
        private String norm(String fcl, boolean tNorm, SourceLocation at) {
            Optional<String> name = tNorm ? FisReader.fisTNorm(fcl) : FisReader.fisSNorm(fcl);
            if (name.isEmpty()) {
                cx.findings.lost(at, WriterCode.OPERATOR, FIS + " has no " + fcl + "; written as "
                        + (tNorm ? "min" : "max"));
                return tNorm ? "min" : "max";
            }
            if (NOT_IN_OCTAVE.contains(name.get())) {
                cx.findings.differs(at, WriterCode.NOT_LOADED, "the Octave fuzzy-logic-toolkit 0.4.6 has no '"
                        + name.get() + "' (" + fcl + "): Octave's evalfis fails on this file");
            }
            return name.get();
        }

        /** One setting for the whole system: a second, different one is lost. */
        private <T> Located<T> same(Located<T> first, Located<T> next, String key, String keyword) {
            if (first == null) {
                return next;
            }
            if (next != null && !next.value().equals(first.value())) {
                cx.findings.lost(next.location(), WriterCode.OPERATOR, FIS + " has one " + key + " for all rules: "
                        + keyword + " " + next.value() + " is written as " + first.value() + ", the first stated");
            }
            return first;
        }

        private void input(int i, StringBuilder out) {
            Variable v = inputs.get(i);
            FuzzyliteWriter.initialValue(cx, v);
            type(v);
            Optional<Fuzzification> f = fb.fuzzifications().stream().filter(x -> Names.same(x.variable(), v.name()))
                    .findFirst();
            List<Term> terms = f.map(Fuzzification::terms).orElse(List.of());
            double[] span = f.map(cx::inputSpan).orElse(new double[] {0, 1});
            out.append("[Input").append(i + 1).append("]\n");
            variable(v.name(), span, terms, true, out);
        }

        private void type(Variable v) {
            if (v.type() != DataType.REAL && v.type() != DataType.LREAL) {
                cx.findings.lost(v.location(), WriterCode.TYPE, FIS + " has real variables only: '" + v.name()
                        + "' is written as a real number, which fclcert does not round as it rounds a " + v.type().name());
            }
        }

        private void variable(String name, double[] span, List<Term> terms, boolean input, StringBuilder out) {
            double lo = span[0];
            double hi = span[1] > span[0] ? span[1] : span[0] + 1;
            out.append("Name='").append(name).append("'\n");
            out.append("Range=[").append(LibraryText.number(lo)).append(' ').append(LibraryText.number(hi)).append("]\n");
            out.append("NumMFs=").append(terms.size()).append('\n');
            for (int k = 0; k < terms.size(); k++) {
                out.append("MF").append(k + 1).append("='").append(terms.get(k).name()).append("':")
                        .append(function(terms.get(k), input)).append('\n');
            }
            out.append('\n');
        }

        private void output(int i, Located<AccumulationMethod> accu, StringBuilder out) {
            Variable v = outputs.get(i);
            FuzzyliteWriter.initialValue(cx, v);
            type(v);
            Defuzzification d = fb.defuzzifications().stream().filter(x -> Names.same(x.variable(), v.name()))
                    .findFirst().orElse(null);
            out.append("[Output").append(i + 1).append("]\n");
            if (d == null) {
                variable(v.name(), new double[] {0, 1}, List.of(), false, out);
                return;
            }
            boolean singletons = !d.terms().isEmpty() && d.terms().stream().allMatch(t -> LibraryText.singleton(t.function()));
            if (sugeno == null) {
                sugeno = singletons;
            } else if (sugeno != singletons) {
                misfit = true;
                cx.findings.lost(d.location(), WriterCode.STRUCTURE, FIS + "'s Type is one for the whole system: '"
                        + v.name() + "' has " + (singletons ? "singletons" : "fuzzy sets") + " where an earlier output"
                        + " has " + (singletons ? "fuzzy sets" : "singletons"));
            }
            Located<DefuzzificationMethod> m = d.method().orElse(new Located<>(DefuzzificationMethod.COG, d.location()));
            if (singletons && m.value() != DefuzzificationMethod.COGS && m.value() != DefuzzificationMethod.COGSS
                    || !singletons && (m.value() == DefuzzificationMethod.COGS || m.value() == DefuzzificationMethod.COGSS
                            || m.value() == DefuzzificationMethod.TSUKAMOTO)) {
                cx.findings.lost(m.location(), WriterCode.METHOD, FIS + " has no " + m.value().keyword() + " of "
                        + (singletons ? "singletons (Sugeno: wtaver, wtsum)" : "fuzzy sets (centroid, bisector, mom,"
                        + " som, lom)") + "; '" + v.name() + "' is written with the system's method");
            } else if (method == null) {
                method = m;
            } else if (method.value() != m.value()) {
                cx.findings.lost(m.location(), WriterCode.METHOD, FIS + " has one DefuzzMethod for all outputs: '"
                        + v.name() + "' is defuzzified by " + method.value().keyword() + ", not " + m.value().keyword());
            }
            if (!singletons) {
                cx.findings.differs(m.location(), WriterCode.SAMPLED, "Octave computes " + m.value().keyword() + " of '"
                        + v.name() + "' from 101 samples of its Range (fuzzylite 6 from 100), not exactly");
                if (m.value() == DefuzzificationMethod.COA) {
                    // measured: defuzz.m of 0.4.6 ends its bisector with 'crisp_x = midpoint', the sample's index
                    cx.findings.differs(m.location(), WriterCode.NOT_A_POSITION, "the Octave fuzzy-logic-toolkit 0.4.6's"
                            + " bisector returns the number of the sample where the area of '" + v.name() + "' halves"
                            + " (1 to 101), not its position; MATLAB and fuzzylite return the position");
                }
            }
            Located<AccumulationMethod> a = accu == null ? new Located<>(AccumulationMethod.MAX, d.location()) : accu;
            if (singletons && a.value() != AccumulationMethod.SUM && d.terms().stream()
                    .anyMatch(t -> cx.conclusions(v.name(), t.name()) > 1)) {
                // MATLAB and fuzzylite average every rule's value (ACCU SUM); Octave accumulates a term's rules first
                cx.findings.lost(a.location(), WriterCode.ACCUMULATION, "a term of '" + v.name() + "' is concluded by"
                        + " several rules: " + FIS + "'s weighted average counts every rule (ACCU SUM), not ACCU "
                        + a.value());
            } else if (accumulation == null) {
                accumulation = a;
            } else if (accumulation.value() != a.value() && !singletons) {
                cx.findings.lost(a.location(), WriterCode.ACCUMULATION, FIS + " has one AggMethod for all outputs: '"
                        + v.name() + "' is accumulated by " + accumulation.value() + ", not " + a.value());
            }
            double[] span = cx.outputSpan(d);
            variable(v.name(), span, d.terms(), false, out);
            misfit = false;
        }

        /** {@code 'trimf',[a b c]}: a term's FIS function, or the nearest one with the loss said. */
        private String function(Term t, boolean input) {
            MembershipFunction f = t.function();
            if (misfit && Boolean.TRUE.equals(sugeno)) {
                // a fuzzy set in a Sugeno system (its loss said): a constant keeps its place, as the Type requires
                return "'constant',[0]";
            }
            if (f instanceof MembershipFunction.Singleton s) {
                String v = cx.numberText(s.value(), 0, WriterCode.POINT_VARIABLE, "singleton '" + t.name() + "'");
                if (misfit) {
                    double x = Double.parseDouble(v);
                    return trapmf(x, x, x, x);
                }
                if (input) {
                    cx.findings.lost(t.location(), WriterCode.SHAPE, FIS + " has no singleton term of an input ('"
                            + t.name() + "'); written as a trapezoid of width 1");
                    double x = Double.parseDouble(v);
                    return trapmf(x, x, x, x);
                }
                return "'constant',[" + v + "]";
            }
            if (f instanceof MembershipFunction.Points p) {
                return points(t, p);
            }
            if (f instanceof MembershipFunction.NamedShape n) {
                return shape(t, n);
            }
            cx.findings.lost(t.location(), WriterCode.SHAPE, FIS + " has no computed term ('" + t.name() + "')");
            return Boolean.TRUE.equals(sugeno) ? "'constant',[0]" : trapmf(0, 0, 0, 0);
        }

        private String shape(Term t, MembershipFunction.NamedShape n) {
            List<Double> p = n.parameters().stream().map(Literal::value).toList();
            if (n.kind() == ShapeKind.RECTANGLE) {
                cx.findings.differs(t.location(), WriterCode.NOT_LOADED, "rectangle '" + t.name() + "' is a trapmf with"
                        + " vertical edges, which the Octave fuzzy-logic-toolkit 0.4.6 refuses");
                return trapmf(p.get(0), p.get(0), p.get(1), p.get(1));
            }
            if (n.kind() == ShapeKind.RAMP) {
                return p.get(0) <= p.get(1) ? rising(p.get(0), p.get(1)) : falling(p.get(1), p.get(0));
            }
            Optional<Map.Entry<String, int[]>> fis = FisReader.fisShape(ShapeNames.fuzzylite(n.kind(), n.parameters()).name())
                    .filter(e -> OCTAVE_SHAPES.contains(e.getKey()));
            if (fis.isEmpty()) {
                cx.findings.lost(t.location(), WriterCode.SHAPE, FIS + " has no " + n.kind().name().toLowerCase()
                        + " ('" + t.name() + "'); written as a trapezoid through its special points");
                // a falling shape lists its special points from right to left
                double[] s = n.kind().specialPoints(n.values()).clone();
                java.util.Arrays.sort(s);
                return trapmf(s[0], s[s.length / 2], s[s.length / 2], s[s.length - 1]);
            }
            if (n.kind() == ShapeKind.BELL && p.get(2) != Math.rint(p.get(2))) {
                // are_mf_params.m of the toolkit: gbellmf's b must be an integer (MATLAB takes any b)
                cx.findings.differs(t.location(), WriterCode.NOT_LOADED, "bell '" + t.name() + "' has slope "
                        + LibraryText.number(p.get(2)) + ": the Octave fuzzy-logic-toolkit 0.4.6 refuses a gbellmf whose"
                        + " b is no integer");
            }
            if (n.kind() == ShapeKind.SIGMOID_DIFFERENCE) {
                FisReader.dsigmfDifference(n.values()).ifPresent(d -> cx.findings.differs(t.location(),
                        WriterCode.SHAPE_FORMULA, "sigmoid difference '" + t.name() + "': " + d));
            }
            int[] order = fis.get().getValue();
            double[] written = new double[order.length];
            for (int k = 0; k < order.length; k++) {
                written[order[k]] = p.get(k);
            }
            return "'" + fis.get().getKey() + "'," + list(written);
        }

        /**
         * A shoulder rising over [x0, x1] and 1 up to FAR. Its plateau starts at FAR / 2 or at x1, whichever is later:
         * a ramp whose top lies beyond FAR / 2 would otherwise give a trapezoid with c &lt; b, which no reader accepts.
         */
        private static String rising(double x0, double x1) {
            return trapmf(x0, x1, Math.max(x1, FAR / 2), FAR);
        }

        /** A shoulder 1 from -FAR, falling over [x0, x1] (the mirror of {@link #rising}). */
        private static String falling(double x0, double x1) {
            return trapmf(-FAR, Math.min(x0, -FAR / 2), x0, x1);
        }

        /** Points as trimf or trapmf when they are a triangle, a trapezoid or a shoulder of degrees 0 and 1. */
        private String points(Term t, MembershipFunction.Points p) {
            List<double[]> xy = new ArrayList<>();
            double previous = 0;
            for (Point pt : p.points()) {
                double x = cx.number(pt.x(), previous, WriterCode.POINT_VARIABLE, "a point of term '" + t.name() + "'");
                double y = cx.number(pt.degree(), 0, WriterCode.POINT_VARIABLE, "a degree of term '" + t.name() + "'");
                xy.add(new double[] {x, y});
                previous = x;
            }
            LibraryText.verticalEdge(cx, t, p);
            // a run of one degree at either end says what the outer-degree rule says anyway (5.2.2)
            while (xy.size() > 1 && xy.get(0)[1] == xy.get(1)[1]) {
                xy.remove(0);
            }
            while (xy.size() > 1 && xy.get(xy.size() - 1)[1] == xy.get(xy.size() - 2)[1]) {
                xy.remove(xy.size() - 1);
            }
            for (int k = 1; k < xy.size(); k++) {
                if (xy.get(k)[0] == xy.get(k - 1)[0]) {
                    cx.findings.differs(t.location(), WriterCode.NOT_LOADED, "term '" + t.name() + "' has a vertical edge,"
                            + " which the Octave fuzzy-logic-toolkit 0.4.6 refuses in trimf and trapmf (MATLAB and"
                            + " fuzzylite read it)");
                    break;
                }
            }
            StringBuilder degrees = new StringBuilder();
            xy.forEach(q -> degrees.append(q[1] == 0 ? '0' : q[1] == 1 ? '1' : '?'));
            double[] x = xy.stream().mapToDouble(q -> q[0]).toArray();
            return switch (degrees.toString()) {
                case "010" -> x[0] < x[2] ? "'trimf'," + list(x) : trapmf(x[0], x[1], x[1], x[2]);
                case "0110" -> trapmf(x[0], x[1], x[2], x[3]);
                case "10" -> falling(x[0], x[1]);
                case "01" -> rising(x[0], x[1]);
                case "1" -> trapmf(-FAR, -FAR / 2, FAR / 2, FAR);
                default -> {
                    cx.findings.lost(t.location(), WriterCode.SHAPE, FIS + " has no function of the points of term '"
                            + t.name() + "' (only triangles, trapezoids and shoulders of degrees 0 and 1); written as"
                            + " the trapezoid of its support and its highest degree");
                    double top = xy.stream().mapToDouble(q -> q[1]).max().orElse(1);
                    double[] peak = xy.stream().filter(q -> q[1] == top).mapToDouble(q -> q[0]).toArray();
                    yield trapmf(x[0], peak[0], peak[peak.length - 1], x[x.length - 1]);
                }
            };
        }

        /** A trapezoid; one of no width (the nearest thing to a lost term) gets width 1 so that it still reads. */
        private static String trapmf(double a, double b, double c, double d) {
            if (!(a < d)) {
                a -= 0.5;
                d += 0.5;
            }
            return "'trapmf'," + list(new double[] {a, b, c, d});
        }

        private static String list(double[] values) {
            StringBuilder out = new StringBuilder("[");
            for (double v : values) {
                out.append(out.length() == 1 ? "" : " ").append(LibraryText.number(v));
            }
            return out.append(']').toString();
        }

        /** The block's rules as FIS rules, each with the block's weight group split per output term. */
        private void rules(RuleBlock rb, AndAlgorithm and, OrAlgorithm or, ActivationMethod act) {
            for (RuleLines.Line line : RuleLines.of(cx, rb, false)) {
                long[] antecedent = new long[inputs.size()];
                Optional<Boolean> connective = flatten(line.condition(), false, antecedent, line.rule(), and, or);
                if (connective.isEmpty()) {
                    continue;
                }
                List<long[]> consequents = new ArrayList<>();
                for (Subconclusion s : line.group().parts()) {
                    int o = index(outputs, s.variable());
                    long term = termIndex(s.variable(), s.term().orElseThrow());
                    if (o < 0 || term == 0) {
                        continue;
                    }
                    long[] slot = consequents.stream().filter(c -> c[o] == 0).findFirst().orElse(null);
                    if (slot == null) {
                        consequents.add(slot = new long[outputs.size()]);
                    }
                    slot[o] = term;
                    RuleLines.noteWeightBeforeActivation(cx, act, line, s, FIS);
                }
                String weight = LibraryText.number(line.group().value());
                for (long[] c : consequents) {
                    rules.add(new FisRule(antecedent, c, weight, connective.get()));
                }
            }
        }

        /**
         * Fills {@code antecedent} from a condition that is one subcondition or a flat AND or OR of them (NOT pushed
         * down by De Morgan); the connective (true: AND), or empty when the rule is left out (and said so).
         */
        private Optional<Boolean> flatten(Condition c, boolean negate, long[] antecedent, Rule rule, AndAlgorithm and,
                OrAlgorithm or) {
            List<Condition.TermSubcondition> literals = new ArrayList<>();
            List<Boolean> negations = new ArrayList<>();
            Boolean[] connective = {null};
            if (!collect(c, negate, literals, negations, connective, rule, and, or)) {
                return Optional.empty();
            }
            for (int k = 0; k < literals.size(); k++) {
                Condition.TermSubcondition t = literals.get(k);
                int i = index(inputs, t.variable());
                if (i < 0) {
                    return Optional.empty();    // an output in the condition: lost (OutputConditions)
                }
                if (antecedent[i] != 0) {
                    cx.findings.lost(t.location(), WriterCode.RULE_FORM, "rule " + rule.name() + " names input '"
                            + t.variable() + "' twice; a FIS rule has one term per input: the rule is left out");
                    return Optional.empty();
                }
                long term = termIndex(t.variable(), t.term());
                if (term == 0) {
                    return Optional.empty();
                }
                antecedent[i] = negations.get(k) ? -term : term;
            }
            return Optional.of(connective[0] == null || connective[0]);
        }

        private boolean collect(Condition c, boolean negate, List<Condition.TermSubcondition> literals,
                List<Boolean> negations, Boolean[] connective, Rule rule, AndAlgorithm and, OrAlgorithm or) {
            if (c instanceof Condition.TermSubcondition t) {
                literals.add(t);
                negations.add(t.negated() != negate);
                return true;
            }
            if (c instanceof Condition.Parenthesized p) {
                return collect(p.inner(), negate, literals, negations, connective, rule, and, or);
            }
            if (c instanceof Condition.Not n) {
                return collect(n.operand(), !negate, literals, negations, connective, rule, and, or);
            }
            boolean isAnd = c instanceof Condition.And;
            List<Condition> operands = isAnd ? ((Condition.And) c).operands() : ((Condition.Or) c).operands();
            boolean written = isAnd != negate;
            if (negate && (and != AndAlgorithm.MIN || or != OrAlgorithm.MAX)) {
                cx.findings.lost(c.location(), WriterCode.OPERATOR, "rule " + rule.name() + ": " + FIS + " has no NOT"
                        + " over an " + (isAnd ? "AND" : "OR") + "; De Morgan's law is exact in floating point for AND"
                        + " MIN with OR MAX only, not for AND " + and + " with OR " + or + ": the rule is left out");
                return false;
            }
            if (connective[0] != null && connective[0] != written) {
                cx.findings.lost(c.location(), WriterCode.RULE_FORM, "rule " + rule.name() + " mixes AND and OR; a"
                        + " FIS rule is one flat AND or one flat OR: the rule is left out");
                return false;
            }
            connective[0] = written;
            for (Condition o : operands) {
                if (!collect(o, negate, literals, negations, connective, rule, and, or)) {
                    return false;
                }
            }
            return true;
        }

        private static int index(List<Variable> vars, String name) {
            for (int i = 0; i < vars.size(); i++) {
                if (Names.same(vars.get(i).name(), name)) {
                    return i;
                }
            }
            return -1;
        }

        /** The 1-based index of a term among its variable's terms (0: not found). */
        private long termIndex(String variable, String term) {
            List<Term> terms = cx.terms(variable);
            for (int k = 0; k < terms.size(); k++) {
                if (Names.same(terms.get(k).name(), term)) {
                    return k + 1;
                }
            }
            return 0;
        }

        /**
         * FIS has no DEFAULT: where no rule concluding the output fires, Octave and fuzzylite give NaN. A DEFAULT
         * other than NaN is kept only when the output's rules fire everywhere (found exactly by {@link CoverageGaps}).
         */
        private void defaultValue(Variable v, AndAlgorithm and, OrAlgorithm or) {
            Optional<Defuzzification> d = fb.defuzzifications().stream().filter(x -> Names.same(x.variable(), v.name()))
                    .findFirst();
            if (d.isEmpty() || d.get().defaultValue().isEmpty()) {
                return;
            }
            DefaultValue def = d.get().defaultValue().get();
            if (def instanceof DefaultValue.Constant c && Double.isNaN(c.value().value())) {
                return;
            }
            List<Rule> concluding = new ArrayList<>();
            for (RuleBlock rb : fb.ruleBlocks()) {
                for (Rule r : rb.rules()) {
                    if (r.conclusion().stream().anyMatch(s -> Names.same(s.variable(), v.name()))) {
                        concluding.add(r);
                    }
                }
            }
            SourceLocation at = d.get().location();
            RuleBlock all = new RuleBlock("all", Optional.of(new Located<>(and, at)), Optional.of(new Located<>(or, at)),
                    Optional.empty(), Optional.empty(), concluding, at);
            CoverageGaps.Result coverage = CoverageGaps.of(fb, all);
            if (!coverage.analysed() || !coverage.gaps().isEmpty() || coverage.undecidedCells() > 0) {
                cx.findings.lost(at, WriterCode.DEFAULT, FIS + " has no DEFAULT: where no rule concluding '"
                        + v.name() + "' fires, Octave and fuzzylite give NaN (MATLAB the middle of its Range)"
                        + (coverage.analysed() ? "" : "; whether its rules fire everywhere is not known: "
                        + coverage.notAnalysed().get()));
            }
        }
    }
}
