package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.BlockIndex;
import org.fclcert.model.Condition;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * The model-level part of the FFLL reader: turns what the strict builder made of an FFLL text into the
 * program FFLL means, in the standard model, recording each construct as an Open Level feature and warning
 * where FFLL's own evaluation differs from fclcert's (docs/dialects.md). One instance per read.
 */
final class FfllModel {
    /** The point counts FFLL loads (its term shapes: singleton, triangle, trapezoid, 7-point curve). */
    private static final List<Integer> FFLL_POINT_COUNTS = List.of(1, 3, 4, 7);

    private final FfllTokens tokens;
    private final List<FeatureUse> features = new ArrayList<>();
    private final List<Diagnostic> diagnostics = new ArrayList<>();
    private int errors;

    FfllModel(FfllTokens tokens) {
        this.tokens = tokens;
    }

    List<FeatureUse> features() {
        return features;
    }

    List<Diagnostic> diagnostics() {
        return diagnostics;
    }

    FunctionBlock functionBlock(FunctionBlock fb, int index) {
        Map<String, FfllTokens.RangeComment> ranges = tokens.ranges(index);
        List<Variable> inputs = fb.variables(VariableKind.INPUT);
        List<Variable> outputs = fb.variables(VariableKind.OUTPUT);
        BlockIndex names = BlockIndex.of(fb);
        // output terms given in FUZZIFY blocks (FFLL's way), by output
        List<Fuzzification> fuzzifications = new ArrayList<>();
        Map<String, Fuzzification> outputFuzzify = new LinkedHashMap<>();
        for (Fuzzification f : fb.fuzzifications()) {
            boolean ofOutput = names.variable(f.variable()).map(v -> v.kind() == VariableKind.OUTPUT).orElse(false);
            if (ofOutput && !outputFuzzify.containsKey(Names.key(f.variable()))) {
                features.add(new FeatureUse(Feature.O_FFLL_OUTPUT_FUZZIFY, f.location()));
                outputFuzzify.put(Names.key(f.variable()), f);
            } else {
                fuzzifications.add(f);
            }
            pointCounts(f.terms());
        }
        List<Defuzzification> defuzzifications = new ArrayList<>();
        for (Defuzzification d : fb.defuzzifications()) {
            Fuzzification terms = outputFuzzify.remove(Names.key(d.variable()));
            defuzzifications.add(defuzzification(d, terms, ranges));
        }
        for (Fuzzification f : outputFuzzify.values()) {
            // output terms but no DEFUZZIFY block at all: FFLL's defaults (CoG, no DEFAULT)
            Defuzzification bare = new Defuzzification(f.variable(), Optional.empty(), List.of(), Optional.empty(),
                    Optional.empty(), f.location());
            defuzzifications.add(defuzzification(bare, f, ranges));
        }
        List<RuleBlock> blocks = new ArrayList<>();
        for (RuleBlock b : fb.ruleBlocks()) {
            blocks.add(ruleBlock(b, names, inputs, outputs, fuzzifications));
        }
        return new FunctionBlock(fb.name(), fb.variables(), fuzzifications, defuzzifications, blocks, fb.options(),
                fb.location());
    }

    private Defuzzification defuzzification(Defuzzification d, Fuzzification fuzzify,
            Map<String, FfllTokens.RangeComment> ranges) {
        List<Term> terms = new ArrayList<>();
        if (fuzzify != null) {
            terms.addAll(fuzzify.terms());
        }
        terms.addAll(d.terms());
        pointCounts(d.terms());
        Optional<Range> range = d.range();
        FfllTokens.RangeComment comment = ranges.get(Names.key(d.variable()));
        if (comment != null && range.isEmpty()) {
            range = Optional.of(comment.range());
        } else if (comment != null && (range.get().min().value() != comment.range().min().value()
                || range.get().max().value() != comment.range().max().value())) {
            warn(range.get().location(), DialectCode.FFLL_RANGES_DISAGREE, "DEFUZZIFY " + d.variable() + ": RANGE ("
                    + range.get().min().value() + " .. " + range.get().max().value() + ") is not the range of the"
                    + " declaration's comment (" + comment.range().min().value() + " .. "
                    + comment.range().max().value() + "); fclcert uses the RANGE");
        }
        Optional<Located<DefuzzificationMethod>> method = d.method();
        if (method.isEmpty()) {
            features.add(new FeatureUse(Feature.O_FFLL_NO_METHOD, d.location()));
            method = Optional.of(new Located<>(DefuzzificationMethod.COG, d.location()));
        } else {
            methodWarnings(d, method.get(), terms);
        }
        Optional<DefaultValue> defaultValue = d.defaultValue();
        if (defaultValue.isEmpty()) {
            features.add(new FeatureUse(Feature.O_FFLL_NO_DEFAULT, d.location()));
            warn(d.location(), DialectCode.FFLL_NO_DEFAULT, "DEFUZZIFY " + d.variable() + " has no DEFAULT: FFLL"
                    + " returns the smallest positive float (about 1.2E-38) when no rule fires; fclcert reads"
                    + " 'DEFAULT := 0;'");
            defaultValue = Optional.of(new DefaultValue.Constant(new Literal(0, true, d.location()), d.location()));
        }
        return new Defuzzification(d.variable(), range, terms, method, defaultValue, d.location());
    }

