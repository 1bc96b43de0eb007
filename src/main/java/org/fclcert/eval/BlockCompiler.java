package org.fclcert.eval;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.eval.BlockPlan.OutputPlan;
import org.fclcert.eval.BlockPlan.RuleBlockPlan;
import org.fclcert.eval.BlockPlan.SubconclusionPlan;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Operand;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * Compiles one checked function block into a {@link BlockPlan}. A program that the checks would
 * reject (unknown names, no METHOD, mixed output terms) is refused with IllegalArgumentException;
 * settings whose absence the checks report but which have an evident default (AND/OR pair, ACT MIN,
 * ACCU MAX, DEFAULT 0) get that default.
 */
final class BlockCompiler {
    private final FunctionBlock fb;
    private final Map<String, Integer> slots = new HashMap<>();
    private final List<Shape> shapes = new ArrayList<>();
    private final Map<String, Integer> termIndex = new HashMap<>();
    /** Per output variable key: its contributions (id, term index within the output, PROD?). */
    private final Map<String, List<int[]>> contributions = new HashMap<>();
    private final Map<String, AccumulationMethod> outputAccumulation = new HashMap<>();
    private int contributionCount;
    private int inputTermCount;
    /** Per contribution id: the hedges of its subconclusion (dialects), or null. */
    private final Map<Integer, org.fclcert.model.Hedge[]> hedges = new HashMap<>();
    /** 'output IS term' in conditions (dialects): key output\0term to its degree entry after the input terms'. */
    private final Map<String, Integer> chained = new LinkedHashMap<>();
    /** DEFUZZIFY blocks by variable key (the first of duplicates, as FunctionBlock.defuzzification finds it). */
    private final Map<String, Defuzzification> defuzzifications = new HashMap<>();
    private final Map<String, Map<String, Integer>> termPositions = new HashMap<>();

    /** jFuzzyLogic's reading of 'output IS term' in a condition (O-OUTPUT-VALUE-CONDITION), else fuzzylite's. */
    private final boolean valueConditions;

    private BlockCompiler(FunctionBlock fb, boolean valueConditions) {
        this.fb = fb;
        this.valueConditions = valueConditions;
        // a map, not a search per subconclusion: programs with 10^5 outputs would compile in quadratic time
        fb.defuzzifications().forEach(d -> defuzzifications.putIfAbsent(Names.key(d.variable()), d));
    }

    static BlockPlan compile(FunctionBlock fb) {
        return compile(fb, false);
    }

    static BlockPlan compile(FunctionBlock fb, boolean valueConditions) {
        return new BlockCompiler(fb, valueConditions).build();
    }

    private BlockPlan build() {
        BlockPlan.Builder b = new BlockPlan.Builder();
        b.name = fb.name();
        variables(b);
        inputTerms(b);
        b.ruleBlocks = fb.ruleBlocks().stream().map(this::ruleBlock).toArray(RuleBlockPlan[]::new);
        b.outputs = fb.defuzzifications().stream().map(this::output).toArray(OutputPlan[]::new);
        b.smoothOutputs = new boolean[b.outputs.length];
        for (int i = 0; i < b.outputs.length; i++) {
            OutputPlan o = b.outputs[i];
            boolean smooth = !o.singletons() && (o.accumulation() == AccumulationMethod.PROBOR
                    || o.accumulation().otherNorm().isPresent()
                    || java.util.Arrays.stream(o.contributionActivation()).anyMatch(a -> !a.standard()));
            for (int s : o.termShapes()) {
                smooth |= shapes.get(s).kind != null;
            }
            // Tsukamoto's method inverts each term at its degree: no accumulated set to integrate
            b.smoothOutputs[i] = smooth && o.method() != DefuzzificationMethod.TSUKAMOTO;
        }
        b.shapes = shapes.toArray(Shape[]::new);
        b.contributionCount = contributionCount;
        chainedDegrees(b);
        if (!hedges.isEmpty()) {
            b.contributionHedges = new org.fclcert.model.Hedge[contributionCount][];
            hedges.forEach((id, h) -> b.contributionHedges[id] = h);
        }
        return new BlockPlan(b);
    }

