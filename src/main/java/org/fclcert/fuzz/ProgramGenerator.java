package org.fclcert.fuzz;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Feature;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * Random valid standard FCL programs (one function block) on the semantic model, for differential testing.
 * Every program passes the strict reader ({@code StrictReader.openLevel()}) and the checks once written with
 * the canonical writer; anything else is a bug of this class. Each program is a function of its seed alone.
 *
 * <p>What a program uses is drawn feature by feature with the weights of {@link FuzzSettings}: every row of
 * Tables 8 and 9 and the Open Level features the reference evaluates (many points, fractional and variable
 * degrees, MoM). Sizes range from one input, one rule and one output to eight inputs and twenty rules.
 * Numbers sit on coarse decimal grids so that ties, plateaus and shared breakpoints occur often.
 */
public final class ProgramGenerator {
    private static final SourceLocation AT = SourceLocation.UNKNOWN;
    private static final double[][] SCALES = {{0, 10}, {0, 100}, {-10, 10}, {0, 1}, {-50, 50}, {0, 1000}, {-1, 1}, {20, 80}};
    private static final int[] GRIDS = {4, 5, 8, 10, 20};
    private static final double[] WEIGHTS = {0.5, 0.25, 0.75, 0.2, 0.8, 0.4, 0.6, 0.9, 1.0};

    private final FuzzSettings settings;

    public ProgramGenerator(FuzzSettings settings) {
        this.settings = settings;
    }

    /** The program of one seed. */
    public Program generate(long seed) {
        return new Build(new Random(seed)).program("fuzz_" + Long.toHexString(seed).toLowerCase(java.util.Locale.ROOT));
    }

    /** A linguistic input: its universe (for placing terms) and its terms. */
    private record In(String name, double lo, double hi, List<Term> terms) {
    }

    /** An output and how it is defuzzified. */
    private record Out(String name, boolean singletons, List<String> terms) {
    }

    /** One program under construction. */
    private final class Build {
        private final Random r;
        private final int size;
        private final List<Variable> inputs = new ArrayList<>();
        private final List<Variable> outputs = new ArrayList<>();
        private final List<Variable> locals = new ArrayList<>();
        private final List<Fuzzification> fuzzifications = new ArrayList<>();
        private final List<Defuzzification> defuzzifications = new ArrayList<>();
        private final List<In> ins = new ArrayList<>();
        private final List<Out> outs = new ArrayList<>();
        /** Inputs whose value is read as a degree (weights, variable subconditions, variable degrees). */
        private final List<String> degreeInputs = new ArrayList<>();
        private final Map<String, Integer> serials = new LinkedHashMap<>();
        private boolean useOr;
        private boolean useNot;
        private boolean useParens;
        private boolean condVariable;
        private boolean withConst;
        private boolean withVar;
        private boolean multiConclusion;

        Build(Random r) {
            this.r = r;
            double s = r.nextDouble();
            this.size = s < 0.3 ? 0 : s < 0.65 ? 1 : s < 0.9 ? 2 : 3;
        }

        Program program(String name) {
            useOr = chance(Math.max(Math.max(w(Feature.E_OR_MAX, 0.3), w(Feature.E_OR_ASUM, 0.3)), w(Feature.E_OR_BSUM, 0.3)));
            useNot = chance(w(Feature.E_NOT, 0.3));
            useParens = chance(w(Feature.E_PARENS, 0.3));
            condVariable = chance(w(Feature.E_COND_VARIABLE, 0.15));
            withConst = chance(w(Feature.E_WITH_CONST, 0.25));
            withVar = chance(w(Feature.E_WITH_VAR, 0.15));
            multiConclusion = chance(w(Feature.E_SUBCONCLUSIONS, 0.25));
            int nIn = between(1, new int[] {2, 3, 4, 8}[size]);
            for (int i = 0; i < nIn; i++) {
                input();
            }
            int nOut = between(1, new int[] {1, 2, 3, 4}[size]);
            for (int i = 0; i < nOut; i++) {
                output();
            }
            boolean local = chance(w(Feature.E_VAR_LOCAL, 0.15));
            int nBlocks = local ? between(2, 3) : chance(w(Feature.E_RULEBLOCKS, 0.2)) ? between(2, 3) : 1;
            if (local) {
                String l = serial("loc");
                locals.add(new Variable(l, VariableKind.LOCAL, DataType.REAL, Optional.empty(), AT));
            }
            AccumulationMethod accu = pick(new AccumulationMethod[] {AccumulationMethod.MAX, AccumulationMethod.BSUM, AccumulationMethod.NSUM},
                    w(Feature.B_ACCU_MAX, 1), w(Feature.E_ACCU_BSUM, 0.3), w(Feature.E_ACCU_NSUM, 0.3));
            List<RuleBlock> blocks = new ArrayList<>();
            for (int b = 0; b < nBlocks; b++) {
                blocks.add(ruleBlock(b, nBlocks, accu));
            }
            List<Variable> variables = new ArrayList<>(inputs);
            variables.addAll(outputs);
            variables.addAll(locals);
            FunctionBlock fb = new FunctionBlock(name, variables, fuzzifications, defuzzifications, blocks, List.of(), AT);
            return new Program("fuzz.fcl", List.of(fb));
        }