    private void methodWarnings(Defuzzification d, Located<DefuzzificationMethod> method, List<Term> terms) {
        String spelled = tokens.methodSpelling(method.location());
        DefuzzificationMethod m = method.value();
        boolean honoured = (m == DefuzzificationMethod.COG && "CoG".equals(spelled))
                || (m == DefuzzificationMethod.MOM && "MoM".equals(spelled));
        if (!honoured) {
            warn(method.location(), DialectCode.FFLL_METHOD_NOT_HONOURED, "METHOD: " + (spelled == null
                    ? m.keyword() : spelled) + ": FFLL honours only 'CoG' and 'MoM' spelled exactly so and"
                    + " defuzzifies " + d.variable() + " by CoG instead; fclcert reads it as IEC 61131-7 does ("
                    + m.keyword() + ")");
        } else if (m == DefuzzificationMethod.MOM) {
            warn(method.location(), DialectCode.FFLL_MOM, "METHOD: MoM: FFLL returns the middle of the peak of the"
                    + " single most activated term of " + d.variable() + "; fclcert the mean of maximum of the"
                    + " accumulated set, which differs when terms overlap or tie");
        } else if (terms.stream().anyMatch(t -> t.function() instanceof MembershipFunction.Points)) {
            warn(method.location(), DialectCode.FFLL_COG, "METHOD: CoG: FFLL adds the area of each activated term"
                    + " of " + d.variable() + " separately (overlaps count twice) on a 201-point grid; fclcert computes"
                    + " the exact CoG of the accumulated set, so results differ where terms overlap");
        }
    }

    private void pointCounts(List<Term> terms) {
        for (Term t : terms) {
            if (t.function() instanceof MembershipFunction.Points p
                    && !FFLL_POINT_COUNTS.contains(p.points().size())) {
                warn(t.location(), DialectCode.FFLL_POINT_COUNT, "term '" + t.name() + "' has " + p.points().size()
                        + " points: FFLL loads terms of 1, 3, 4 or 7 points only");
            }
        }
    }

    // ---------------------------------------------------------------- rules

    private RuleBlock ruleBlock(RuleBlock b, BlockIndex names, List<Variable> inputs, List<Variable> outputs,
            List<Fuzzification> fuzzifications) {
        List<Rule> rules = new ArrayList<>(b.rules().size());
        for (Rule r : b.rules()) {
            int[] position = {0};
            Condition condition = positional(r, r.condition(), position, names, inputs, fuzzifications);
            Optional<SourceLocation> notAnd = firstNonAnd(r.condition());
            notAnd.ifPresent(at -> warn(at, DialectCode.FFLL_NOT_AN_AND, "rule " + r.name() + ": FFLL evaluates every"
                    + " condition as the AND of its subconditions, ignoring OR, NOT and parentheses; fclcert reads the"
                    + " condition as written (Table 6)"));
            rules.add(new Rule(r.name(), condition, conclusion(r, names, outputs), r.location()));
        }
        return new RuleBlock(b.name(), b.and(), b.or(), b.activation(), b.accumulation(), rules, b.location());
    }

    /** Rebuilds the condition with every subcondition bound to the input in its position (FFLL's reading). */
    private Condition positional(Rule r, Condition c, int[] position, BlockIndex names, List<Variable> inputs,
            List<Fuzzification> fuzzifications) {
        if (c instanceof Condition.TermSubcondition s) {
            Optional<Variable> input = input(r, s.location(), position[0]++, inputs);
            if (input.isEmpty()) {
                return s;
            }
            String name = input.get().name();
            if (!Names.same(name, s.variable())) {
                warn(s.location(), DialectCode.FFLL_WRITTEN_VARIABLE_IGNORED, "rule " + r.name() + ": '"
                        + s.variable() + " IS " + s.term() + "' is subcondition " + position[0] + ", and FFLL takes"
                        + " subcondition " + position[0] + " for input '" + name + "' (the " + ordinal(position[0])
                        + " declared), whatever variable is written: read as '" + name + " IS " + s.term() + "'");
            }
            return new Condition.TermSubcondition(name, s.term(), s.negated(), s.location());
        }
        if (c instanceof Condition.VariableSubcondition v) {
            int k = position[0]++;
            boolean termOfPosition = k < inputs.size() && fuzzifications.stream()
                    .filter(f -> Names.same(f.variable(), inputs.get(k).name()))
                    .anyMatch(f -> f.term(v.variable()).isPresent());
            if (!termOfPosition && names.variable(v.variable()).isPresent()) {
                return v;   // a variable used as a degree (Table 9): standard FCL, kept as it is
            }
            Optional<Variable> input = input(r, v.location(), k, inputs);
            if (input.isEmpty()) {
                return v;
            }
            features.add(new FeatureUse(Feature.O_FFLL_TERM_ONLY_CONDITION, v.location()));
            return new Condition.TermSubcondition(input.get().name(), v.variable(), false, v.location());
        }
        if (c instanceof Condition.Not n) {
            return new Condition.Not(positional(r, n.operand(), position, names, inputs, fuzzifications), n.location());
        }
        if (c instanceof Condition.Parenthesized p) {
            return new Condition.Parenthesized(positional(r, p.inner(), position, names, inputs, fuzzifications),
                    p.location());
        }
        if (c instanceof Condition.And a) {
            List<Condition> ops = new ArrayList<>(a.operands().size());
            for (Condition o : a.operands()) {
                ops.add(positional(r, o, position, names, inputs, fuzzifications));
            }
            return new Condition.And(ops, a.location());
        }
        Condition.Or o = (Condition.Or) c;
        List<Condition> ops = new ArrayList<>(o.operands().size());
        for (Condition x : o.operands()) {
            ops.add(positional(r, x, position, names, inputs, fuzzifications));
        }
        return new Condition.Or(ops, o.location());
    }

