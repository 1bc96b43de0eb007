package org.fclcert.write;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Set;
import java.util.TreeSet;
import org.fclcert.model.Condition;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;

/** Names of the model constructs a program uses, to show that generated programs cover all of them. */
final class Constructs {
    /** Every construct the model can hold, in the names {@link #of} uses. */
    static final Set<String> ALL = Set.of("several function blocks", "VAR_INPUT", "VAR_OUTPUT", "VAR",
            "initial value", "integer literal", "real literal", "point with literal x", "point with variable x",
            "variable degree", "literal singleton", "variable singleton", "RANGE", "METHOD", "DEFAULT value",
            "DEFAULT NC", "AND:", "OR:", "ACT:", "ACCU:", "numbered rule", "rule named by identifier",
            "IS", "IS NOT", "bare variable condition", "NOT", "AND", "OR", "parentheses",
            "several subconclusions", "bare variable conclusion", "WITH literal", "WITH variable", "OPTIONS",
            "several fuzzifications", "several defuzzifications", "several rule blocks");

    private final Set<String> seen = new TreeSet<>();

    private Constructs() {
    }

    static Set<String> of(Iterable<Program> programs) {
        Constructs c = new Constructs();
        programs.forEach(c::program);
        return c.seen;
    }

    private void program(Program p) {
        note(p.functionBlocks().size() > 1, "several function blocks");
        p.functionBlocks().forEach(this::functionBlock);
    }

    private void functionBlock(FunctionBlock fb) {
        fb.variables().forEach(this::variable);
        note(fb.fuzzifications().size() > 1, "several fuzzifications");
        note(fb.defuzzifications().size() > 1, "several defuzzifications");
        note(fb.ruleBlocks().size() > 1, "several rule blocks");
        note(!fb.options().isEmpty(), "OPTIONS");
        fb.fuzzifications().forEach(f -> f.terms().forEach(this::term));
        fb.defuzzifications().forEach(this::defuzzification);
        fb.ruleBlocks().forEach(this::ruleBlock);
    }

    private void variable(Variable v) {
        seen.add(v.kind().keyword());
        v.initialValue().ifPresent(l -> {
            seen.add("initial value");
            literal(l);
        });
    }

    private void defuzzification(Defuzzification d) {
        d.range().ifPresent(r -> seen.add("RANGE"));
        d.terms().forEach(this::term);
        d.method().ifPresent(m -> seen.add("METHOD"));
        d.defaultValue().ifPresent(v -> seen.add(v instanceof DefaultValue.NoChange ? "DEFAULT NC" : "DEFAULT value"));
    }

    private void term(Term t) {
        if (t.function() instanceof MembershipFunction.Singleton s) {
            seen.add(s.value() instanceof Literal ? "literal singleton" : "variable singleton");
            operand(s.value());
            return;
        }
        for (Point p : ((MembershipFunction.Points) t.function()).points()) {
            seen.add(p.x() instanceof Literal ? "point with literal x" : "point with variable x");
            note(!(p.degree() instanceof Literal), "variable degree");
            operand(p.x());
            operand(p.degree());
        }
    }

    private void operand(Operand o) {
        if (o instanceof Literal l) {
            literal(l);
        }
    }

    private void literal(Literal l) {
        seen.add(l.integral() ? "integer literal" : "real literal");
    }

    private void ruleBlock(RuleBlock b) {
        b.and().ifPresent(x -> seen.add("AND:"));
        b.or().ifPresent(x -> seen.add("OR:"));
        b.activation().ifPresent(x -> seen.add("ACT:"));
        b.accumulation().ifPresent(x -> seen.add("ACCU:"));
        b.rules().forEach(this::rule);
    }

    private void rule(Rule r) {
        seen.add(r.numbered() ? "numbered rule" : "rule named by identifier");
        note(r.conclusion().size() > 1, "several subconclusions");
        r.conclusion().forEach(this::subconclusion);
        condition(r.condition());
    }

    private void subconclusion(Subconclusion s) {
        note(s.bareVariable(), "bare variable conclusion");
        s.weight().ifPresent(w -> seen.add(w instanceof Literal ? "WITH literal" : "WITH variable"));
    }

    private void condition(Condition root) {
        Deque<Condition> work = new ArrayDeque<>();
        work.push(root);
        while (!work.isEmpty()) {
            Condition c = work.pop();
            if (c instanceof Condition.TermSubcondition t) {
                seen.add(t.negated() ? "IS NOT" : "IS");
            } else if (c instanceof Condition.VariableSubcondition) {
                seen.add("bare variable condition");
            } else if (c instanceof Condition.Not n) {
                seen.add("NOT");
                work.push(n.operand());
            } else if (c instanceof Condition.And a) {
                seen.add("AND");
                a.operands().forEach(work::push);
            } else if (c instanceof Condition.Or o) {
                seen.add("OR");
                o.operands().forEach(work::push);
            } else if (c instanceof Condition.Parenthesized p) {
                seen.add("parentheses");
                work.push(p.inner());
            }
        }
    }

    private void note(boolean condition, String construct) {
        if (condition) {
            seen.add(construct);
        }
    }
}