        // ---- inputs

        private void input() {
            String name = serial("in");
            inputs.add(new Variable(name, VariableKind.INPUT, type(), Optional.empty(), AT));
            double[] scale = SCALES[r.nextInt(SCALES.length)];
            double lo = scale[0];
            double hi = scale[1];
            int grid = GRIDS[r.nextInt(GRIDS.length)];
            int nTerms = between(1, new int[] {2, 3, 5, 7}[size]);
            List<Term> terms = new ArrayList<>();
            for (int t = 0; t < nTerms; t++) {
                terms.add(new Term("t" + (t + 1), new MembershipFunction.Points(inputPoints(lo, hi, grid, t, nTerms)), AT));
            }
            fuzzifications.add(new Fuzzification(name, terms, AT));
            ins.add(new In(name, lo, hi, terms));
        }

        /** The points of input term {@code t} of {@code n}: centred on its share of the universe. */
        private List<Point> inputPoints(double lo, double hi, int grid, int t, int n) {
            double step = (hi - lo) / grid;
            int centre = (int) Math.round((t + 0.5) * grid / n + r.nextGaussian());
            centre = Math.max(0, Math.min(grid, centre));
            int left = between(1, Math.max(1, grid / n + 1));
            int right = between(1, Math.max(1, grid / n + 1));
            double c = grid(lo, step, centre);
            double a = grid(lo, step, centre - left);
            double b = grid(lo, step, centre + right);
            List<double[]> xy = new ArrayList<>();
            double shape = r.nextDouble();
            if (chance(w(Feature.O_MANY_POINTS, 0.12))) {
                int k = between(5, 7);
                double x = grid(lo, step, centre - left - 1);
                for (int i = 0; i < k; i++) {
                    xy.add(new double[] {x, i == 0 || i == k - 1 ? 0 : degree()});
                    x = round(x + step * between(0, 2) / 2.0 + (i == 0 ? 0 : 0));
                    if (xy.size() > 1 && xy.get(xy.size() - 1)[0] < xy.get(xy.size() - 2)[0]) {
                        xy.get(xy.size() - 1)[0] = xy.get(xy.size() - 2)[0];
                    }
                }
            } else if (chance(w(Feature.E_IN_TERM_4, 0.3))) {
                double d = grid(lo, step, centre + between(0, 2));
                double e = round(Math.max(d, b) + step);
                xy.add(new double[] {a, 0});
                xy.add(new double[] {c, 1});
                xy.add(new double[] {d, 1});
                xy.add(new double[] {e, 0});
            } else if (t == 0 && shape < 0.4) {
                xy.add(new double[] {c, 1});
                xy.add(new double[] {b, 0});
            } else if (t == n - 1 && shape < 0.4) {
                xy.add(new double[] {a, 0});
                xy.add(new double[] {c, 1});
            } else if (shape < 0.08) {
                xy.add(new double[] {c, 0});          // a vertical edge: 0 up to c, then falling
                xy.add(new double[] {c, 1});
                xy.add(new double[] {b, 0});
            } else {
                xy.add(new double[] {a, 0});
                xy.add(new double[] {c, 1});
                xy.add(new double[] {b, 0});
            }
            if (chance(w(Feature.O_DEGREES_0_1, 0.12))) {
                for (double[] p : xy) {
                    if (p[1] == 1) {
                        p[1] = new double[] {0.5, 0.8, 0.6, 0.25}[r.nextInt(4)];
                    }
                }
            }
            List<Point> points = new ArrayList<>();
            boolean variableX = chance(w(Feature.E_TERM_VARIABLE_POINT, 0.12) / 2);
            boolean variableDegree = chance(w(Feature.O_VAR_DEGREE, 0.1) / 2);
            int peak = peakIndex(xy);
            for (int i = 0; i < xy.size(); i++) {
                double[] p = xy.get(i);
                Operand x = Literal.of(p[0]);
                Operand y = Literal.of(p[1]);
                if (i == peak && variableX && xy.size() >= 3) {
                    x = new VariableRef(parameterInput(), AT);
                    variableX = false;
                }
                if (i == peak && variableDegree && p[1] > 0) {
                    y = new VariableRef(degreeInput(), AT);
                    variableDegree = false;
                }
                points.add(new Point(x, y, AT));
            }
            return points;
        }

