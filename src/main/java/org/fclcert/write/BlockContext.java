package org.fclcert.write;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.BlockIndex;
import org.fclcert.model.Condition;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Operand;
import org.fclcert.model.Point;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * What the library writers share about one function block: names in their declared spelling (the libraries
 * are case-sensitive, the standard is not), operands turned into numbers (a local variable is its initial
 * value, since nothing can set it; an input's value is known only at run time, which the libraries cannot say),
 * the span of a variable's terms, and the subconclusions of a rule grouped by weight (the libraries weigh a
 * whole rule, the standard each subconclusion).
 */
final class BlockContext {
    final FunctionBlock fb;
    /** fb's names by hash: the writers look up every name of every rule. */
    final BlockIndex index;
    final Findings findings;
    /** How the library must spell a name it does not read as declared (identity: as declared). */
    java.util.function.UnaryOperator<String> spelling = java.util.function.UnaryOperator.identity();

    BlockContext(FunctionBlock fb, Findings findings) {
        this.fb = fb;
        this.index = BlockIndex.of(fb);
        this.findings = findings;
    }

    /** A variable's name as declared (or as written when it is not declared). */
    String variable(String name) {
        return spelling.apply(index.variable(name).map(Variable::name).orElse(name));
    }

    /** A term's name as its FUZZIFY or DEFUZZIFY block declares it. */
    String term(String variable, String term) {
        return spelling.apply(terms(variable).stream().filter(t -> Names.same(t.name(), term)).findFirst()
                .map(Term::name).orElse(term));
    }

    List<Term> terms(String variable) {
        Optional<Fuzzification> f = index.fuzzification(variable);
        if (f.isPresent()) {
            return f.get().terms();
        }
        return index.defuzzification(variable).map(Defuzzification::terms).orElse(List.of());
    }

    /**
     * An operand as a number: a literal is itself, a local variable its initial value (exact: no one sets a
     * local); a variable the library's FCL cannot name here (an input) is lost, and its initial value, else
     * {@code fallback}, is written instead.
     */
    double number(Operand o, double fallback, WriterCode code, String what) {
        if (o instanceof Literal l) {
            return l.value();
        }
        VariableRef ref = (VariableRef) o;
        Optional<Variable> v = index.variable(ref.name());
        double initial = v.flatMap(Variable::initialValue).map(Literal::value).orElse(fallback);
        if (v.isPresent() && v.get().kind() == VariableKind.LOCAL) {
            return v.get().initialValue().map(Literal::value).orElse(0.0);
        }
        findings.lost(ref.location(), code, what + " is the variable '" + ref.name() + "', which " + findings.library()
                + " cannot name there (it takes numbers only); written as " + LibraryText.number(initial)
                + ", " + (v.flatMap(Variable::initialValue).isPresent() ? "its initial value" : "the default"));
        return initial;
    }

    /** A literal operand as written (keeps the integer spelling), any other as {@link #number}. */
    String numberText(Operand o, double fallback, WriterCode code, String what) {
        return o instanceof Literal l ? LibraryText.number(l) : LibraryText.number(number(o, fallback, code, what));
    }

