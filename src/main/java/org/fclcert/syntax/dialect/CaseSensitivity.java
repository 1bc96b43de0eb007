package org.fclcert.syntax.dialect;

import java.util.HashMap;
import java.util.Map;
import org.fclcert.model.Condition;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;

/**
 * jFuzzyLogic's names are case-sensitive, FCL's are not (IEC 61131-3 B.1.1): FCL-W303 wherever one
 * name is spelled two ways, at the later spelling — two declarations (two names there, one here, which
 * the checks then report as a duplicate) or a use spelled unlike its declaration (jFuzzyLogic would not
 * find it).
 */
final class CaseSensitivity {
    interface Sink {
        void warn(SourceLocation at, DialectCode code, String message);
    }

    private CaseSensitivity() {
    }

    static void warn(FunctionBlock fb, Sink sink) {
        Map<String, String> variables = new HashMap<>();
        for (Variable v : fb.variables()) {
            declare(variables, v.name(), v.location(), "variable", sink);
        }
        Map<String, Map<String, String>> terms = new HashMap<>();
        for (Fuzzification f : fb.fuzzifications()) {
            use(variables, f.variable(), f.location(), "variable", sink);
            Map<String, String> own = terms.computeIfAbsent(Names.key(f.variable()), k -> new HashMap<>());
            for (Term t : f.terms()) {
                declare(own, t.name(), t.location(), "term", sink);
            }
        }
        for (Defuzzification d : fb.defuzzifications()) {
            use(variables, d.variable(), d.location(), "variable", sink);
            Map<String, String> own = terms.computeIfAbsent(Names.key(d.variable()), k -> new HashMap<>());
            for (Term t : d.terms()) {
                declare(own, t.name(), t.location(), "term", sink);
            }
        }
        for (RuleBlock rb : fb.ruleBlocks()) {
            for (Rule r : rb.rules()) {
                for (Condition.TermSubcondition t : subconditions(r.condition(), new java.util.ArrayList<>())) {
                    {
                        use(variables, t.variable(), t.location(), "variable", sink);
                        if (!t.any()) {
                            use(terms.getOrDefault(Names.key(t.variable()), Map.of()), t.term(), t.location(), "term", sink);
                        }
                    }
                }
                for (Subconclusion s : r.conclusion()) {
                    use(variables, s.variable(), s.location(), "variable", sink);
                    s.term().ifPresent(t -> use(terms.getOrDefault(Names.key(s.variable()), Map.of()), t,
                            s.location(), "term", sink));
                }
            }
        }
    }

    /** The subconditions of a condition, left to right (the reader limits nesting, so recursion is safe). */
    static java.util.List<Condition.TermSubcondition> subconditions(Condition c, java.util.List<Condition.TermSubcondition> out) {
        if (c instanceof Condition.TermSubcondition t) {
            out.add(t);
        } else if (c instanceof Condition.Not n) {
            subconditions(n.operand(), out);
        } else if (c instanceof Condition.Parenthesized p) {
            subconditions(p.inner(), out);
        } else if (c instanceof Condition.And a) {
            a.operands().forEach(o -> subconditions(o, out));
        } else if (c instanceof Condition.Or o) {
            o.operands().forEach(x -> subconditions(x, out));
        }
        return out;
    }

    private static void declare(Map<String, String> seen, String name, SourceLocation at, String what, Sink sink) {
        String first = seen.putIfAbsent(Names.key(name), name);
        if (first != null && !first.equals(name)) {
            sink.warn(at, DialectCode.NAMES_DIFFER_IN_CASE, "the " + what + " '" + name + "' differs from '"
                    + first + "' only in case: two names in jFuzzyLogic, one in FCL");
        }
    }

    private static void use(Map<String, String> declared, String name, SourceLocation at, String what, Sink sink) {
        String decl = declared.get(Names.key(name));
        if (decl != null && !decl.equals(name)) {
            sink.warn(at, DialectCode.NAMES_DIFFER_IN_CASE, "'" + name + "' is spelled '" + decl
                    + "' where the " + what + " is declared; jFuzzyLogic's names are case-sensitive, so it would not"
                    + " find it (fclcert does)");
        }
    }
}