        private int peakIndex(List<double[]> xy) {
            int best = 0;
            for (int i = 0; i < xy.size(); i++) {
                if (xy.get(i)[1] > xy.get(best)[1]) {
                    best = i;
                }
            }
            return best;
        }

        private double degree() {
            return chance(w(Feature.O_DEGREES_0_1, 0.12)) ? new double[] {0.5, 0.3, 0.75}[r.nextInt(3)] : r.nextBoolean() ? 1 : 0;
        }

        private String parameterInput() {
            String name = serial("p");
            inputs.add(new Variable(name, VariableKind.INPUT, DataType.REAL, Optional.empty(), AT));
            return name;
        }

        private String degreeInput() {
            String name = serial("w");
            inputs.add(new Variable(name, VariableKind.INPUT, DataType.REAL, Optional.empty(), AT));
            degreeInputs.add(name);
            return name;
        }

        // ---- outputs

        private void output() {
            String name = serial("out");
            double[] scale = SCALES[r.nextInt(SCALES.length)];
            double lo = scale[0];
            double hi = scale[1];
            int grid = GRIDS[r.nextInt(GRIDS.length)];
            double step = (hi - lo) / grid;
            double continuous = Math.max(Math.max(w(Feature.E_COG, 0.5), w(Feature.E_COA, 0.5)),
                    Math.max(Math.max(w(Feature.E_LM, 0.5), w(Feature.E_RM, 0.5)), w(Feature.O_MOM, 0.5)));
            continuous = Math.max(continuous, Math.max(w(Feature.E_RANGE, 0.5), w(Feature.E_OUT_TERM_4, 0.5)));
            boolean singletons = !chance(Math.min(0.85, continuous));
            int nTerms = between(singletons ? 2 : 1, new int[] {2, 3, 4, 6}[size]);
            List<Term> terms = new ArrayList<>();
            Optional<Range> range = Optional.empty();
            DefuzzificationMethod method;
            if (singletons) {
                method = DefuzzificationMethod.COGS;
                List<Integer> used = new ArrayList<>();
                for (int t = 0; t < nTerms; t++) {
                    int k = r.nextInt(grid + 1);
                    if (used.contains(k)) {
                        continue;
                    }
                    used.add(k);
                    Operand value = chance(w(Feature.E_TERM_VARIABLE_POINT, 0.12) / 2)
                            ? new VariableRef(parameterInput(), AT) : Literal.of(grid(lo, step, k));
                    terms.add(new Term("s" + used.size(), new MembershipFunction.Singleton(value), AT));
                }
            } else {
                method = pick(new DefuzzificationMethod[] {DefuzzificationMethod.COG, DefuzzificationMethod.COA,
                    DefuzzificationMethod.LM, DefuzzificationMethod.RM, DefuzzificationMethod.MOM},
                        w(Feature.E_COG, 0.5), w(Feature.E_COA, 0.5), w(Feature.E_LM, 0.5), w(Feature.E_RM, 0.5),
                        w(Feature.O_MOM, 0.3));
                boolean withRange = chance(w(Feature.E_RANGE, 0.4));
                if (withRange) {
                    double rlo = lo;
                    double rhi = hi;
                    if (chance(0.3)) {       // a RANGE cutting into the outer terms
                        rlo = grid(lo, step, 1);
                        rhi = grid(lo, step, grid - 1);
                    }
                    range = Optional.of(new Range(Literal.of(rlo), Literal.of(rhi), AT));
                }
                for (int t = 0; t < nTerms; t++) {
                    terms.add(new Term("t" + (t + 1), new MembershipFunction.Points(
                            outputPoints(lo, step, grid, t, nTerms, withRange)), AT));
                }
            }
            boolean nc = chance(w(Feature.B_DEFAULT_NC, 0.25));
            DefaultValue dflt = nc ? new DefaultValue.NoChange(AT)
                    : new DefaultValue.Constant(Literal.of(chance(0.5) ? 0 : grid(lo, step, r.nextInt(grid + 1))), AT);
            Optional<Literal> initial = nc && chance(0.2) ? Optional.of(Literal.of(grid(lo, step, r.nextInt(grid + 1))))
                    : Optional.empty();
            outputs.add(new Variable(name, VariableKind.OUTPUT, type(), initial, AT));
            defuzzifications.add(new Defuzzification(name, range, terms,
                    Optional.of(new Located<>(method, AT)), Optional.of(dflt), AT));
            outs.add(new Out(name, singletons, terms.stream().map(Term::name).toList()));
        }

