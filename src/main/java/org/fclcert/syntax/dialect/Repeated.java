package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.Term;

/** Names written twice where the standard wants them once, read as the libraries read them (FCL-W308). */
final class Repeated {
    private Repeated() {
    }

    /**
     * Terms of one variable that repeat a name: fuzzylite finds only the first of them (its rules and conditions
     * name the first), jFuzzyLogic only the last (a map, the later replaces the earlier); the standard wants one
     * name per term (FCL-C005). Read as the library reads it: the others left out, each with FCL-W308.
     */
    static List<Term> terms(DialectParser p, String variable, List<Term> terms, boolean keepFirst) {
        Map<String, Term> kept = new java.util.LinkedHashMap<>();
        for (Term t : terms) {
            Term before = kept.get(Names.key(t.name()));
            if (before == null) {
                kept.put(Names.key(t.name()), t);
                continue;
            }
            Term dropped = keepFirst ? t : before;
            Term other = keepFirst ? before : t;
            p.warn(dropped.location(), DialectCode.TOLERATED, "term '" + t.name() + "' of '" + variable + "' is"
                    + " defined twice (also at line " + other.location().line() + "): " + p.library + " uses only the "
                    + (keepFirst ? "first" : "last") + ", so this one is left out; the standard wants one name per"
                    + " term (5.2.2)");
            if (!keepFirst) {
                kept.remove(Names.key(t.name()));
                kept.put(Names.key(t.name()), t);
            }
        }
        return kept.size() == terms.size() ? terms : new ArrayList<>(kept.values());
    }

    /**
     * Rules that repeat a name of their block: both libraries keep and evaluate every rule (fuzzylite ignores the
     * names, jFuzzyLogic keeps them in a list), the standard wants one name per rule (5.2.4, FCL-C007). Read as the
     * library reads it, each repetition under a new name that says where it came from, with FCL-W308.
     */
    static List<Rule> rules(DialectParser p, List<Rule> rules) {
        Map<String, Rule> first = new HashMap<>();
        Set<String> taken = new HashSet<>();
        rules.forEach(r -> taken.add(Names.key(r.name())));
        List<Rule> out = new ArrayList<>(rules.size());
        for (Rule r : rules) {
            Rule before = first.putIfAbsent(Names.key(r.name()), r);
            if (before == null) {
                out.add(r);
                continue;
            }
            String stem = (r.numbered() ? "r" : "") + r.name() + "_";
            int k = 2;
            while (taken.contains(Names.key(stem + k))) {
                k++;
            }
            String name = stem + k;
            taken.add(Names.key(name));
            p.warn(r.location(), DialectCode.TOLERATED, "RULE " + r.name() + " repeats the name of the rule at line "
                    + before.location().line() + ": " + p.library + " keeps and evaluates both, the standard wants one"
                    + " name per rule in a rule block (5.2.4); read as rule '" + name + "'");
            out.add(new Rule(name, r.condition(), r.conclusion(), r.location()));
        }
        return out;
    }
}
