package org.fclcert.lsp;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.Point;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableRef;
import org.fclcert.write.LiteralText;

/**
 * Hover: check's own line for a diagnostic at the place; for a variable its declaration, type, RANGE and terms;
 * for a term its shape, points and where its degree is 1; for a keyword the clause that defines it and its
 * meaning. Names are resolved by the {@link Outline}; what they are comes from the program's model.
 */
final class Hovers {
    private Hovers() {
    }

    static Optional<Hover> at(Snapshot s, Position p) {
        List<String> parts = new ArrayList<>();
        int offset = s.source().offset(p);
        for (org.fclcert.model.Diagnostic d : s.diagnostics()) {
            Range r = Diagnostics.range(s, d);
            int from = s.source().offset(r.getStart());
            int to = s.source().offset(r.getEnd());
            if (from <= offset && (offset < to || (from == to && offset == from))) {
                parts.add("`" + d + "`");
            }
        }
        Outline outline = s.outline();
        int line = p.getLine() + 1;
        int column = s.text().codePointCount(s.source().offset(new Position(p.getLine(), 0)), offset);
        int index = outline.tokenAt(line, column, false);
        Range range = null;
        if (index >= 0) {
            Outline.Tok t = outline.tokens().get(index);
            range = Navigation.range(s, t);
            Optional<Outline.Occurrence> o = outline.occurrenceAt(index);
            if (o.isPresent()) {
                describe(s, o.get()).ifPresent(parts::add);
            } else if (!t.isName()) {
                KeywordHelp.of(t.text()).ifPresent(h -> parts.add("**" + t.text() + "** (IEC 61131-7 " + h.clause()
                        + "): " + h.meaning()));
            }
        }
        if (parts.isEmpty()) {
            return Optional.empty();
        }
        Hover h = new Hover(new MarkupContent(MarkupKind.MARKDOWN, String.join("\n\n", parts)));
        h.setRange(range);
        return Optional.of(h);
    }

    private static Optional<String> describe(Snapshot s, Outline.Occurrence o) {
        Optional<FunctionBlock> fb = s.program().flatMap(p -> p.functionBlock(o.block() == null ? "" : o.block()));
        return switch (o.kind()) {
            case FUNCTION_BLOCK -> Optional.of("**FUNCTION_BLOCK " + o.name() + "**: " + s.dialectNote()
                    + fb.map(b -> "; " + b.variables().size() + " variables, " + b.ruleBlocks().size() + " rule blocks")
                            .orElse(""));
            case VARIABLE -> fb.flatMap(b -> b.variable(o.name()).map(v -> variable(b, v)))
                    .or(() -> declaredOnly(s, o));
            case TERM -> fb.flatMap(b -> term(b, o.owner(), o.name()));
            case RULE_BLOCK -> fb.flatMap(b -> b.ruleBlock(o.name())).map(Hovers::ruleBlock);
            case RULE -> Optional.empty();
        };
    }

    /** Without a model (a text the reader cannot make one of): where the tokens say the variable is declared. */
    private static Optional<String> declaredOnly(Snapshot s, Outline.Occurrence o) {
        return s.outline().declaration(o).filter(d -> d.section() != null).map(d -> "**" + d.name() + "** — declared in "
                + d.section().keyword() + " of " + d.block() + ", line " + s.outline().tokens().get(d.token()).line()
                + " (the text has errors the reader cannot mend, so its type and terms are not shown)");
    }

    static String variable(FunctionBlock b, Variable v) {
        StringBuilder s = new StringBuilder("**" + v.name() + "** : " + v.type() + " — declared in "
                + v.kind().keyword() + " of " + b.name() + ", line " + v.location().line());
        v.initialValue().ifPresent(l -> s.append("; initial value ").append(LiteralText.of(l)));
        Optional<Defuzzification> d = b.defuzzification(v.name());
        d.flatMap(Defuzzification::range).ifPresent(r -> s.append("\n\nRANGE (").append(LiteralText.of(r.min()))
                .append(" .. ").append(LiteralText.of(r.max())).append(")"));
        d.flatMap(Defuzzification::method).ifPresent(m -> s.append("\n\nMETHOD : ").append(m.value().keyword()));
        d.flatMap(Defuzzification::defaultValue).ifPresent(dv -> s.append("\n\nDEFAULT := ").append(
                dv instanceof DefaultValue.Constant c ? LiteralText.of(c.value()) : "NC"));
        List<Term> terms = b.fuzzification(v.name()).map(Fuzzification::terms)
                .or(() -> d.map(Defuzzification::terms)).orElse(List.of());
        if (!terms.isEmpty()) {
            s.append("\n\nterms: ").append(String.join(", ", terms.stream().map(Term::name).toList()));
        }
        return s.toString();
    }