        /** Output term points: zero at both ends unless a RANGE bounds the set. */
        private List<Point> outputPoints(double lo, double step, int grid, int t, int n, boolean withRange) {
            int centre = Math.max(0, Math.min(grid, (int) Math.round((t + 0.5) * grid / n + r.nextGaussian())));
            int left = between(1, Math.max(1, grid / n + 1));
            int right = between(1, Math.max(1, grid / n + 1));
            double a = grid(lo, step, centre - left);
            double c = grid(lo, step, centre);
            double b = grid(lo, step, centre + right);
            double top = chance(w(Feature.O_DEGREES_0_1, 0.12)) ? new double[] {0.5, 0.8, 0.4}[r.nextInt(3)] : 1;
            List<double[]> xy = new ArrayList<>();
            if (withRange && t == 0 && chance(0.4)) {
                xy.add(new double[] {c, top});
                xy.add(new double[] {b, 0});
            } else if (withRange && t == n - 1 && chance(0.4)) {
                xy.add(new double[] {a, 0});
                xy.add(new double[] {c, top});
            } else if (chance(w(Feature.O_MANY_POINTS, 0.12))) {
                xy.add(new double[] {a, 0});
                xy.add(new double[] {round((a + c) / 2), top / 2});
                xy.add(new double[] {c, top});
                xy.add(new double[] {round(c + step / 2), top});
                xy.add(new double[] {round(b + step / 2), 0});
            } else if (chance(0.35)) {
                xy.add(new double[] {a, 0});
                xy.add(new double[] {c, top});
                xy.add(new double[] {round(c + step * between(1, 2)), top});
                xy.add(new double[] {round(b + step * 2), 0});
            } else {
                xy.add(new double[] {a, 0});
                xy.add(new double[] {c, top});
                xy.add(new double[] {b, 0});
            }
            return xy.stream().map(p -> new Point(Literal.of(p[0]), Literal.of(p[1]), AT)).toList();
        }

        // ---- rules

