package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.syntax.ReservedWords;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.MembershipFunction.Points;
import org.fclcert.model.MembershipFunction.Singleton;
import org.fclcert.model.Operand;
import org.fclcert.model.OptionsBlock;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * Writes a program as standard FCL text in one fixed layout, so that equal models give equal text
 * and reading the text back gives the same model (comments are not part of the model and are lost).
 *
 * <p>Layout: keywords in upper case, except the defuzzification methods, which are spelled as
 * Table 1 and the 5.4 production spell them ({@code CoG}, {@code CoGS}, {@code CoA}, {@code LM},
 * {@code RM}); names as declared; four spaces of indentation; one declaration, term, setting or
 * rule per line; the blocks of a function block in the order of the 5.4 production (variable
 * sections, FUZZIFY, DEFUZZIFY, RULEBLOCK, OPTIONS) with a blank line between blocks; DEFUZZIFY
 * items in the 5.4 order (RANGE, terms, METHOD, DEFAULT), RANGE in the 5.4 form {@code RANGE (a .. b);}
 * (the prose form {@code RANGE := (...)} draws a reader warning); a rule's second and later
 * subconclusions on their own lines. OPTIONS content is written verbatim. Numbers are spelled by {@link LiteralText}.
 *
 * <p>Dialect models: a linear named shape (triangle, trapezoid, rectangle, ramp) is written as its exact
 * points; a smooth named shape or a hedge has no standard spelling and is refused with
 * IllegalArgumentException (convert the program first, see {@link ShapePoints}).
 */
public final class CanonicalWriter {
    static final String INDENT = "    ";

    /** The whole program; function blocks separated by a blank line, text ending in a newline. */
    public String write(Program program) {
        List<String> blocks = program.functionBlocks().stream().map(this::write).toList();
        return String.join("\n", blocks);
    }

    /** One function block, ending in a newline. */
    public String write(FunctionBlock fb) {
        List<String> sections = new ArrayList<>(variableSections(fb.variables()));
        fb.fuzzifications().forEach(f -> sections.add(fuzzify(f)));
        fb.defuzzifications().forEach(d -> sections.add(defuzzify(d)));
        fb.ruleBlocks().forEach(b -> sections.add(ruleBlock(b)));
        fb.options().forEach(o -> sections.add(options(o)));
        return "FUNCTION_BLOCK " + name(fb.name()) + "\n" + String.join("\n", sections) + "END_FUNCTION_BLOCK\n";
    }

    /**
     * One section per run of consecutive variables of the same kind, so the declaration order is
     * kept; local variables come last because 5.4 puts {@code other_var_declarations} after the
     * input and output sections.
     */
    private static List<String> variableSections(List<Variable> variables) {
        List<Variable> ordered = new ArrayList<>(variables.stream().filter(v -> v.kind() != VariableKind.LOCAL).toList());
        ordered.addAll(variables.stream().filter(v -> v.kind() == VariableKind.LOCAL).toList());
        List<String> sections = new ArrayList<>();
        StringBuilder section = null;
        VariableKind current = null;
        for (Variable v : ordered) {
            if (v.kind() != current) {
                closeSection(sections, section);
                section = new StringBuilder(v.kind().keyword()).append('\n');
                current = v.kind();
            }
            section.append(INDENT).append(declaration(v)).append('\n');
        }
        closeSection(sections, section);
        return sections;
    }

    private static void closeSection(List<String> sections, StringBuilder section) {
        if (section != null) {
            sections.add(section.append("END_VAR\n").toString());
        }
    }

    private static String declaration(Variable v) {
        String init = v.initialValue().map(l -> " := " + LiteralText.of(l)).orElse("");
        return name(v.name()) + " : " + v.type().name() + init + ";";
    }

    private static String fuzzify(Fuzzification f) {
        StringBuilder out = new StringBuilder("FUZZIFY ").append(name(f.variable())).append('\n');
        f.terms().forEach(t -> line(out, term(t)));
        return out.append("END_FUZZIFY\n").toString();
    }