    private void variables(BlockPlan.Builder b) {
        List<Variable> vars = fb.variables();
        int n = vars.size();
        b.variableNames = new String[n];
        b.types = new org.fclcert.model.DataType[n];
        b.isInput = new boolean[n];
        b.initialValues = new double[n];
        b.slotByName = new HashMap<>();
        b.inputNames = new ArrayList<>();
        b.outputNames = new ArrayList<>();
        List<Integer> outputSlots = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Variable v = vars.get(i);
            b.variableNames[i] = v.name();
            b.types[i] = v.type();
            b.isInput[i] = v.kind() == VariableKind.INPUT;
            double init = v.initialValue().map(Literal::value).orElse(0.0);
            b.initialValues[i] = v.type().isInteger() ? Conversions.roundHalfAwayFromZero(init) : init;
            slots.put(Names.key(v.name()), i);
            b.slotByName.put(v.name(), i);
            b.slotByName.put(Names.key(v.name()), i);
            if (v.kind() == VariableKind.INPUT) {
                b.inputNames.add(v.name());
            } else if (v.kind() == VariableKind.OUTPUT) {
                b.outputNames.add(v.name());
                outputSlots.add(i);
            }
        }
        b.outputSlots = outputSlots.stream().mapToInt(Integer::intValue).toArray();
    }

    private void inputTerms(BlockPlan.Builder b) {
        List<Integer> varSlot = new ArrayList<>();
        List<Integer> shape = new ArrayList<>();
        List<String> varName = new ArrayList<>();
        List<String> name = new ArrayList<>();
        for (Fuzzification f : fb.fuzzifications()) {
            int slot = slot(f.variable());
            for (Term t : f.terms()) {
                termIndex.put(Names.key(f.variable()) + '\0' + Names.key(t.name()), varSlot.size());
                varSlot.add(slot);
                shape.add(addShape(t));
                varName.add(fb.variables().get(slot).name());
                name.add(t.name());
            }
        }
        b.termVariableSlot = varSlot.stream().mapToInt(Integer::intValue).toArray();
        b.termShape = shape.stream().mapToInt(Integer::intValue).toArray();
        b.termVariableName = varName.toArray(String[]::new);
        b.termName = name.toArray(String[]::new);
        inputTermCount = varSlot.size();
    }

    /**
     * Which contribution feeds which chained degree, and with which accumulation; or, in jFuzzyLogic's reading, which
     * output term is taken at the output's value when the evaluation begins.
     */
    private void chainedDegrees(BlockPlan.Builder b) {
        b.chainedTerms = chained.size();
        b.chainedDegree = new int[contributionCount];
        b.chainedAccumulation = new AccumulationMethod[contributionCount];
        java.util.Arrays.fill(b.chainedDegree, -1);
        if (valueConditions) {
            b.valueTermShape = new int[chained.size()];
            b.valueTermSlot = new int[chained.size()];
            b.valueTermStart = new double[chained.size()];
        }
        for (Map.Entry<String, Integer> e : chained.entrySet()) {
            String output = e.getKey().substring(0, e.getKey().indexOf('\0'));
            String term = e.getKey().substring(e.getKey().indexOf('\0') + 1);
            Defuzzification d = fb.defuzzification(output).orElseThrow();
            int position = positions(d).getOrDefault(term, -1);
            if (valueConditions) {
                int k = e.getValue() - inputTermCount;
                OutputPlan o = java.util.Arrays.stream(b.outputs).filter(x -> Names.same(x.variable(), d.variable()))
                        .findFirst().orElseThrow();
                b.valueTermShape[k] = o.termShapes()[position];
                b.valueTermSlot[k] = o.slot();
                // jFuzzyLogic sets an output to its numeric DEFAULT before the rules run; with NC it keeps its value
                b.valueTermStart[k] = o.noChange() ? Double.NaN : o.defaultValue();
                continue;
            }
            for (int[] c : contributions.getOrDefault(output, List.of())) {
                if (c[1] == position) {
                    b.chainedDegree[c[0]] = e.getValue();
                    b.chainedAccumulation[c[0]] = outputAccumulation.getOrDefault(output, AccumulationMethod.MAX);
                }
            }
        }
    }

    private int addShape(Term t) {
        MembershipFunction f = t.function();
        Shape s;
        if (f instanceof MembershipFunction.NamedShape named) {
            if (named.parameters().size() != named.kind().arity()) {
                throw new IllegalArgumentException("term " + t.name() + ": " + named.kind() + " takes "
                        + named.kind().arity() + " parameters");
            }
            java.util.Optional<List<Point>> linear = named.points();
            if (linear.isPresent()) {
                f = new MembershipFunction.Points(linear.get());
            } else {
                shapes.add(new Shape(named.kind(), named.values()));
                return shapes.size() - 1;
            }
        }
        if (f instanceof MembershipFunction.Computed computed) {
            shapes.add(new Shape(computedValue(computed.value())));
            return shapes.size() - 1;
        }
        if (f instanceof MembershipFunction.Singleton single) {
            s = new Shape(true, new double[] {constant(single.value())}, new int[] {slotOrNone(single.value())},
                    new double[] {1.0}, new int[] {-1});
        } else {
            List<Point> pts = ((MembershipFunction.Points) f).points();
            int n = pts.size();
            if (n == 0) {
                throw new IllegalArgumentException("term " + t.name() + " has no points");
            }
            double[] xc = new double[n];
            int[] xs = new int[n];
            double[] yc = new double[n];
            int[] ys = new int[n];
            for (int i = 0; i < n; i++) {
                xc[i] = constant(pts.get(i).x());
                xs[i] = slotOrNone(pts.get(i).x());
                yc[i] = constant(pts.get(i).degree());
                ys[i] = slotOrNone(pts.get(i).degree());
            }
            s = new Shape(false, xc, xs, yc, ys);
        }
        shapes.add(s);
        return shapes.size() - 1;
    }

    /** A Takagi–Sugeno term's value over the variables' slots (names resolved once, here). */
    private java.util.function.ToDoubleFunction<double[]> computedValue(org.fclcert.model.Expression e) {
        Map<String, Integer> used = new HashMap<>();
        for (String v : e.variables()) {
            used.put(v, slot(v));
        }
        return values -> e.evaluate(name -> values[used.get(name)]);
    }

    private RuleBlockPlan ruleBlock(RuleBlock rb) {
        AndAlgorithm and = rb.and().map(Located::value)
                .orElse(rb.or().map(o -> o.value().pair()).orElse(AndAlgorithm.MIN));
        OrAlgorithm or = rb.or().map(Located::value).orElse(and.pair());
        ActivationMethod act = rb.activation().map(Located::value).orElse(ActivationMethod.MIN);
        AccumulationMethod accu = rb.accumulation().map(Located::value).orElse(AccumulationMethod.MAX);
        int n = rb.rules().size();
        String[] names = new String[n];
        ConditionCode[] conditions = new ConditionCode[n];
        SubconclusionPlan[][] conclusions = new SubconclusionPlan[n][];
        Map<String, Integer> bareTargets = new LinkedHashMap<>();
        for (int r = 0; r < n; r++) {
            Rule rule = rb.rules().get(r);
            names[r] = rule.name();
            conditions[r] = ConditionCode.compile(rule.condition(), this::termIndexOf, this::slot);
            conclusions[r] = rule.conclusion().stream()
                    .map(s -> subconclusion(s, act, accu, bareTargets)).toArray(SubconclusionPlan[]::new);
        }
        int[] bareSlots = bareTargets.keySet().stream().mapToInt(this::slot).toArray();
        return new RuleBlockPlan(rb.name(), and, or, act, accu, names, conditions, conclusions, bareSlots);
    }

    private SubconclusionPlan subconclusion(Subconclusion s, ActivationMethod act, AccumulationMethod accu,
            Map<String, Integer> bareTargets) {
        double wConst = s.weight().map(BlockCompiler::constant).orElse(1.0);
        int wSlot = s.weight().map(this::slotOrNone).orElse(-1);
        String variable = fb.variables().get(slot(s.variable())).name();
        if (s.term().isEmpty()) {
            int target = bareTargets.computeIfAbsent(Names.key(s.variable()), k -> bareTargets.size());
            return new SubconclusionPlan(variable, null, -1, target, wConst, wSlot);
        }
        String key = Names.key(s.variable());
        Defuzzification d = java.util.Optional.ofNullable(defuzzifications.get(key)).orElseThrow(
                () -> new IllegalArgumentException("no DEFUZZIFY for " + s.variable()));
        int termInOutput = termPositions.computeIfAbsent(key, k -> positions(d))
                .getOrDefault(Names.key(s.term().get()), -1);
        if (termInOutput < 0) {
            throw new IllegalArgumentException("output " + d.variable() + " has no term " + s.term().get());
        }
        int id = contributionCount++;
        if (!s.hedges().isEmpty()) {
            hedges.put(id, s.hedges().toArray(org.fclcert.model.Hedge[]::new));
        }
        contributions.computeIfAbsent(key, k -> new ArrayList<>())
                .add(new int[] {id, termInOutput, act.ordinal()});
        outputAccumulation.putIfAbsent(key, accu);
        return new SubconclusionPlan(variable, d.terms().get(termInOutput).name(), id, -1, wConst, wSlot);
    }

    private OutputPlan output(Defuzzification d) {
        String key = Names.key(d.variable());
        int slot = slot(d.variable());
        boolean singletons = !d.terms().isEmpty()
                && d.terms().stream().allMatch(BlockCompiler::singletonLike);
        boolean points = d.terms().stream().noneMatch(BlockCompiler::singletonLike);
        if (!singletons && !points) {
            throw new IllegalArgumentException("output " + d.variable() + " mixes singleton and point terms");
        }
        DefuzzificationMethod method = d.method().map(Located::value)
                .orElseThrow(() -> new IllegalArgumentException("output " + d.variable() + " has no METHOD"));
        if (singletons && method == DefuzzificationMethod.COA) {
            throw new IllegalArgumentException("CoA is not applicable to the singletons of " + d.variable());
        }
        if (!singletons && (method == DefuzzificationMethod.COGS || method == DefuzzificationMethod.COGSS)) {
            throw new IllegalArgumentException("CoGS needs singleton terms on " + d.variable());
        }
        if (method == DefuzzificationMethod.TSUKAMOTO && !d.terms().stream().allMatch(BlockCompiler::monotonic)) {
            throw new IllegalArgumentException("Tsukamoto's method needs monotonic terms on " + d.variable());
        }
        int[] termShapes = d.terms().stream().mapToInt(this::addShape).toArray();
        int maxPoints = d.terms().stream().mapToInt(BlockCompiler::pointCount).sum();
        List<int[]> cs = contributions.getOrDefault(key, List.of());
        boolean[] prod = new boolean[cs.size()];
        ActivationMethod[] activation = new ActivationMethod[cs.size()];
        for (int i = 0; i < prod.length; i++) {
            activation[i] = ActivationMethod.values()[cs.get(i)[2]];
            prod[i] = activation[i] == ActivationMethod.PROD;
        }
        boolean nc = d.defaultValue().map(v -> v instanceof DefaultValue.NoChange).orElse(false);
        double def = d.defaultValue().filter(v -> v instanceof DefaultValue.Constant)
                .map(v -> ((DefaultValue.Constant) v).value().value()).orElse(0.0);
        return new OutputPlan(fb.variables().get(slot).name(), slot, method, singletons,
                d.range().isPresent(), d.range().map(r -> r.min().value()).orElse(0.0),
                d.range().map(r -> r.max().value()).orElse(0.0), termShapes,
                d.terms().stream().map(Term::name).toArray(String[]::new), nc, def,
                outputAccumulation.getOrDefault(key, AccumulationMethod.MAX),
                cs.stream().mapToInt(c -> c[0]).toArray(), cs.stream().mapToInt(c -> c[1]).toArray(), prod,
                maxPoints, activation);
    }

    /** A term Tsukamoto's method can invert: a monotonic named shape, or points rising or falling throughout. */
    private static boolean monotonic(Term t) {
        MembershipFunction f = t.function();
        if (f instanceof MembershipFunction.NamedShape named) {
            return named.kind().monotonic() && named.parameters().size() == named.kind().arity();
        }
        if (f instanceof MembershipFunction.Points p && p.points().stream().allMatch(x -> x.degree() instanceof Literal)) {
            boolean up = true;
            boolean down = true;
            for (int i = 0; i + 1 < p.points().size(); i++) {
                double a = ((Literal) p.points().get(i).degree()).value();
                double b = ((Literal) p.points().get(i + 1).degree()).value();
                up &= a <= b;
                down &= a >= b;
            }
            return up || down;
        }
        return false;
    }

    /** Singletons and Takagi–Sugeno terms (a singleton at a computed value). */
    private static boolean singletonLike(Term t) {
        return t.function() instanceof MembershipFunction.Singleton || t.function() instanceof MembershipFunction.Computed;
    }

    private static int pointCount(Term t) {
        if (t.function() instanceof MembershipFunction.NamedShape named) {
            return named.points().map(List::size).orElse(0);
        }
        return t.function() instanceof MembershipFunction.Points p ? p.points().size() : 1;
    }

    /** Term key to its position in the output (the first of duplicates), built once per output. */
    private static Map<String, Integer> positions(Defuzzification d) {
        Map<String, Integer> m = new HashMap<>();
        for (int i = 0; i < d.terms().size(); i++) {
            m.putIfAbsent(Names.key(d.terms().get(i).name()), i);
        }
        return m;
    }

    private int termIndexOf(String variable, String term) {
        Integer i = termIndex.get(Names.key(variable) + '\0' + Names.key(term));
        java.util.Optional<Defuzzification> output = fb.defuzzification(variable);
        if (i == null && output.isPresent() && output.get().terms().stream().anyMatch(t -> Names.same(t.name(), term))) {
            String key = Names.key(variable) + '\0' + Names.key(term);
            return chained.computeIfAbsent(key, k -> inputTermCount + chained.size());
        }
        if (i == null) {
            throw new IllegalArgumentException("no term " + term + " of input " + variable);
        }
        return i;
    }

    private int slot(String variable) {
        Integer s = slots.get(Names.key(variable));
        if (s == null) {
            throw new IllegalArgumentException("undeclared variable " + variable);
        }
        return s;
    }

    private int slotOrNone(Operand o) {
        return o instanceof VariableRef v ? slot(v.name()) : -1;
    }

    private static double constant(Operand o) {
        return o instanceof Literal l ? l.value() : 0.0;
    }
}