    private Optional<Variable> input(Rule r, SourceLocation at, int k, List<Variable> inputs) {
        if (k < inputs.size()) {
            return Optional.of(inputs.get(k));
        }
        error(at, DialectCode.FFLL_NO_INPUT_IN_POSITION, "rule " + r.name() + ": subcondition " + (k + 1)
                + " has no input in its position: FFLL matches the subconditions of a rule to the inputs in their"
                + " declaration order, and this function block declares " + inputs.size() + " input(s)");
        return Optional.empty();
    }

    private static Optional<SourceLocation> firstNonAnd(Condition c) {
        if (c instanceof Condition.TermSubcondition s) {
            return s.negated() ? Optional.of(s.location()) : Optional.empty();
        }
        if (c instanceof Condition.VariableSubcondition) {
            return Optional.empty();
        }
        if (c instanceof Condition.Parenthesized p && p.inner() instanceof Condition.TermSubcondition) {
            return firstNonAnd(p.inner());   // '(x IS t)' is FFLL's own strict form: the parentheses change nothing
        }
        if (c instanceof Condition.And a) {
            for (Condition o : a.operands()) {
                Optional<SourceLocation> at = firstNonAnd(o);
                if (at.isPresent()) {
                    return at;
                }
            }
            return Optional.empty();
        }
        return Optional.of(c.location());   // Or, Not, Parenthesized
    }

    private List<Subconclusion> conclusion(Rule r, BlockIndex names, List<Variable> outputs) {
        List<Subconclusion> result = new ArrayList<>(r.conclusion().size());
        for (int k = 0; k < r.conclusion().size(); k++) {
            Subconclusion s = r.conclusion().get(k);
            s.weight().ifPresent(w -> warn(w.location(), DialectCode.FFLL_WITH_IGNORED, "rule " + r.name()
                    + ": FFLL ignores WITH; fclcert applies the weighting factor as IEC 61131-7 does (5.2.4)"));
            if (!s.bareVariable() || names.variable(s.variable()).isPresent()) {
                result.add(s);
                continue;
            }
            if (k >= outputs.size()) {
                error(s.location(), DialectCode.FFLL_NO_OUTPUT_IN_POSITION, "rule " + r.name() + ": '" + s.variable()
                        + "' names no variable, so it is a term of the output in position " + (k + 1) + ", but this"
                        + " function block declares " + outputs.size() + " output(s)");
                result.add(s);
                continue;
            }
            features.add(new FeatureUse(Feature.O_FFLL_TERM_ONLY_CONCLUSION, s.location()));
            result.add(new Subconclusion(outputs.get(k).name(), Optional.of(s.variable()), s.weight(), s.location()));
        }
        return result;
    }

    private static String ordinal(int n) {
        return n + (n % 100 >= 11 && n % 100 <= 13 ? "th" : switch (n % 10) {
            case 1 -> "st";
            case 2 -> "nd";
            case 3 -> "rd";
            default -> "th";
        });
    }

    private void warn(SourceLocation at, DialectCode code, String message) {
        diagnostics.add(Diagnostic.warning(at, code, message));
    }

    /** Capped like the other readers' errors: one rule of 10^5 misplaced subconditions gave 10^5 FCL-D101. */
    private void error(SourceLocation at, DialectCode code, String message) {
        if (++errors > DialectParser.MAX_ERRORS) {
            if (errors == DialectParser.MAX_ERRORS + 1) {
                diagnostics.add(Diagnostic.error(at, DialectCode.TOO_MANY_ERRORS,
                        "more than " + DialectParser.MAX_ERRORS + " errors; the rest are not reported"));
            }
            return;
        }
        diagnostics.add(Diagnostic.error(at, code, message));
    }
}