    /** The x values of a list of terms (points with variables as their fallback), as {lowest, highest}. */
    double[] span(List<Term> terms) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Term t : terms) {
            for (double x : xs(t.function())) {
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
        }
        if (lo > hi) {
            return new double[] {0, 1};
        }
        return new double[] {lo, hi};
    }

    private static List<Double> xs(MembershipFunction f) {
        List<Double> out = new ArrayList<>();
        if (f instanceof MembershipFunction.Singleton s && s.value() instanceof Literal l) {
            out.add(l.value());
        } else if (f instanceof MembershipFunction.Points p) {
            for (Point pt : p.points()) {
                if (pt.x() instanceof Literal l) {
                    out.add(l.value());
                }
            }
        } else if (f instanceof MembershipFunction.NamedShape n) {
            for (double x : n.kind().specialPoints(n.values())) {
                out.add(x);
            }
        }
        return out;
    }

    /** An input's interval: its RANGE as a dialect program declared it, else the span of its terms. */
    double[] inputSpan(Fuzzification f) {
        return f.declaredRange().map(r -> new double[] {r.min().value(), r.max().value()}).orElseGet(() -> span(f.terms()));
    }

    /** An output's interval: its RANGE, else the span of its terms (where CoG and the others find the set anyway). */
    double[] outputSpan(Defuzzification d) {
        return d.range().map(r -> new double[] {r.min().value(), r.max().value()}).orElseGet(() -> {
            double[] s = span(d.terms());
            // a RANGE must not be empty: one singleton value gets a unit on each side (singletons ignore RANGE)
            return s[0] < s[1] ? s : new double[] {s[0] - 1, s[1] + 1};
        });
    }

    /** The accumulation of each output: that of the rule blocks concluding it (MAX when none says, as fclcert). */
    Map<String, Located<AccumulationMethod>> accumulations() {
        Map<String, Located<AccumulationMethod>> out = new LinkedHashMap<>();
        for (RuleBlock rb : fb.ruleBlocks()) {
            Located<AccumulationMethod> a = rb.accumulation()
                    .orElse(new Located<>(AccumulationMethod.MAX, rb.location()));
            for (Rule r : rb.rules()) {
                for (Subconclusion s : r.conclusion()) {
                    Located<AccumulationMethod> before = out.putIfAbsent(Names.key(s.variable()), a);
                    if (before != null && before.value() != a.value()) {
                        findings.lost(a.location(), WriterCode.ACCUMULATION, "rule block '" + rb.name()
                                + "' accumulates '" + s.variable() + "' by " + a.value() + ", another rule block by "
                                + before.value() + "; " + findings.library() + " holds one ACCU per output (written: "
                                + before.value() + ")");
                        out.put(Names.key(s.variable()), before);
                    }
                }
            }
        }
        return out;
    }

    /** The subconclusions of a rule with one weight, and that weight (empty: no WITH). */
    record WeightGroup(List<Subconclusion> parts, Optional<String> weight, double value) {
    }

    /**
     * The subconclusions grouped by weight, in order of first appearance: one group when every subconclusion has
     * the same weight (the library's one WITH per rule says it); otherwise the rule is written once per group
     * (the same condition concluding each group: the same activations, so the same meaning).
     */
    List<WeightGroup> weightGroups(Rule r) {
        Map<String, List<Subconclusion>> groups = new LinkedHashMap<>();
        Map<String, Double> values = new LinkedHashMap<>();
        Map<String, Boolean> written = new LinkedHashMap<>();
        for (Subconclusion s : r.conclusion()) {
            String key;
            double value;
            if (s.weight().isEmpty()) {
                value = 1.0;
                key = LibraryText.number(1.0);
            } else {
                Operand w = s.weight().get();
                key = numberText(w, 1.0, WriterCode.WEIGHT_VARIABLE, "the weight of '" + s.variable() + "' in rule "
                        + r.name());
                value = Double.parseDouble(key);
                key = LibraryText.number(value);
            }
            groups.computeIfAbsent(key, k -> new ArrayList<>()).add(s);
            values.put(key, value);
            written.merge(key, s.weight().isPresent(), Boolean::logicalOr);
        }
        List<WeightGroup> out = new ArrayList<>();
        for (Map.Entry<String, List<Subconclusion>> e : groups.entrySet()) {
            Optional<String> w = written.get(e.getKey()) ? Optional.of(e.getKey()) : Optional.empty();
            out.add(new WeightGroup(e.getValue(), w, values.get(e.getKey())));
        }
        return out;
    }

    /** Whether the output has point (or shape) terms rather than singletons. */
    /** Whether an output is defuzzified by Tsukamoto's method (its terms inverted, no fuzzy set). */
    boolean tsukamoto(String output) {
        return index.defuzzification(output).flatMap(Defuzzification::method)
                .map(m -> m.value() == org.fclcert.model.DefuzzificationMethod.TSUKAMOTO).orElse(false);
    }

    boolean pointTerms(String output) {
        return terms(output).stream().anyMatch(t -> !(t.function() instanceof MembershipFunction.Singleton));
    }

    /** How many rules conclude each term of an output (after the libraries' rule splitting: per written rule). */
    int conclusions(String output, String term) {
        int n = 0;
        for (RuleBlock rb : fb.ruleBlocks()) {
            for (Rule r : rb.rules()) {
                for (Subconclusion s : r.conclusion()) {
                    if (Names.same(s.variable(), output) && s.term().isPresent() && Names.same(s.term().get(), term)) {
                        n++;
                    }
                }
            }
        }
        return n;
    }

    static SourceLocation at(Condition c) {
        return c.location();
    }
}
