package org.fclcert.write;

import java.util.ArrayList;
import java.util.LinkedHashMap;
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
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.syntax.dialect.Dialect;

/**
 * Writes a program as the Free Fuzzy Logic Library reads FCL, in the layout of its own sample: declarations
 * {@code name REAL; (* RANGE(lo .. hi) *)} (FFLL loads no variable without its range comment), output terms in a
 * FUZZIFY block of the output, DEFUZZIFY with METHOD only, {@code ACCUM}, rules that AND one subcondition per
 * input in declaration order (FFLL binds subconditions by position). To say in that form what a rule says,
 * the writer puts the condition in disjunctive normal form, one rule per conjunction ({@link FfllRules}), gives an
 * input a rule does not name a term of degree 1 everywhere ({@code anything}: the unit of MIN, PROD and BDIF),
 * and gives a negated subcondition a complement term ({@code not_t}, the points (x, 1 − y)); point lists are
 * padded to the 1, 3, 4 or 7 points FFLL loads by repeating their last point. All of that is exact.
 */
public final class FfllWriter implements DialectWriter {
    private static final String IN = "    ";

    @Override
    public Dialect dialect() {
        return Dialect.FFLL;
    }

    @Override
    public Written write(Program program) {
        Findings findings = new Findings("FFLL");
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < program.functionBlocks().size(); i++) {
            if (i > 0) {
                out.append('\n');
            }
            OutputConditions.check(program, program.functionBlocks().get(i), findings, null);
            structure(program, program.functionBlocks().get(i), i, findings);
            new Block(new BlockContext(program.functionBlocks().get(i), findings)).write(out);
        }
        return new Written(Dialect.FFLL, out.toString(), findings.losses(), findings.differences());
    }

    /**
     * What FFLL's model cannot hold: it reads the first VAR_INPUT, VAR_OUTPUT and RULEBLOCK of a file, has one
     * output variable (a second: "Model Already Has An Output Variable") and one rule block.
     */
    private static void structure(Program program, FunctionBlock fb, int index, Findings findings) {
        if (index > 0) {
            findings.lost(fb.location(), WriterCode.STRUCTURE, "FFLL reads one function block; '" + fb.name()
                    + "' is written after the first, which FFLL alone would read");
        }
        List<Variable> outputs = fb.variables(VariableKind.OUTPUT);
        if (outputs.size() > 1) {
            findings.lost(outputs.get(1).location(), WriterCode.STRUCTURE, "FFLL's model has one output variable;"
                    + " '" + fb.name() + "' has " + outputs.size() + " (FFLL refuses the second)");
        }
        if (fb.ruleBlocks().size() > 1) {
            findings.lost(fb.ruleBlocks().get(1).location(), WriterCode.STRUCTURE, "FFLL reads the first RULEBLOCK"
                    + " only; '" + fb.name() + "' has " + fb.ruleBlocks().size());
        }
    }

    /** One function block: rules first (they may add terms), then the text in FFLL's order. */
    private static final class Block {
        final BlockContext cx;
        final FunctionBlock fb;
        final List<Variable> inputs;
        /** Terms added to an input, by input key: name → points. */
        final Map<String, Map<String, List<double[]>>> added = new LinkedHashMap<>();
        /** The RANGE written for each input, by key. */
        final Map<String, double[]> spans = new java.util.HashMap<>();

        Block(BlockContext cx) {
            this.cx = cx;
            this.fb = cx.fb;
            this.inputs = fb.variables(VariableKind.INPUT);
        }

        void write(StringBuilder out) {
            List<String> blocks = new ArrayList<>();
            for (RuleBlock rb : fb.ruleBlocks()) {
                blocks.add(ruleBlock(rb));
            }
            out.append("FUNCTION_BLOCK ").append(fb.name()).append("\n\n");
            for (VariableKind kind : List.of(VariableKind.INPUT, VariableKind.OUTPUT)) {
                List<Variable> vs = fb.variables(kind);
                if (vs.isEmpty()) {
                    continue;
                }
                out.append(kind.keyword()).append('\n');
                for (Variable v : vs) {
                    FuzzyliteWriter.initialValue(cx, v);
                    double[] span = kind == VariableKind.INPUT ? inputSpan(v.name()) : fb.defuzzification(v.name()).map(cx::outputSpan)
                            .orElse(new double[] {0, 1});
                    out.append(IN).append(v.name()).append(' ').append(v.type().name()).append("; (* RANGE(")
                            .append(LibraryText.number(span[0])).append(" .. ").append(LibraryText.number(span[1]))
                            .append(") *)\n");
                }
                out.append("END_VAR\n\n");
            }
            fb.options().forEach(o -> cx.findings.differs(o.location(), WriterCode.LEFT_OUT, "FFLL has no OPTIONS"
                    + " block; it is left out (fclcert gives it no meaning)"));
            for (Fuzzification f : fb.fuzzifications()) {
                out.append("FUZZIFY ").append(cx.variable(f.variable())).append('\n');
                for (Term t : f.terms()) {
                    term(t, inputSpan(f.variable()), out);
                }
                addedTerms(f.variable(), out);
                out.append("END_FUZZIFY\n\n");
            }
            for (Variable v : inputs) {
                if (fb.fuzzification(v.name()).isEmpty() && added.containsKey(Names.key(v.name()))) {
                    out.append("FUZZIFY ").append(v.name()).append('\n');
                    addedTerms(v.name(), out);
                    out.append("END_FUZZIFY\n\n");
                }
            }
            for (Defuzzification d : fb.defuzzifications()) {
                out.append("FUZZIFY ").append(cx.variable(d.variable())).append('\n');
                for (Term t : d.terms()) {
                    term(t, cx.outputSpan(d), out);
                }
                out.append("END_FUZZIFY\n\n");
            }
            for (Defuzzification d : fb.defuzzifications()) {
                defuzzify(d, out);
            }
            blocks.forEach(out::append);
            out.append("END_FUNCTION_BLOCK\n");
        }

        /**
         * The RANGE written for an input: its own, widened to the right where a shoulder rising to the end needs it
         * ({@link FfllShapes#rightEnd}): FFLL clamps inputs to the RANGE and every term is constant beyond its last
         * point, so a wider RANGE to the right changes no degree, only the grid.
         */
        private double[] inputSpan(String input) {
            return spans.computeIfAbsent(Names.key(input), k -> {
                double[] span = fb.fuzzification(input).map(cx::inputSpan).orElse(new double[] {0, 1});
                double hi = span[1];
                for (Term t : fb.fuzzification(input).map(Fuzzification::terms).orElse(List.of())) {
                    if (t.function() instanceof MembershipFunction.Points p) {
                        Optional<List<double[]>> xy = literal(p.points());
                        if (xy.isPresent()) {
                            hi = Math.max(hi, FfllShapes.rightEnd(xy.get(), span[0], span[1]));
                            List<double[]> complement = xy.get().stream().map(q -> new double[] {q[0], 1 - q[1]}).toList();
                            hi = Math.max(hi, FfllShapes.rightEnd(complement, span[0], span[1]));
                        }
                    }
                }
                return new double[] {span[0], hi};
            });
        }

        private void addedTerms(String input, StringBuilder out) {
            added.getOrDefault(Names.key(input), Map.of()).forEach((name, points) ->
                    out.append(IN).append("TERM ").append(name).append(" := ").append(pointsText(points)).append(";\n"));
        }

        private void term(Term t, double[] span, StringBuilder out) {
            out.append(IN).append("TERM ").append(t.name()).append(" := ");
            MembershipFunction f = t.function();
            if (f instanceof MembershipFunction.Singleton s) {
                out.append(cx.numberText(s.value(), 0, WriterCode.POINT_VARIABLE, "singleton '" + t.name() + "'"))
                        .append(";\n");
                return;
            }
            if (f instanceof MembershipFunction.Computed c) {
                // a place-holder singleton keeps the rules that name the term (one point would not read back)
                LibraryText.computedLost(cx, t, c, "FFLL");
                out.append(LibraryText.number(span[0])).append(";\n");
                return;
            }
            List<Point> points = points(t, span);
            Optional<List<double[]>> literal = literal(points);
            if (literal.isPresent()) {
                Optional<List<double[]>> form = FfllShapes.form(literal.get(), span[0], span[1]);
                if (form.isPresent()) {
                    out.append(pointsText(form.get())).append(";\n");
                    return;
                }
                cx.findings.lost(t.location(), WriterCode.SHAPE, FfllShapes.why(t.name(), span[0], span[1]));
            }
            if (points.size() > 7) {
                cx.findings.differs(t.location(), WriterCode.NOT_LOADED, "term '" + t.name() + "' has "
                        + points.size() + " points; FFLL loads terms of 1, 3, 4 or 7 points only");
            }
            while (points.size() == 2 || points.size() == 5 || points.size() == 6) {
                points.add(points.get(points.size() - 1));   // a repeated last point changes no degree
            }
            out.append(LibraryText.points(points, cx, t.name())).append(";\n");
        }

        /** The points as numbers, when none is given by a variable. */
        private static Optional<List<double[]>> literal(List<Point> points) {
            List<double[]> out = new ArrayList<>();
            for (Point p : points) {
                if (!(p.x() instanceof Literal x) || !(p.degree() instanceof Literal y)) {
                    return Optional.empty();
                }
                out.add(new double[] {x.value(), y.value()});
            }
            return Optional.of(out);
        }

        private static String pointsText(List<double[]> points) {
            List<String> ps = new ArrayList<>();
            for (double[] p : points) {
                ps.add("(" + LibraryText.number(p[0]) + ", " + LibraryText.number(p[1]) + ")");
            }
            return String.join(" ", ps);
        }

        private List<Point> points(Term t, double[] span) {
            MembershipFunction f = t.function();
            if (f instanceof MembershipFunction.Points p) {
                return new ArrayList<>(p.points());
            }
            MembershipFunction.NamedShape n = (MembershipFunction.NamedShape) f;
            Optional<List<Point>> exact = ShapePoints.exact(n);
            if (exact.isPresent()) {
                return new ArrayList<>(exact.get());
            }
            ShapePoints.Approximation a = ShapePoints.approximate(n, span[0], span[1], 101);
            cx.findings.lost(t.location(), WriterCode.SHAPE, "FFLL has no " + n.kind() + " shape; term '" + t.name()
                    + "' is written as points, membership error up to " + LibraryText.upTo3Digits(a.maxError()));
            return new ArrayList<>(a.points());
        }

        private void defuzzify(Defuzzification d, StringBuilder out) {
            String name = cx.variable(d.variable());
            out.append("DEFUZZIFY ").append(name).append('\n');
            DefuzzificationMethod m = d.method().map(Located::value).orElse(DefuzzificationMethod.COG);
            var at = d.method().map(Located::location).orElse(d.location());
            if (m == DefuzzificationMethod.COGSS) {
                cx.findings.lost(at, WriterCode.METHOD, "FFLL has no COGSS; '" + name + "' is written with CoGS");
                m = DefuzzificationMethod.COGS;
            } else if (m == DefuzzificationMethod.TSUKAMOTO) {
                cx.findings.lost(at, WriterCode.METHOD, "FFLL has no Tsukamoto method; '" + name + "' is written with"
                        + " CoG");
                m = DefuzzificationMethod.COG;
            }
            out.append(IN).append("METHOD: ").append(m.keyword()).append(";\n");
            if (m == DefuzzificationMethod.COG && cx.pointTerms(d.variable())) {
                cx.findings.differs(at, WriterCode.SAMPLED, "FFLL computes CoG of '" + name + "' on a 201 × 101 grid,"
                        + " adding each activated term's area (overlaps count twice)");
            } else if (m == DefuzzificationMethod.MOM) {
                cx.findings.differs(at, WriterCode.IGNORED_BY_LIBRARY, "FFLL's MoM of '" + name + "' is the middle of"
                        + " the peak of the single most activated term, not the mean of maxima of the accumulated set");
            } else if (m != DefuzzificationMethod.COG) {
                cx.findings.differs(at, WriterCode.IGNORED_BY_LIBRARY, "FFLL honours only CoG and MoM; it computes"
                        + " '" + name + "' with CoG instead of " + m.keyword());
            }
            Optional<DefaultValue> def = d.defaultValue();
            if (def.isPresent() && def.get() instanceof DefaultValue.Constant c && Double.isNaN(c.value().value())) {
                cx.findings.lost(c.location(), WriterCode.DEFAULT, "FFLL has no DEFAULT := nan; '" + name
                        + "' is written without DEFAULT (0)");
                def = Optional.empty();
            }
            boolean zero = def.isEmpty() || def.get() instanceof DefaultValue.Constant c && c.value().value() == 0;
            if (!zero) {
                String value = def.get() instanceof DefaultValue.Constant c ? LibraryText.number(c.value()) : "NC";
                out.append(IN).append("DEFAULT := ").append(value).append(";\n");
                cx.findings.differs(def.get().location(), WriterCode.IGNORED_BY_LIBRARY, "FFLL has no DEFAULT: when no"
                        + " rule concludes '" + name + "' it gives the smallest positive float, not " + value);
            }
            out.append("END_DEFUZZIFY\n\n");
        }

        private String ruleBlock(RuleBlock rb) {
            StringBuilder out = new StringBuilder("RULEBLOCK ").append(rb.name()).append('\n');
            AndAlgorithm and = rb.and().map(Located::value).orElse(rb.or().map(o -> o.value().pair())
                    .orElse(AndAlgorithm.MIN));
            OrAlgorithm or = rb.or().map(Located::value).orElse(null);
            AccumulationMethod accu = rb.accumulation().map(Located::value).orElse(AccumulationMethod.MAX);
            if (!and.standard()) {
                // FFLL's reader takes Table 3's names only (it would refuse the program), and it ANDs with MIN anyway
                cx.findings.lost(rb.and().map(Located::location).orElse(rb.location()), WriterCode.OPERATOR, "FFLL has no"
                        + " AND " + and.name() + "; rule block '" + rb.name() + "' is written with AND MIN");
                and = AndAlgorithm.MIN;
            }
            // FFLL reads the line after the RULEBLOCK's name as the AND line and the next as the ACCU line, nothing
            // between them (an ACT line makes it refuse the program); it ANDs and activates with MIN whatever is written
            out.append(IN).append("AND: ").append(and.name()).append(";\n");
            if (and != AndAlgorithm.MIN) {
                cx.findings.differs(rb.and().map(Located::location).orElse(rb.location()), WriterCode.IGNORED_BY_LIBRARY,
                        "FFLL ANDs subconditions with MIN whatever AND says (rule block '" + rb.name() + "')");
            }
            rb.activation().ifPresent(a -> {
                if (a.value() != org.fclcert.model.ActivationMethod.MIN && concludesPointTerms(rb)) {
                    cx.findings.lost(a.location(), WriterCode.OPERATOR, "FFLL has no ACT: it activates with MIN"
                            + " (an ACT line between AND and ACCUM makes it refuse the program); rule block '" + rb.name()
                            + "' is written without ACT " + a.value());
                }
            });
            if (accu != AccumulationMethod.MAX && accu != AccumulationMethod.BSUM) {
                cx.findings.lost(rb.accumulation().get().location(), WriterCode.ACCUMULATION, "FFLL reads ACCU MAX and"
                        + " BSUM only (any other it refuses); rule block '" + rb.name() + "' is written with MAX");
                accu = AccumulationMethod.MAX;
            } else if (accu == AccumulationMethod.BSUM) {
                cx.findings.differs(rb.accumulation().get().location(), WriterCode.IGNORED_BY_LIBRARY, "FFLL reads"
                        + " ACCU BSUM as MIN: it keeps the least degree of each output term (rule block '" + rb.name()
                        + "')");
            }
            out.append(IN).append("ACCUM: ").append(accu.name()).append(";\n");
            List<String[]> rules = new ArrayList<>();
            boolean split = false;
            for (Rule r : rb.rules()) {
                List<String> conditions = conditions(r, and, or, accu);
                split |= conditions.size() != 1;
                String conclusion = conclusion(r);
                if (conclusion == null) {
                    continue;
                }
                for (String c : conditions) {
                    rules.add(new String[] {r.name(), c, conclusion});
                }
            }
            Map<String, String[]> cells = new LinkedHashMap<>();
            for (String[] r : rules) {
                String[] before = cells.putIfAbsent(r[1], r);
                if (before != null && !before[2].equals(r[2])) {
                    cx.findings.lost(rb.location(), WriterCode.RULE_FORM, "rules " + before[0] + " and " + r[0]
                            + " share the condition " + r[1] + " and conclude differently; FFLL's rules are a table with"
                            + " one conclusion per combination of input terms, and it keeps the last");
                }
            }
            for (int i = 0; i < rules.size(); i++) {
                String[] r = rules.get(i);
                out.append(IN).append("RULE ").append(split ? Integer.toString(i) : r[0]).append(": IF ").append(r[1])
                        .append(" THEN ").append(r[2]).append(";\n");
            }
            return out.append("END_RULEBLOCK\n\n").toString();
        }

        private boolean concludesPointTerms(RuleBlock rb) {
            return rb.rules().stream().flatMap(r -> r.conclusion().stream()).map(Subconclusion::variable).distinct()
                    .anyMatch(cx::pointTerms);
        }

        /** The rule's condition as FFLL conditions (one per conjunction); empty when it has no FFLL form. */
        private List<String> conditions(Rule r, AndAlgorithm and, OrAlgorithm or, AccumulationMethod accu) {
            List<List<FfllRules.Literal>> dnf;
            try {
                dnf = FfllRules.dnf(r.condition(), and, or, accu);
            } catch (FfllRules.Unsayable e) {
                cx.findings.lost(r.location(), WriterCode.RULE_FORM, "rule " + r.name() + " has no FFLL form: "
                        + e.getMessage() + "; it is left out");
                return List.of();
            }
            List<String> out = new ArrayList<>();
            for (List<FfllRules.Literal> conjunction : dnf) {
                String[] terms = new String[inputs.size()];
                String problem = null;
                for (FfllRules.Literal l : conjunction) {
                    int k = index(l.variable());
                    if (k < 0) {
                        problem = "'" + l.variable() + "' is not an input";
                        break;
                    }
                    String term = l.negated() ? complement(inputs.get(k), l.term()) : cx.term(l.variable(), l.term());
                    if (term == null) {
                        problem = "'" + l.term() + "' of '" + l.variable() + "' has no complement term FFLL can hold"
                                + " (a singleton, or its complement is no triangle, trapezoid or shoulder)";
                        break;
                    }
                    if (terms[k] != null && !(terms[k].equals(term) && and == AndAlgorithm.MIN)) {
                        problem = "it names input '" + inputs.get(k).name() + "' twice in one conjunction";
                        break;
                    }
                    terms[k] = term;
                }
                if (problem != null) {
                    cx.findings.lost(r.location(), WriterCode.RULE_FORM, "rule " + r.name() + " has no FFLL form: "
                            + problem + " (FFLL takes one subcondition per input); it is left out");
                    return List.of();
                }
                if (and == AndAlgorithm.BDIF && java.util.Arrays.stream(terms).anyMatch(java.util.Objects::isNull)) {
                    cx.findings.lost(r.location(), WriterCode.RULE_FORM, "rule " + r.name() + " does not name every"
                            + " input, as FFLL needs; under AND BDIF an added subcondition of degree 1 changes how the sum"
                            + " rounds (a + 1 − 1), so a degree near 0 may fire on one side only; it is written so anyway");
                }
                StringBuilder c = new StringBuilder();
                for (int k = 0; k < inputs.size(); k++) {
                    String term = terms[k] != null ? terms[k] : anything(inputs.get(k));
                    // parenthesised: FFLL reads '(x IS t)' by position, and takes a bare first word for its shorthand
                    c.append(k == 0 ? "(" : " AND (").append(inputs.get(k).name()).append(" IS ").append(term).append(')');
                }
                out.add(c.toString());
            }
            return out;
        }

        private String conclusion(Rule r) {
            List<String> parts = new ArrayList<>();
            for (Subconclusion s : r.conclusion()) {
                if (s.bareVariable()) {
                    cx.findings.lost(s.location(), WriterCode.BARE_VARIABLE, "rule " + r.name() + " concludes the"
                            + " variable '" + s.variable() + "' itself (Table 9), which FFLL cannot say: left out");
                    continue;
                }
                String text = "(" + cx.variable(s.variable()) + " IS " + cx.term(s.variable(), s.term().get()) + ")";
                if (s.weight().isPresent()) {
                    String w = cx.numberText(s.weight().get(), 1.0, WriterCode.WEIGHT_VARIABLE, "the weight of '"
                            + s.variable() + "' in rule " + r.name());
                    text += " WITH " + w;
                    if (Double.parseDouble(w) != 1) {
                        cx.findings.differs(s.location(), WriterCode.IGNORED_BY_LIBRARY, "FFLL ignores WITH (rule "
                                + r.name() + ")");
                    }
                }
                parts.add(text);
            }
            if (parts.isEmpty()) {
                cx.findings.lost(r.location(), WriterCode.RULE_FORM, "rule " + r.name() + " is left out: nothing of"
                        + " its conclusion is left that FFLL can say");
                return null;
            }
            return String.join(", ", parts);
        }

        private int index(String variable) {
            for (int k = 0; k < inputs.size(); k++) {
                if (Names.same(inputs.get(k).name(), variable)) {
                    return k;
                }
            }
            return -1;
        }

        /** A term of degree 1 everywhere on the input, added once. */
        private String anything(Variable input) {
            Map<String, List<double[]>> terms = added.computeIfAbsent(Names.key(input.name()), k -> new LinkedHashMap<>());
            for (Map.Entry<String, List<double[]>> e : terms.entrySet()) {
                if (e.getKey().startsWith("anything")) {
                    return e.getKey();
                }
            }
            double[] span = inputSpan(input.name());
            String name = fresh(input, "anything");
            terms.put(name, FfllShapes.everywhere(span[0], span[1]));
            return name;
        }

        /** The complement of a point term (x, 1 − y), added once; null for a singleton or a term with variables. */
        private String complement(Variable input, String term) {
            Optional<Term> t = fb.fuzzification(input.name()).flatMap(f -> f.term(term));
            if (t.isEmpty() || t.get().function() instanceof MembershipFunction.Singleton) {
                return null;
            }
            double[] span = inputSpan(input.name());
            List<Point> points = points(t.get(), span);
            if (points.stream().anyMatch(p -> !(p.x() instanceof Literal) || !(p.degree() instanceof Literal))) {
                return null;
            }
            Map<String, List<double[]>> terms = added.computeIfAbsent(Names.key(input.name()), k -> new LinkedHashMap<>());
            String wanted = "not_" + t.get().name();
            if (terms.containsKey(wanted)) {
                return wanted;
            }
            List<double[]> ps = new ArrayList<>();
            for (Point p : points) {
                ps.add(new double[] {((Literal) p.x()).value(), 1 - ((Literal) p.degree()).value()});
            }
            Optional<List<double[]>> form = FfllShapes.form(ps, span[0], span[1]);
            if (form.isEmpty()) {
                return null;
            }
            String name = fresh(input, wanted);
            terms.put(name, form.get());
            return name;
        }

        /** {@code base}, or base_2, base_3, …: a name no term of the input, no added term and no variable has. */
        private String fresh(Variable input, String base) {
            String name = base;
            for (int i = 2; taken(input, name); i++) {
                name = base + "_" + i;
            }
            return name;
        }

        private boolean taken(Variable input, String name) {
            return cx.terms(input.name()).stream().anyMatch(t -> Names.same(t.name(), name))
                    || fb.variable(name).isPresent()
                    || added.getOrDefault(Names.key(input.name()), Map.of()).keySet().stream()
                            .anyMatch(n -> Names.same(n, name));
        }
    }
}
