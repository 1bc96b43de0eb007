package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;

/** Repeated rule names in a library's rule block, read as the libraries read them. */
final class RepeatedRuleNames {
    private RepeatedRuleNames() {
    }

    /**
     * Rules that repeat a name of their block: both libraries keep and evaluate every rule (fuzzylite ignores the
     * names, jFuzzyLogic keeps them in a list), the standard wants one name per rule (5.2.4, FCL-C007). Read as the
     * library reads it, each repetition under a new name that says where it came from, with FCL-W308.
     */
    static List<Rule> renamed(DialectParser p, List<Rule> rules) {
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