        private RuleBlock ruleBlock(int index, int count, AccumulationMethod accu) {
            AndAlgorithm and = pick(AndAlgorithm.values(),
                    Math.max(w(Feature.B_AND_MIN, 1), useOr ? w(Feature.E_OR_MAX, 0.3) : 0),
                    Math.max(w(Feature.E_AND_PROD, 0.3), useOr ? w(Feature.E_OR_ASUM, 0.3) : 0),
                    Math.max(w(Feature.E_AND_BDIF, 0.3), useOr ? w(Feature.E_OR_BSUM, 0.3) : 0));
            if (!settings.allows(Feature.E_AND_PROD) && !settings.allows(Feature.E_AND_BDIF)) {
                and = AndAlgorithm.MIN;
            }
            Optional<Located<AndAlgorithm>> andDecl = Optional.of(new Located<>(and, AT));
            Optional<Located<OrAlgorithm>> orDecl = Optional.empty();
            if (useOr && chance(0.6)) {
                orDecl = Optional.of(new Located<>(and.pair(), AT));
                if (chance(0.4)) {
                    andDecl = Optional.empty();
                }
            }
            double actMin = w(Feature.E_ACT_MIN, 0.2);
            double actProd = w(Feature.E_ACT_PROD, 0.25);
            Optional<Located<ActivationMethod>> act = Optional.empty();
            if (chance(Math.max(actMin, actProd))) {
                act = Optional.of(new Located<>(pick(new ActivationMethod[] {ActivationMethod.MIN, ActivationMethod.PROD},
                        actMin, actProd), AT));
            }
            int nRules = between(1, new int[] {2, 4, 8, 20}[size]);
            List<Rule> rules = new ArrayList<>();
            boolean writesLocal = !locals.isEmpty() && index == 0;
            boolean readsLocal = !locals.isEmpty() && index > 0;
            for (int i = 0; i < nRules; i++) {
                List<Subconclusion> conclusion = new ArrayList<>();
                if (writesLocal && (i == 0 || chance(0.3))) {
                    conclusion.add(new Subconclusion(locals.get(0).name(), Optional.empty(), weight(), AT));
                }
                if (conclusion.isEmpty() || chance(0.5)) {
                    // every output is concluded in the last block at least once
                    int first = index == count - 1 && i < outs.size() ? i : r.nextInt(outs.size());
                    List<Integer> targets = new ArrayList<>(List.of(first));
                    if (multiConclusion && chance(0.5)) {
                        // another output, or the same one again with another term (both are accumulated)
                        targets.add(r.nextInt(outs.size()));
                    }
                    for (int o : targets) {
                        Out out = outs.get(o);
                        String term = out.terms().get(r.nextInt(out.terms().size()));
                        conclusion.add(new Subconclusion(out.name(), Optional.of(term), weight(), AT));
                    }
                }
                if (multiConclusion && !locals.isEmpty() && index == 0 && conclusion.size() == 1 && chance(0.2)) {
                    conclusion.add(new Subconclusion(locals.get(0).name(), Optional.empty(), Optional.empty(), AT));
                }
                rules.add(new Rule(Integer.toString(i + 1), condition(readsLocal && i == 0), dedupe(conclusion), AT));
            }
            if (index == count - 1) {
                for (int i = nRules; i < outs.size(); i++) {      // fewer rules than outputs: one more rule per output
                    Out out = outs.get(i);
                    rules.add(new Rule(Integer.toString(i + 1), condition(false),
                            List.of(new Subconclusion(out.name(), Optional.of(out.terms().get(0)), Optional.empty(), AT)), AT));
                }
            }
            return new RuleBlock("rb" + (index + 1), andDecl, orDecl, act,
                    Optional.of(new Located<>(accu, AT)), rules, AT);
        }

        /** One subconclusion per variable and term (a bare variable is assigned once). */
        private List<Subconclusion> dedupe(List<Subconclusion> parts) {
            List<Subconclusion> out = new ArrayList<>();
            for (Subconclusion s : parts) {
                if (out.stream().noneMatch(o -> o.variable().equals(s.variable())
                        && (o.term().isEmpty() || s.term().isEmpty() || o.term().equals(s.term())))) {
                    out.add(s);
                }
            }
            return out;
        }

        private Optional<Operand> weight() {
            if (withVar && chance(0.3)) {
                return Optional.of(new VariableRef(degreeInputs.isEmpty() || chance(0.3) ? degreeInput()
                        : degreeInputs.get(r.nextInt(degreeInputs.size())), AT));
            }
            if (withConst && chance(0.4)) {
                return Optional.of(Literal.of(WEIGHTS[r.nextInt(WEIGHTS.length)]));
            }
            return Optional.empty();
        }

