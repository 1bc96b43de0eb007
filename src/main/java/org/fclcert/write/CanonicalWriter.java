package org.fclcert.write;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.syntax.ReservedWords;
import org.fclcert.model.Comment.Line;
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
import org.fclcert.model.SourceLocation;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/**
 * Writes a program as standard FCL text in one fixed layout, so that equal models give equal text
 * and reading the text back gives the same model. A program's comments ({@link Program#comments}) are written
 * back on the line of the layout they belong to: on lines of their own before it, at the indentation of that
 * line, or at its end after one space; their text is written exactly as read.
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

    /** The whole program with its comments; function blocks separated by a blank line, text ending in a newline. */
    public String write(Program program) {
        CommentLines comments = new CommentLines(program.comments());
        List<String> blocks = program.functionBlocks().stream().map(fb -> write(fb, comments)).toList();
        return String.join("\n", blocks) + comments.rest();
    }

    /** One function block, ending in a newline (comments belong to the program: none). */
    public String write(FunctionBlock fb) {
        return write(fb, CommentLines.none());
    }

    private static String write(FunctionBlock fb, CommentLines c) {
        List<String> sections = new ArrayList<>(variableSections(fb.variables(), c));
        fb.fuzzifications().forEach(f -> sections.add(fuzzify(f, c)));
        fb.defuzzifications().forEach(d -> sections.add(defuzzify(d, c)));
        fb.ruleBlocks().forEach(b -> sections.add(ruleBlock(b, c)));
        fb.options().forEach(o -> sections.add(options(o, c)));
        return c.before(Line.ITEM, fb.location(), "") + "FUNCTION_BLOCK " + name(fb.name())
                + c.after(Line.ITEM, fb.location()) + "\n" + String.join("\n", sections)
                + c.before(Line.END, fb.location(), "") + "END_FUNCTION_BLOCK" + c.after(Line.END, fb.location()) + "\n";
    }

    /**
     * One section per run of consecutive variables of the same kind, so the declaration order is
     * kept; local variables come last because 5.4 puts {@code other_var_declarations} after the
     * input and output sections.
     */
    private static List<String> variableSections(List<Variable> variables, CommentLines c) {
        List<Variable> ordered = new ArrayList<>(variables.stream().filter(v -> v.kind() != VariableKind.LOCAL).toList());
        ordered.addAll(variables.stream().filter(v -> v.kind() == VariableKind.LOCAL).toList());
        List<String> sections = new ArrayList<>();
        StringBuilder section = null;
        for (int i = 0; i < ordered.size(); i++) {
            Variable v = ordered.get(i);
            SourceLocation at = v.location();
            if (i == 0 || ordered.get(i - 1).kind() != v.kind()) {
                section = new StringBuilder(c.before(Line.SECTION_START, at, "")).append(v.kind().keyword())
                        .append(c.after(Line.SECTION_START, at)).append('\n');
            } else {
                // the text opened a section here that the layout joins with the one before
                section.append(c.instead(Line.SECTION_START, at, INDENT));
            }
            section.append(c.before(Line.ITEM, at, INDENT)).append(INDENT).append(declaration(v))
                    .append(c.after(Line.ITEM, at)).append('\n');
            if (i == ordered.size() - 1 || ordered.get(i + 1).kind() != v.kind()) {
                sections.add(section.append(c.before(Line.END, at, INDENT)).append("END_VAR")
                        .append(c.after(Line.END, at)).append('\n').toString());
            } else {
                section.append(c.instead(Line.END, at, INDENT));
            }
        }
        return sections;
    }

    private static String declaration(Variable v) {
        String init = v.initialValue().map(l -> " := " + LiteralText.of(l)).orElse("");
        return name(v.name()) + " : " + v.type().name() + init + ";";
    }

    private static String fuzzify(Fuzzification f, CommentLines c) {
        StringBuilder out = header(c, "FUZZIFY ", f.variable(), f.location());
        f.terms().forEach(t -> line(out, c, t.location(), term(t)));
        return end(out, c, "END_FUZZIFY", f.location());
    }

    private static String defuzzify(Defuzzification d, CommentLines c) {
        StringBuilder out = header(c, "DEFUZZIFY ", d.variable(), d.location());
        d.range().ifPresent(r -> line(out, c, r.location(),
                "RANGE (" + LiteralText.of(r.min()) + " .. " + LiteralText.of(r.max()) + ");"));
        d.terms().forEach(t -> line(out, c, t.location(), term(t)));
        d.method().ifPresent(m -> line(out, c, m.location(), "METHOD : " + m.value().keyword() + ";"));
        d.defaultValue().ifPresent(v -> line(out, c, v.location(), "DEFAULT := " + defaultValue(v) + ";"));
        return end(out, c, "END_DEFUZZIFY", d.location());
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

    private static String ruleBlock(RuleBlock b, CommentLines c) {
        StringBuilder out = header(c, "RULEBLOCK ", b.name(), b.location());
        b.and().ifPresent(a -> line(out, c, a.location(), "AND : " + a.value().name() + ";"));
        b.or().ifPresent(o -> line(out, c, o.location(), "OR : " + o.value().name() + ";"));
        b.activation().ifPresent(a -> line(out, c, a.location(), "ACT : " + a.value().name() + ";"));
        b.accumulation().ifPresent(a -> line(out, c, a.location(), "ACCU : " + a.value().name() + ";"));
        b.rules().forEach(r -> line(out, c, r.location(), rule(r).strip()));
        return end(out, c, "END_RULEBLOCK", b.location());
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

    private static String options(OptionsBlock o, CommentLines c) {
        StringBuilder out = header(c, "OPTIONS", "", o.location());
        out.append(o.content().isEmpty() ? "" : o.content() + "\n");
        return end(out, c, "END_OPTIONS", o.location());
    }

    /**
     * A name as written: a keyword of standard FCL (a dialect reader may give one, e.g. an unnamed block's
     * {@code function_block}) gets {@link ReservedWords#SUFFIX}, the same at every use; StandardConversion lists it.
     */
    static String name(String name) {
        return ReservedWords.unreserved(name);
    }

    /** A line inside a block, with the comments before it and at its end. */
    private static void line(StringBuilder out, CommentLines c, SourceLocation item, String text) {
        out.append(c.before(Line.ITEM, item, INDENT)).append(INDENT).append(text).append(c.after(Line.ITEM, item))
                .append('\n');
    }

    /** A block's first line ({@code keyword name}), with its comments. */
    private static StringBuilder header(CommentLines c, String keyword, String blockName, SourceLocation item) {
        return new StringBuilder(c.before(Line.ITEM, item, "")).append(keyword)
                .append(blockName.isEmpty() ? "" : name(blockName))
                .append(c.after(Line.ITEM, item)).append('\n');
    }

    /** A block's END_… line, with its comments; the block's text. */
    private static String end(StringBuilder out, CommentLines c, String keyword, SourceLocation item) {
        return out.append(c.before(Line.END, item, INDENT)).append(keyword).append(c.after(Line.END, item))
                .append('\n').toString();
    }
}
