package org.fclcert.eval;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * What one evaluation did, stage by stage (A.2.3): the degree of each term of each input
 * (fuzzification), each rule's degree (aggregation), each subconclusion's activated degree
 * (activation and weighting), each output's accumulated set (accumulation) and its crisp value
 * (defuzzification, or DEFAULT / NC). Pass a trace to {@link FunctionBlockInstance#evaluate(Trace)};
 * it is cleared and filled. Recording allocates; evaluation without a trace does not.
 */
public final class Trace {

    /** Fuzzification: the degree of membership of one input term. */
    public record TermDegree(String variable, String term, double degree) {
    }

    /** Aggregation: the degree of accomplishment of one rule's condition. */
    public record RuleDegree(String ruleBlock, String rule, double degree) {
    }

    /**
     * Activation: one subconclusion of a rule; {@code term} is empty for a bare variable conclusion.
     * {@code activatedDegree} is weight × rule degree: the height to which the term is activated
     * (the whole activated set is weight × ACT(rule degree, term membership)).
     */
    public record Activation(String ruleBlock, String rule, String variable, Optional<String> term,
            double weight, double activatedDegree) {
    }

    /** One point of an accumulated set; a jump appears as two or three points with the same u. */
    public record Breakpoint(double u, double degree) {
    }

    /**
     * Accumulation: the accumulated set of one defuzzified output. For singleton outputs one
     * breakpoint per term (its value and accumulated degree, in declaration order); otherwise the
     * vertices of the piece-wise linear set over the defuzzification interval, left to right.
     */
    public record AccumulatedSet(String variable, boolean singletons, List<Breakpoint> breakpoints) {
        public AccumulatedSet {
            breakpoints = List.copyOf(breakpoints);
        }
    }

    /** How an output got its value. */
    public enum Outcome {
        /** Defuzzified from a non-empty accumulated set. */
        DEFUZZIFIED,
        /** Nothing fired; the DEFAULT constant was used. */
        DEFAULT,
        /** Nothing fired; DEFAULT NC kept the previous value. */
        NO_CHANGE,
        /** A bare variable conclusion ({@code THEN v}) assigned the value. */
        ASSIGNED
    }

    /**
     * The crisp value given to one variable, after conversion to its data type ({@code value}), and the value before
     * it ({@code computed}: the defuzzified, DEFAULT or kept value, which an integer output rounds half away from zero).
     */
    public record Result(String variable, double value, Outcome outcome, double computed) {
        public Result(String variable, double value, Outcome outcome) {
            this(variable, value, outcome, value);
        }
    }

    private final List<TermDegree> termDegrees = new ArrayList<>();
    private final List<RuleDegree> ruleDegrees = new ArrayList<>();
    private final List<Activation> activations = new ArrayList<>();
    private final List<AccumulatedSet> accumulatedSets = new ArrayList<>();
    private final List<Result> results = new ArrayList<>();

    private boolean decidedExactly;

    void clear() {
        decidedExactly = false;
        termDegrees.clear();
        ruleDegrees.clear();
        activations.clear();
        accumulatedSets.clear();
        results.clear();
    }

    void add(TermDegree t) {
        termDegrees.add(t);
    }

    void add(RuleDegree r) {
        ruleDegrees.add(r);
    }

    void add(Activation a) {
        activations.add(a);
    }

    void add(AccumulatedSet s) {
        accumulatedSets.add(s);
    }

    void add(Result r) {
        results.add(r);
    }

    /**
     * The filtered evaluator could not settle a decision with its error bounds and redid the evaluation exactly: the
     * results are replaced by the exact path's (the degrees and sets above stay the double computation's, which
     * may differ from the exact ones in their last digits and, at the undecided point, in what they show).
     */
    void decidedExactly(List<Result> exactResults) {
        decidedExactly = true;
        results.clear();
        results.addAll(exactResults);
    }

    /** Whether the results come from the exact path (see {@link #decidedExactly(List)}). */
    public boolean decidedExactly() {
        return decidedExactly;
    }

    public List<TermDegree> termDegrees() {
        return List.copyOf(termDegrees);
    }

    public List<RuleDegree> ruleDegrees() {
        return List.copyOf(ruleDegrees);
    }

    public List<Activation> activations() {
        return List.copyOf(activations);
    }

    public List<AccumulatedSet> accumulatedSets() {
        return List.copyOf(accumulatedSets);
    }

    public List<Result> results() {
        return List.copyOf(results);
    }

    /** The degree of one input term, by name (case-insensitive). */
    public Optional<Double> termDegree(String variable, String term) {
        return termDegrees.stream()
                .filter(t -> t.variable().equalsIgnoreCase(variable) && t.term().equalsIgnoreCase(term))
                .map(TermDegree::degree).findFirst();
    }

    /** The accumulated set of one output, by name (case-insensitive). */
    public Optional<AccumulatedSet> accumulatedSet(String variable) {
        return accumulatedSets.stream().filter(s -> s.variable().equalsIgnoreCase(variable)).findFirst();
    }

    /** The result of one variable, by name (case-insensitive). */
    public Optional<Result> result(String variable) {
        return results.stream().filter(r -> r.variable().equalsIgnoreCase(variable)).findFirst();
    }
}
