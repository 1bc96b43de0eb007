package org.fclcert.check;

import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.model.Condition;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.VariableKind;

/**
 * FCL-W001 (warning): every term of a FUZZIFY block is named by some subcondition and every term of
 * a DEFUZZIFY block by some subconclusion. An unused term is legal but usually a leftover or a typo
 * elsewhere (Annex C itself defines terms no rule uses). A misspelt use ({@code temp IS lwo}) counts as a
 * use of the term it most likely means: the typo's own error says so, and a second report would mislead. Only the first FUZZIFY block of an input and
 * the first DEFUZZIFY block of an output are considered: other blocks are errors of their own.
 */
public final class NoUnusedTerms implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.warning("FCL-W001", "—",
            "every defined term is used by some rule");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        Scope scope = Scope.of(block);
        // per FUZZIFY or DEFUZZIFY block (by identity), which of its terms some rule names: no name keys to build
        Map<Object, boolean[]> used = new IdentityHashMap<>();
        // a use spelt by the very Strings of one already marked marks nothing new (the reader shares one String per
        // spelling, so a large block's uses are a few spellings): skipped by identity, before any name lookup
        Map<String, Map<String, Boolean>> markedIn = new IdentityHashMap<>();
        Map<String, Map<String, Boolean>> markedOut = new IdentityHashMap<>();
        for (RuleBlock rb : block.ruleBlocks()) {
            for (Rule rule : rb.rules()) {
                for (Condition c : scope.subconditions(rule)) {
                    if (c instanceof Condition.TermSubcondition t && !t.any() && first(markedIn, t.variable(), t.term())) {
                        String[] meant = scope.meant(t.variable(), t.term(), true);
                        scope.fuzzification(meant[0]).ifPresent(f -> mark(used, f, f.terms(), meant[1]));
                    }
                }
                for (Subconclusion s : rule.conclusion()) {
                    if (s.term().isPresent() && first(markedOut, s.variable(), s.term().get())) {
                        String[] meant = scope.meant(s.variable(), s.term().get(), false);
                        scope.defuzzification(meant[0]).ifPresent(d -> mark(used, d, d.terms(), meant[1]));
                    }
                }
            }
        }
        // only blocks rules can reach: the first FUZZIFY of an input, the first DEFUZZIFY of an output
        // (the terms of a misplaced or repeated block are already covered by that block's error)
        for (Fuzzification f : block.fuzzifications()) {
            if (scope.is(f.variable(), VariableKind.INPUT) && scope.fuzzification(f.variable()).get() == f) {
                report(f.variable(), f.terms(), used.get(f), "subcondition", sink);
            }
        }
        for (Defuzzification d : block.defuzzifications()) {
            if (scope.is(d.variable(), VariableKind.OUTPUT) && scope.defuzzification(d.variable()).get() == d) {
                report(d.variable(), d.terms(), used.get(d), "subconclusion", sink);
            }
        }
    }

    /** True the first time this pair of Strings (by identity) is seen. */
    private static boolean first(Map<String, Map<String, Boolean>> seen, String variable, String term) {
        return seen.computeIfAbsent(variable, v -> new IdentityHashMap<>()).put(term, Boolean.TRUE) == null;
    }

    /** Marks every term of the block named {@code term} (a repeated term name is its own error). */
    private static void mark(Map<Object, boolean[]> used, Object owner, List<Term> terms, String term) {
        boolean[] marks = used.computeIfAbsent(owner, o -> new boolean[terms.size()]);
        for (int i = 0; i < marks.length; i++) {
            if (Names.same(terms.get(i).name(), term)) {
                marks[i] = true;
            }
        }
    }

    private void report(String variable, List<Term> terms, boolean[] used, String by, DiagnosticSink sink) {
        for (int i = 0; i < terms.size(); i++) {
            Term t = terms.get(i);
            if (used == null || !used[i]) {
                sink.report(finding(t.location(), "term '" + t.name() + "' of '" + variable + "' is never used: no "
                        + by + " names '" + variable + " IS " + t.name() + "'"));
            }
        }
    }
}
