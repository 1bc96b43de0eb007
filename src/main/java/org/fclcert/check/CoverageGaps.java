package org.fclcert.check;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.TreeSet;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Hedge;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * The regions of a rule block's input space where no rule fires (every rule's degree is 0), found exactly
 * from the piece-wise linear terms, not by sampling (docs/diagnostics.md, FCL-W005).
 *
 * <p>Why it is exact: along each input, the abscissas of its terms cut the line into points and open
 * intervals ("cells"). On an open cell every term is linear, so it is identically 0, identically 1 or strictly
 * between 0 and 1 throughout, and which of the three is read off its limits at the cell's ends (5.2.2, with
 * the vertical-edge reading of docs/semantics.md). Each operator maps those three classes to a set of classes
 * (MIN, PROD, MAX, ASUM: one class; BDIF, BSUM, NMIN, NMAX of two degrees strictly between 0 and 1: two, since
 * the outcome depends on the values), so a rule's degree is certainly 0 on a product of cells, certainly
 * positive, or undecided. A gap is a product of cells where every rule is certainly 0; a product where none
 * certainly fires but one is undecided is counted ({@link Result#undecidedCells}), never reported as a gap.
 *
 * <p>Limits: at most {@link #MAX_INPUTS} inputs in the block's conditions and {@link #MAX_WORK} cell-times-
 * condition-node evaluations; terms given by points, singletons or linear dialect shapes with constant
 * values. Beyond them the block is {@linkplain Result#analysed() not analysed}, with the reason.
 */
public final class CoverageGaps {
    /** The most inputs a block's conditions may use for its coverage to be analysed. */
    public static final int MAX_INPUTS = 6;
    /** The most (cells × condition nodes) one block's analysis may evaluate. */
    public static final long MAX_WORK = 4_000_000L;

    /** The three classes of a degree, as bits of a mask: 0, strictly between 0 and 1, 1. */
    private static final int ZERO = 1;
    private static final int MID = 2;
    private static final int ONE = 4;

    private CoverageGaps() {
    }

    /** One side of an interval: a value (possibly infinite) and whether the value itself belongs to it. */
    public record Interval(double low, boolean lowClosed, double high, boolean highClosed) {
        /** True for the whole line. */
        public boolean whole() {
            return low == Double.NEGATIVE_INFINITY && high == Double.POSITIVE_INFINITY;
        }

        /** Whether v lies in the interval, its ends included where they are closed. */
        public boolean contains(double v) {
            return (lowClosed ? v >= low : v > low) && (highClosed ? v <= high : v < high);
        }

        /** A single point, a gap of zero width. */
        public boolean point() {
            return low == high;
        }

        /** {@code [-5, -1]}, {@code (0, 2)}, {@code = 3} for a point, {@code (-inf, 0]}. */
        @Override
        public String toString() {
            if (point()) {
                return "= " + Describe.number(low);
            }
            return (lowClosed ? "[" : "(") + bound(low) + ", " + bound(high) + (highClosed ? "]" : ")");
        }

        private static String bound(double v) {
            return Double.isInfinite(v) ? (v < 0 ? "-inf" : "inf") : Describe.number(v);
        }
    }

    /** A box of the input space: one interval per analysed input, in {@link Result#inputs()} order. */
    public record Box(List<Interval> intervals) {
        public Box {
            intervals = List.copyOf(intervals);
        }
    }

    /**
     * @param inputs         the inputs the block's conditions use, in declaration order
     * @param gaps           disjoint boxes covering exactly the cells where no rule fires
     * @param undecidedCells cells where no rule certainly fires but one might (operators whose outcome depends
     *                       on the degrees' values, bare non-input variables)
     * @param notAnalysed    why the block was not analysed, empty when it was
     */
    public record Result(List<String> inputs, List<Box> gaps, long undecidedCells, Optional<String> notAnalysed) {
        public boolean analysed() {
            return notAnalysed.isEmpty();
        }

        static Result not(String why) {
            return new Result(List.of(), List.of(), 0, Optional.of(why));
        }
    }

    /** The coverage of one rule block of the function block. */
    public static Result of(FunctionBlock block, RuleBlock ruleBlock) {
        if (ruleBlock.rules().isEmpty()) {
            return Result.not("it has no rules");
        }
        AndAlgorithm and = ruleBlock.and().map(Located::value)
                .orElse(ruleBlock.or().map(o -> o.value().pair()).orElse(AndAlgorithm.MIN));
        OrAlgorithm or = ruleBlock.or().map(Located::value).orElse(and.pair());
        Compiler compiler = new Compiler(block);
        List<int[]> programs = new ArrayList<>();
        for (Rule rule : ruleBlock.rules()) {
            Optional<int[]> program = compiler.compile(rule.condition());
            if (program.isEmpty()) {
                return Result.not(compiler.why);
            }
            programs.add(program.get());
        }
        List<Axis> axes = compiler.axes;
        int inputs = axes.size() + compiler.beyond.size();
        if (inputs > MAX_INPUTS) {
            return Result.not("its conditions use " + inputs + " inputs (at most " + MAX_INPUTS + " are analysed)");
        }
        long cells = 1;
        for (Axis axis : axes) {
            cells *= axis.cellCount();
            if (cells > MAX_WORK) {
                return Result.not("its inputs' terms cut the input space into more than " + MAX_WORK + " cells");
            }
        }
        long nodes = programs.stream().mapToLong(p -> p.length).sum();
        if (cells * nodes > MAX_WORK) {
            return Result.not("it would take " + cells + " cells × " + nodes + " condition nodes (at most "
                    + MAX_WORK + ")");
        }
        // rules with the same condition have the same degree on every cell: evaluate each condition once
        // (a large block repeats its conditions across outputs and weights); the limits above count every rule
        List<int[]> distinct = distinct(programs);
        int[][] andTable = table(and, true);
        int[][] orTable = table(or, false);
        boolean[] gap = new boolean[(int) cells];
        int[] cell = new int[axes.size()];
        int[] stack = new int[(int) Math.min(Integer.MAX_VALUE, nodes + 1)];
        long undecided = 0;
        for (int index = 0; index < cells; index++) {
            decode(index, axes, cell);
            boolean certainlyZero = true;
            boolean fires = false;
            for (int[] program : distinct) {
                int mask = run(program, compiler.leaves, cell, stack, andTable, orTable);
                if ((mask & ZERO) == 0) {
                    fires = true;
                    break;
                }
                if (mask != ZERO) {
                    certainlyZero = false;
                }
            }
            if (!fires) {
                if (certainlyZero) {
                    gap[index] = true;
                } else {
                    undecided++;
                }
            }
        }
        List<Box> boxes = boxes(gap, axes);
        return new Result(axes.stream().map(a -> a.variable).toList(), boxes, undecided, Optional.empty());
    }

    /** The programs without repeats, in first-seen order. */
    private static List<int[]> distinct(List<int[]> programs) {
        record Key(int[] program) {
            @Override
            public boolean equals(Object o) {
                return o instanceof Key k && Arrays.equals(program, k.program);
            }

            @Override
            public int hashCode() {
                return Arrays.hashCode(program);
            }
        }
        java.util.Set<Key> seen = new java.util.LinkedHashSet<>();
        for (int[] p : programs) {
            seen.add(new Key(p));
        }
        return seen.stream().map(Key::program).toList();
    }

    /** The cell of each axis for a flat index (axis 0 varies fastest). */
    private static void decode(long index, List<Axis> axes, int[] cell) {
        for (int a = 0; a < axes.size(); a++) {
            int n = axes.get(a).cellCount();
            cell[a] = (int) (index % n);
            index /= n;
        }
    }

    /** Evaluates a compiled condition (postfix) on one cell, in masks of classes. */
    private static int run(int[] program, List<Leaf> leaves, int[] cell, int[] stack, int[][] andTable,
            int[][] orTable) {
        int top = 0;
        for (int i = 0; i < program.length; i++) {
            int op = program[i];
            if (op >= 0) {
                Leaf leaf = leaves.get(op);
                stack[top++] = leaf.masks[cell[leaf.axis]];
            } else if (op == NOT) {
                stack[top - 1] = swap(stack[top - 1]);
            } else {
                int n = program[++i];
                int[][] t = op == AND ? andTable : orTable;
                int acc = stack[top - n];
                for (int k = top - n + 1; k < top; k++) {
                    acc = t[acc][stack[k]];
                }
                top -= n;
                stack[top++] = acc;
            }
        }
        return stack[0];
    }

    private static final int NOT = -1;
    private static final int AND = -2;
    private static final int OR = -3;

    private static int swap(int mask) {
        return (mask & MID) | ((mask & ZERO) != 0 ? ONE : 0) | ((mask & ONE) != 0 ? ZERO : 0);
    }

    /** For two masks, the mask of the operator's possible outcomes. */
    private static int[][] table(Enum<?> algorithm, boolean and) {
        int[][] t = new int[8][8];
        for (int a = 1; a < 8; a++) {
            for (int b = 1; b < 8; b++) {
                int out = 0;
                for (int x = 1; x <= 4; x <<= 1) {
                    for (int y = 1; y <= 4; y <<= 1) {
                        if ((a & x) != 0 && (b & y) != 0) {
                            out |= and ? andOf((AndAlgorithm) algorithm, x, y) : orOf((OrAlgorithm) algorithm, x, y);
                        }
                    }
                }
                t[a][b] = out;
            }
        }
        return t;
    }

    /** Table 3 and the dialects' norms on single classes. */
    private static int andOf(AndAlgorithm algorithm, int x, int y) {
        if (x == ZERO || y == ZERO) {
            return ZERO;
        }
        if (x == ONE && y == ONE) {
            return ONE;
        }
        if (x == ONE || y == ONE) {
            return MID;       // every norm has 1 as its unit
        }
        return switch (algorithm) {
            case MIN, PROD, EPROD, HPROD -> MID;
            case DPROD -> ZERO;
            case BDIF, NMIN -> ZERO | MID;   // x + y - 1 (or x + y > 1) depends on the values
        };
    }

    private static int orOf(OrAlgorithm algorithm, int x, int y) {
        if (x == ONE || y == ONE) {
            return ONE;
        }
        if (x == ZERO) {
            return y;         // every conorm has 0 as its unit
        }
        if (y == ZERO) {
            return x;
        }
        return switch (algorithm) {
            case MAX, ASUM, ESUM, HSUM -> MID;
            case DSUM -> ONE;
            case BSUM, NMAX -> MID | ONE;
        };
    }

    private static int classOf(double degree) {
        return degree <= 0 ? ZERO : degree >= 1 ? ONE : MID;
    }

    /** The classes of the degrees strictly between two different limits of a linear piece. */
    private static int openClasses(double a, double b) {
        if (a == b) {
            return classOf(a);
        }
        double lo = Math.min(a, b);
        double hi = Math.max(a, b);
        return (lo < 0 ? ZERO : 0) | (hi > 1 ? ONE : 0) | (lo < 1 && hi > 0 ? MID : 0);
    }

    /** One input: its breakpoints, cut into 2k + 1 cells: (-inf, b0), b0, (b0, b1), b1, ..., (b(k-1), inf). */
    private static final class Axis {
        final String variable;
        final double[] breaks;

        Axis(String variable, double[] breaks) {
            this.variable = variable;
            this.breaks = breaks;
        }

        int cellCount() {
            return 2 * breaks.length + 1;
        }
    }

    /** A subcondition's classes on each cell of its input's axis. */
    private record Leaf(int axis, int[] masks) {
    }

    /** A term as sorted points with constant values. */
    private record Piecewise(double[] x, double[] y) {
        /** The degree at a breakpoint: the largest of the degrees written at that x (docs/semantics.md 1). */
        double at(double v) {
            int n = x.length;
            if (v < x[0]) {
                return y[0];
            }
            if (v > x[n - 1]) {
                return y[n - 1];
            }
            double max = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < n; i++) {
                if (x[i] == v) {
                    max = Math.max(max, y[i]);
                }
            }
            return max;        // callers ask only at x values that are breakpoints of this term, or outside
        }

        /** The classes at a breakpoint v of another term, strictly inside one of this term's pieces or at its own. */
        int classesAt(double v) {
            int n = x.length;
            if (v <= x[0] || v >= x[n - 1] || contains(v)) {
                return classOf(at(v));
            }
            int i = 0;
            while (x[i + 1] < v) {
                i++;
            }
            return openClasses(y[i], y[i + 1]);
        }

        /** The classes strictly between two neighbouring breakpoints of the axis (a piece of this term). */
        int classesBetween(double a, double b) {
            int n = x.length;
            if (b <= x[0]) {
                return classOf(y[0]);
            }
            if (a >= x[n - 1]) {
                return classOf(y[n - 1]);
            }
            int i = 0;          // the last point at or before a: its last (right-most) duplicate
            while (i + 1 < n && x[i + 1] <= a) {
                i++;
            }
            return openClasses(y[i], y[i + 1]);
        }

        private boolean contains(double v) {
            for (double p : x) {
                if (p == v) {
                    return true;
                }
            }
            return false;
        }
    }

    /** Turns conditions into postfix programs over leaves, collecting the inputs and their breakpoints. */
    private static final class Compiler {
        final FunctionBlock block;
        final List<Axis> axes = new ArrayList<>();
        final List<Leaf> leaves = new ArrayList<>();
        /** Leaves made so far, by the subcondition's spelling: a large block names the same few thousand times. */
        private final java.util.Map<List<Object>, Integer> made = new java.util.HashMap<>();
        String why = "";
        /**
         * The inputs the conditions use beyond the first {@link #MAX_INPUTS} (by key): counted, not given an axis, since
         * the block will not be analysed. Their leaves are {@link #beyondLeaf}, which no program is evaluated with.
         */
        final java.util.Set<String> beyond = new java.util.HashSet<>();
        private int beyondLeaf = -1;
        /** The block's name lookups (the block's own walk lists); the checks of the same run built it already. */
        private final Scope scope;

        Compiler(FunctionBlock block) {
            this.block = block;
            this.scope = Scope.of(block);
        }

        /** Post-order without recursion (conditions may be nested very deep). */
        Optional<int[]> compile(Condition root) {
            // no boxing, no frame objects: a large block compiles tens of thousands of conditions
            int[] out = new int[16];
            int size = 0;
            Condition[] stack = new Condition[16];
            boolean[] expandedAt = new boolean[16];
            int top = 0;
            stack[top] = root;
            expandedAt[top++] = false;
            while (top > 0) {
                Condition c = stack[--top];
                boolean expanded = expandedAt[top];
                stack[top] = null;
                if (out.length - size < 2) {
                    out = Arrays.copyOf(out, out.length * 2);
                }
                if (c instanceof Condition.Parenthesized p) {
                    stack[top] = p.inner();
                    expandedAt[top++] = false;
                } else if (c instanceof Condition.TermSubcondition || c instanceof Condition.VariableSubcondition) {
                    int leaf = leaf(c);
                    if (leaf < 0) {
                        return Optional.empty();
                    }
                    out[size++] = leaf;
                } else if (expanded) {
                    if (c instanceof Condition.Not) {
                        out[size++] = NOT;
                    } else {
                        out[size++] = c instanceof Condition.And ? AND : OR;
                        out[size++] = operands(c).size();
                    }
                } else {
                    List<Condition> operands = operands(c);
                    if (stack.length - top < operands.size() + 1) {
                        int room = Math.max(stack.length * 2, top + operands.size() + 1);
                        stack = Arrays.copyOf(stack, room);
                        expandedAt = Arrays.copyOf(expandedAt, room);
                    }
                    stack[top] = c;
                    expandedAt[top++] = true;
                    for (int i = operands.size() - 1; i >= 0; i--) {
                        stack[top] = operands.get(i);
                        expandedAt[top++] = false;
                    }
                }
            }
            return Optional.of(Arrays.copyOf(out, size));
        }

        private static List<Condition> operands(Condition c) {
            if (c instanceof Condition.Not n) {
                return List.of(n.operand());
            }
            return c instanceof Condition.And a ? a.operands() : ((Condition.Or) c).operands();
        }

        /** The leaf of a subcondition, or -1 with {@link #why} set; the same leaf for the same spelling. */
        private int leaf(Condition c) {
            List<Object> key = c instanceof Condition.TermSubcondition t
                    ? Arrays.asList(t.variable(), t.term(), t.hedges(), t.negated(), t.any())
                    : List.of(((Condition.VariableSubcondition) c).variable());
            Integer known = made.get(key);
            if (known != null) {
                return known;
            }
            int leaf = newLeaf(c);
            if (leaf >= 0) {
                made.put(key, leaf);
            }
            return leaf;
        }

        private int newLeaf(Condition c) {
            String variable = c instanceof Condition.TermSubcondition t ? t.variable()
                    : ((Condition.VariableSubcondition) c).variable();
            Optional<Variable> declared = scope.variable(variable);
            if (declared.isEmpty() || declared.get().kind() != VariableKind.INPUT) {
                why = "'" + variable + "' in a condition is not an input";
                return -1;
            }
            Piecewise term;
            List<Hedge> hedges = List.of();
            boolean negated = false;
            if (c instanceof Condition.TermSubcondition t) {
                hedges = t.hedges();
                negated = t.negated();
                if (t.any()) {
                    term = new Piecewise(new double[] {0}, new double[] {1});
                } else {
                    Optional<Term> found = scope.fuzzification(variable).flatMap(f -> f.term(t.term()));
                    if (found.isEmpty()) {
                        why = "term '" + t.term() + "' of '" + variable + "' is not defined";
                        return -1;
                    }
                    Optional<Piecewise> p = piecewise(found.get().function());
                    if (p.isEmpty()) {
                        why = "term '" + t.term() + "' of '" + variable + "' is not piece-wise linear with constant"
                                + " points";
                        return -1;
                    }
                    term = p.get();
                }
            } else {
                term = new Piecewise(new double[] {0, 1}, new double[] {0, 1});  // the value clamped to [0, 1]
            }
            Axis axis = existingAxis(variable);
            if (axis == null && axes.size() >= MAX_INPUTS) {
                // a seventh input: the block is not analysed, so only count it (an axis per input of a block of
                // 100 000 inputs made this check run for hours)
                beyond.add(Names.key(variable));
                if (beyondLeaf < 0) {
                    leaves.add(new Leaf(-1, new int[0]));
                    beyondLeaf = leaves.size() - 1;
                }
                return beyondLeaf;
            }
            if (axis == null) {
                axis = newAxis(declared.get().name());
            }
            int a = axes.indexOf(axis);
            int[] masks = new int[axis.cellCount()];
            double[] b = axis.breaks;
            for (int cell = 0; cell < masks.length; cell++) {
                int mask;
                if (cell % 2 == 1) {
                    mask = term.classesAt(b[cell / 2]);
                } else {
                    double lo = cell == 0 ? Double.NEGATIVE_INFINITY : b[cell / 2 - 1];
                    double hi = cell == masks.length - 1 ? Double.POSITIVE_INFINITY : b[cell / 2];
                    mask = term.classesBetween(lo, hi);
                }
                for (int h = hedges.size() - 1; h >= 0; h--) {
                    mask = hedges.get(h) == Hedge.ANY ? ONE : hedges.get(h) == Hedge.NOT ? swap(mask) : mask;
                }
                masks[cell] = negated ? swap(mask) : mask;
            }
            leaves.add(new Leaf(a, masks));
            return leaves.size() - 1;
        }

        /** The axis already made for an input, or null. */
        private Axis existingAxis(String variable) {
            for (Axis axis : axes) {
                if (Names.same(axis.variable, variable)) {
                    return axis;
                }
            }
            return null;
        }

        /**
         * A new axis for an input that has none yet, inserted in declaration order: every breakpoint of its terms (and
         * 0 and 1, where it is used as a degree).
         */
        private Axis newAxis(String variable) {
            TreeSet<Double> breaks = new TreeSet<>(List.of(0.0, 1.0));
            Optional<Fuzzification> f = scope.fuzzification(variable);
            if (f.isPresent()) {
                breaks.clear();
                boolean bare = false;
                for (Term t : f.get().terms()) {
                    piecewise(t.function()).ifPresent(p -> Arrays.stream(p.x).forEach(breaks::add));
                }
                bare = usedBare(variable);
                if (bare || breaks.isEmpty()) {
                    breaks.add(0.0);
                    breaks.add(1.0);
                }
            }
            Axis axis = new Axis(variable, breaks.stream().mapToDouble(Double::doubleValue).toArray());
            // keep declaration order: insert before the first axis declared later
            int at = axes.size();
            List<String> order = block.variables().stream().map(Variable::name).toList();
            for (int i = 0; i < axes.size(); i++) {
                if (order.indexOf(axes.get(i).variable) > order.indexOf(variable)) {
                    at = i;
                    break;
                }
            }
            if (at < axes.size()) {
                // leaves record axis indices: renumber them
                for (int i = 0; i < leaves.size(); i++) {
                    Leaf l = leaves.get(i);
                    if (l.axis >= at) {
                        leaves.set(i, new Leaf(l.axis + 1, l.masks));
                    }
                }
            }
            axes.add(at, axis);
            return axis;
        }

        private boolean usedBare(String variable) {
            if (bare == null) {
                // one walk for all axes (each used to walk every rule of the block): the bare variables' names
                bare = new java.util.HashMap<>();
                for (RuleBlock rb : block.ruleBlocks()) {
                    for (Rule r : rb.rules()) {
                        for (Condition c : scope.subconditions(r)) {
                            if (c instanceof Condition.VariableSubcondition v) {
                                List<String> spelt = bare.computeIfAbsent(folded(v.variable()), k -> new ArrayList<>());
                                if (!spelt.contains(v.variable())) {
                                    spelt.add(v.variable());
                                }
                            }
                        }
                    }
                }
            }
            List<String> spelt = bare.get(folded(variable));
            return spelt != null && spelt.stream().anyMatch(n -> Names.same(n, variable));
        }

        /** The names used as bare-variable subconditions anywhere in the block, by {@link #folded}, once asked for. */
        private java.util.Map<String, List<String>> bare;

        /** A name with each character folded as {@link String#equalsIgnoreCase} folds it (a hash key for {@link Names#same}). */
        private static String folded(String name) {
            char[] c = name.toCharArray();
            for (int i = 0; i < c.length; i++) {
                c[i] = Character.toLowerCase(Character.toUpperCase(c[i]));
            }
            return new String(c);
        }
    }

    /** A term's points when they are constant and piece-wise linear (points, a singleton, a linear shape). */
    static Optional<Piecewise> piecewise(MembershipFunction function) {
        List<Point> points;
        if (function instanceof MembershipFunction.Points p) {
            points = p.points();
        } else if (function instanceof MembershipFunction.Singleton s) {
            if (!(s.value() instanceof Literal v)) {
                return Optional.empty();
            }
            // degree 1 at the value, 0 on either side: three points at one x, the middle one the largest
            return Optional.of(new Piecewise(new double[] {v.value(), v.value(), v.value()}, new double[] {0, 1, 0}));
        } else if (function instanceof MembershipFunction.NamedShape n) {
            Optional<List<Point>> linear = n.points();
            if (linear.isEmpty()) {
                return Optional.empty();
            }
            points = linear.get();
        } else {
            return Optional.empty();
        }
        if (points.isEmpty()) {
            return Optional.empty();
        }
        double[] x = new double[points.size()];
        double[] y = new double[points.size()];
        Integer[] order = new Integer[points.size()];
        for (int i = 0; i < points.size(); i++) {
            if (!(points.get(i).x() instanceof Literal px) || !(points.get(i).degree() instanceof Literal py)
                    || !Double.isFinite(px.value()) || !Double.isFinite(py.value())) {
                return Optional.empty();
            }
            order[i] = i;
            x[i] = px.value();
            y[i] = py.value();
        }
        Arrays.sort(order, (a, b) -> Double.compare(x[a], x[b]));    // stable, as the evaluator sorts
        double[] sx = new double[x.length];
        double[] sy = new double[y.length];
        for (int i = 0; i < order.length; i++) {
            sx[i] = x[order[i]];
            sy[i] = y[order[i]];
        }
        return Optional.of(new Piecewise(sx, sy));
    }

    /** Merges the gap cells into disjoint boxes, greedily: along axis 0 first, then each further axis. */
    private static List<Box> boxes(boolean[] gap, List<Axis> axes) {
        int dims = axes.size();
        int[] size = new int[dims];
        long[] stride = new long[dims];
        long s = 1;
        for (int a = 0; a < dims; a++) {
            size[a] = axes.get(a).cellCount();
            stride[a] = s;
            s *= size[a];
        }
        boolean[] taken = new boolean[gap.length];
        List<Box> boxes = new ArrayList<>();
        int[] start = new int[dims];
        for (int index = 0; index < gap.length; index++) {
            if (!gap[index] || taken[index]) {
                continue;
            }
            decode(index, axes, start);
            int[] extent = new int[dims];
            Arrays.fill(extent, 1);
            for (int a = 0; a < dims; a++) {
                while (start[a] + extent[a] < size[a] && slabFree(gap, taken, start, extent, a, stride)) {
                    extent[a]++;
                }
            }
            markTaken(taken, start, extent, stride);
            List<Interval> intervals = new ArrayList<>();
            for (int a = 0; a < dims; a++) {
                intervals.add(interval(axes.get(a).breaks, start[a], start[a] + extent[a] - 1));
            }
            boxes.add(new Box(intervals));
        }
        return boxes;
    }

    /** Whether the slab just beyond the box along axis a is all gap and not yet taken. */
    private static boolean slabFree(boolean[] gap, boolean[] taken, int[] start, int[] extent, int a, long[] stride) {
        int[] slabStart = start.clone();
        int[] slabExtent = extent.clone();
        slabStart[a] = start[a] + extent[a];
        slabExtent[a] = 1;
        boolean[] ok = {true};
        forEach(slabStart, slabExtent, stride, i -> ok[0] &= gap[(int) i] && !taken[(int) i]);
        return ok[0];
    }

    private static void markTaken(boolean[] taken, int[] start, int[] extent, long[] stride) {
        forEach(start, extent, stride, i -> taken[(int) i] = true);
    }

    private static void forEach(int[] start, int[] extent, long[] stride, java.util.function.LongConsumer action) {
        int dims = start.length;
        int[] at = new int[dims];
        while (true) {
            long index = 0;
            for (int a = 0; a < dims; a++) {
                index += (start[a] + at[a]) * stride[a];
            }
            action.accept(index);
            int a = 0;
            while (a < dims && ++at[a] == extent[a]) {
                at[a] = 0;
                a++;
            }
            if (a == dims) {
                return;
            }
        }
    }

    /** The interval covered by cells from..to of an axis. */
    private static Interval interval(double[] b, int from, int to) {
        double low;
        boolean lowClosed;
        if (from % 2 == 1) {
            low = b[from / 2];
            lowClosed = true;
        } else {
            low = from == 0 ? Double.NEGATIVE_INFINITY : b[from / 2 - 1];
            lowClosed = false;
        }
        double high;
        boolean highClosed;
        if (to % 2 == 1) {
            high = b[to / 2];
            highClosed = true;
        } else {
            high = to == 2 * b.length ? Double.POSITIVE_INFINITY : b[to / 2];
            highClosed = false;
        }
        return new Interval(low, lowClosed, high, highClosed);
    }
}