    static Optional<String> term(FunctionBlock b, String variable, String name) {
        if (variable == null) {
            return Optional.empty();
        }
        Optional<Term> t = b.fuzzification(variable).flatMap(f -> f.term(name))
                .or(() -> b.defuzzification(variable).flatMap(d -> d.term(name)));
        return t.map(term -> "**" + variable + " IS " + term.name() + "**: " + TermShape.describe(term.function()));
    }

    private static String ruleBlock(RuleBlock rb) {
        StringBuilder s = new StringBuilder("**RULEBLOCK " + rb.name() + "**: " + rb.rules().size() + " rules");
        rb.and().ifPresent(a -> s.append("; AND : ").append(a.value()));
        rb.or().ifPresent(a -> s.append("; OR : ").append(a.value()));
        rb.activation().ifPresent(a -> s.append("; ACT : ").append(a.value()));
        rb.accumulation().ifPresent(a -> s.append("; ACCU : ").append(a.value()));
        return s.toString();
    }

    static String operand(Operand o) {
        return o instanceof Literal l ? LiteralText.of(l) : ((VariableRef) o).name();
    }

    /** A membership function in words: its shape, its points and where its degree is 1 (5.2.2, 5.2.3). */
    static final class TermShape {
        private TermShape() {
        }

        static String describe(MembershipFunction f) {
            if (f instanceof MembershipFunction.Singleton single) {
                return "singleton: degree 1 at " + operand(single.value()) + ", 0 elsewhere";
            }
            if (f instanceof MembershipFunction.NamedShape named) {
                return named.kind() + " " + String.join(" ", named.parameters().stream().map(LiteralText::of).toList())
                        + named.points().map(ps -> "; " + points(ps)).orElse("");
            }
            if (f instanceof MembershipFunction.Computed c) {
                return "computed: " + c.written();
            }
            return points(((MembershipFunction.Points) f).points());
        }

        private static String points(List<Point> ps) {
            return shape(ps) + " through " + String.join(" ", ps.stream()
                    .map(p -> "(" + operand(p.x()) + ", " + operand(p.degree()) + ")").toList()) + "; " + whereOne(ps);
        }

        private static String shape(List<Point> ps) {
            double[] y = new double[ps.size()];
            for (int i = 0; i < y.length; i++) {
                if (!(ps.get(i).degree() instanceof Literal l)) {
                    return "piece-wise linear";
                }
                y[i] = l.value();
            }
            if (y.length == 2) {
                return y[0] < y[1] ? "rising ramp" : y[0] > y[1] ? "falling ramp" : "constant";
            }
            if (y.length == 3 && y[0] == 0 && y[1] == 1 && y[2] == 0) {
                return "triangle";
            }
            if (y.length == 4 && y[0] == 0 && y[1] == 1 && y[2] == 1 && y[3] == 0) {
                return "trapezoid";
            }
            return "piece-wise linear";
        }

        /** Where the degree is 1: the points of degree 1, joined into intervals, and beyond an outer one. */
        private static String whereOne(List<Point> ps) {
            List<String> where = new ArrayList<>();
            int n = ps.size();
            for (int i = 0; i < n; i++) {
                if (!one(ps.get(i))) {
                    continue;
                }
                int j = i;
                while (j + 1 < n && one(ps.get(j + 1))) {
                    j++;
                }
                String from = operand(ps.get(i).x());
                String to = operand(ps.get(j).x());
                if (i == 0 && j == n - 1) {
                    where.add("everywhere");
                } else if (i == 0) {
                    where.add("x ≤ " + to);
                } else if (j == n - 1) {
                    where.add("x ≥ " + from);
                } else {
                    where.add(i == j ? "x = " + from : from + " ≤ x ≤ " + to);
                }
                i = j;
            }
            return where.isEmpty() ? "degree 1 nowhere" : "degree 1 at " + String.join(" and ", where);
        }

        private static boolean one(Point p) {
            return p.degree() instanceof Literal l && l.value() == 1.0;
        }
    }
}