        private Condition condition(boolean readLocal) {
            int leaves = between(1, new int[] {2, 3, 4, 6}[size]);
            Condition c = disjunction(leaves, 2);
            if (readLocal) {
                Condition local = new Condition.VariableSubcondition(locals.get(0).name(), AT);
                return c instanceof Condition.Or
                        ? new Condition.And(List.of(local, new Condition.Parenthesized(c, AT)), AT)
                        : new Condition.And(concat(local, c), AT);
            }
            return c;
        }

        private List<Condition> concat(Condition first, Condition rest) {
            List<Condition> out = new ArrayList<>(List.of(first));
            if (rest instanceof Condition.And a) {
                out.addAll(a.operands());
            } else {
                out.add(rest);
            }
            return out;
        }

        private Condition disjunction(int leaves, int depth) {
            if (useOr && leaves >= 2 && chance(0.5)) {
                List<Integer> parts = split(leaves);
                return new Condition.Or(parts.stream().map(n -> conjunction(n, depth)).toList(), AT);
            }
            return conjunction(leaves, depth);
        }

        private Condition conjunction(int leaves, int depth) {
            if (leaves >= 2) {
                List<Integer> parts = useParens && depth > 0 ? split(leaves) : java.util.Collections.nCopies(leaves, 1);
                return new Condition.And(parts.stream().map(n -> factor(n, depth)).toList(), AT);
            }
            return factor(1, depth);
        }

        private Condition factor(int leaves, int depth) {
            Condition primary = primary(leaves, depth);
            if (useNot && chance(0.15)) {
                return new Condition.Not(primary instanceof Condition.Parenthesized ? primary
                        : new Condition.Parenthesized(primary, AT), AT);
            }
            return primary;
        }

        private Condition primary(int leaves, int depth) {
            if (leaves >= 2) {
                return new Condition.Parenthesized(disjunction(leaves, depth - 1), AT);
            }
            if (useParens && chance(0.1)) {
                return new Condition.Parenthesized(leaf(), AT);
            }
            return leaf();
        }

        private Condition leaf() {
            if (condVariable && chance(0.25)) {
                String name = degreeInputs.isEmpty() || chance(0.4) ? degreeInput() : degreeInputs.get(r.nextInt(degreeInputs.size()));
                return new Condition.VariableSubcondition(name, AT);
            }
            In in = ins.get(r.nextInt(ins.size()));
            Term t = in.terms().get(r.nextInt(in.terms().size()));
            return new Condition.TermSubcondition(in.name(), t.name(), useNot && chance(0.15), AT);
        }

        /** {@code n} (at least 2) split into 2 or more positive parts. */
        private List<Integer> split(int n) {
            int k = between(2, Math.min(n, 3));
            List<Integer> parts = new ArrayList<>(java.util.Collections.nCopies(k, 1));
            for (int i = k; i < n; i++) {
                int j = r.nextInt(k);
                parts.set(j, parts.get(j) + 1);
            }
            return parts;
        }

        // ---- helpers

        private DataType type() {
            return chance(0.15) ? DataType.LREAL : DataType.REAL;
        }

        private double w(Feature f, double base) {
            return settings.weight(f, base);
        }

        private String serial(String prefix) {
            int n = serials.merge(prefix, 1, Integer::sum);
            return prefix + n;
        }

        private boolean chance(double p) {
            return r.nextDouble() < p;
        }

        private int between(int lo, int hi) {
            return hi <= lo ? lo : lo + r.nextInt(hi - lo + 1);
        }

        private <T> T pick(T[] values, double... weights) {
            double total = 0;
            for (double w : weights) {
                total += w;
            }
            if (total <= 0) {
                return values[0];
            }
            double x = r.nextDouble() * total;
            for (int i = 0; i < values.length; i++) {
                x -= weights[i];
                if (x < 0) {
                    return values[i];
                }
            }
            return values[values.length - 1];
        }
    }

    private static double grid(double lo, double step, int k) {
        return round(lo + step * k);
    }

    /** Ten significant digits: grid arithmetic leaves no 0.30000000000000004 in the text. */
    static double round(double v) {
        return v == 0 ? 0 : new BigDecimal(v).round(new MathContext(10)).doubleValue();
    }
}