    private static String defuzzify(Defuzzification d) {
        StringBuilder out = new StringBuilder("DEFUZZIFY ").append(name(d.variable())).append('\n');
        d.range().ifPresent(r -> line(out, "RANGE (" + LiteralText.of(r.min()) + " .. " + LiteralText.of(r.max()) + ");"));
        d.terms().forEach(t -> line(out, term(t)));
        d.method().ifPresent(m -> line(out, "METHOD : " + m.value().keyword() + ";"));
        d.defaultValue().ifPresent(v -> line(out, "DEFAULT := " + defaultValue(v) + ";"));
        return out.append("END_DEFUZZIFY\n").toString();
    }

    private static String defaultValue(DefaultValue v) {
        return v instanceof DefaultValue.Constant c ? LiteralText.of(c.value()) : "NC";
    }

    private static String term(Term t) {
        return "TERM " + name(t.name()) + " := " + membershipFunction(t.function()) + ";";
    }

    private static String membershipFunction(MembershipFunction f) {
        if (f instanceof Singleton s) {
            return operand(s.value());
        }
        if (f instanceof MembershipFunction.NamedShape named) {
            // a linear shape is exactly its points; a smooth one has no standard spelling (ShapePoints.approximate)
            return String.join(" ", ShapePoints.exact(named).orElseThrow(() -> new IllegalArgumentException(
                    "a " + named.kind() + " shape is not expressible in standard FCL; convert it first"
                            + " (ShapePoints.approximate)")).stream().map(CanonicalWriter::point).toList());
        }
        if (f instanceof MembershipFunction.Computed computed) {
            throw new IllegalArgumentException("a Takagi-Sugeno term (" + computed.written() + ") is not expressible"
                    + " in standard FCL");
        }
        List<String> points = ((Points) f).points().stream().map(CanonicalWriter::point).toList();
        return String.join(" ", points);
    }

    private static String point(Point p) {
        return "(" + operand(p.x()) + ", " + operand(p.degree()) + ")";
    }

    static String operand(Operand o) {
        return o instanceof Literal l ? LiteralText.of(l) : name(((VariableRef) o).name());
    }

    private static String ruleBlock(RuleBlock b) {
        StringBuilder out = new StringBuilder("RULEBLOCK ").append(name(b.name())).append('\n');
        b.and().ifPresent(a -> line(out, "AND : " + a.value().name() + ";"));
        b.or().ifPresent(o -> line(out, "OR : " + o.value().name() + ";"));
        b.activation().ifPresent(a -> line(out, "ACT : " + a.value().name() + ";"));
        b.accumulation().ifPresent(a -> line(out, "ACCU : " + a.value().name() + ";"));
        b.rules().forEach(r -> out.append(rule(r)));
        return out.append("END_RULEBLOCK\n").toString();
    }

    /** {@code RULE n : IF c THEN s1,} with each further subconclusion on its own, deeper line. */
    static String rule(Rule r) {
        StringBuilder out = new StringBuilder(INDENT).append("RULE ").append(name(r.name())).append(" : IF ")
                .append(ConditionText.of(r.condition())).append(" THEN ");
        List<Subconclusion> parts = r.conclusion();
        for (int i = 0; i < parts.size(); i++) {
            if (i > 0) {
                out.append(",\n").append(INDENT).append(INDENT);
            }
            out.append(subconclusion(parts.get(i)));
        }
        return out.append(";\n").toString();
    }

    private static String subconclusion(Subconclusion s) {
        String term = s.term().map(t -> " IS " + name(t)).orElse("");
        String weight = s.weight().map(w -> " WITH " + operand(w)).orElse("");
        return name(s.variable()) + term + weight;
    }

    private static String options(OptionsBlock o) {
        String content = o.content().isEmpty() ? "" : o.content() + "\n";
        return "OPTIONS\n" + content + "END_OPTIONS\n";
    }

    /**
     * A name as written: a keyword of standard FCL (a dialect reader may give one, e.g. an unnamed block's
     * {@code function_block}) gets {@link ReservedWords#SUFFIX}, the same at every use; StandardConversion lists it.
     */
    static String name(String name) {
        return ReservedWords.unreserved(name);
    }

    private static void line(StringBuilder out, String text) {
        out.append(INDENT).append(text).append('\n');
    }
}
