package org.fclcert.check;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Condition;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Names;
import org.fclcert.model.Rule;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * Name lookup in one function block, case-insensitive. Where a name is declared twice (itself an
 * error, reported by its own rule), the first declaration is the one that counts, so that one
 * mistake does not cascade into a diagnostic at every use.
 */
final class Scope {
    private final NameMap<Variable> variables = new NameMap<>();
    private final NameMap<Fuzzification> fuzzifications = new NameMap<>();
    private final NameMap<Defuzzification> defuzzifications = new NameMap<>();
    private final FunctionBlock block;
    /** Per rule (by identity): its subconditions, walked once per check run rather than once per rule class. */
    private final Map<Rule, List<Condition>> subconditions = new IdentityHashMap<>();
    private List<OperandUse> operandUses;
    private List<TermUse> termUses;
    private String hashedName;
    private int hashedHash;

    /** The last scope built on this thread, held weakly: every rule of one check run asks for the same block. */
    private static final ThreadLocal<WeakReference<Scope>> LAST = new ThreadLocal<>();

    /**
     * The scope of this block, built once per check run rather than once per rule (a block is immutable,
     * and a scope only adds what it works out from the block, the same each time, so sharing it is invisible).
     */
    static Scope of(FunctionBlock block) {
        WeakReference<Scope> ref = LAST.get();
        Scope s = ref == null ? null : ref.get();
        if (s != null && s.block == block) {
            return s;
        }
        s = new Scope(block);
        LAST.set(new WeakReference<>(s));
        return s;
    }

    Scope(FunctionBlock block) {
        this.block = block;
        block.variables().forEach(v -> variables.putIfAbsent(v.name(), v));
        block.fuzzifications().forEach(f -> fuzzifications.putIfAbsent(f.variable(), f));
        block.defuzzifications().forEach(d -> defuzzifications.putIfAbsent(d.variable(), d));
    }

    /**
     * A case-insensitive map from names to what they declare ({@link Names#same}), the first of two
     * declarations differing only in case winning: open addressing on a hash of the case-folded characters,
     * so that a lookup neither upper-cases nor allocates, and one slot pair per name (a block may declare
     * 100 000 names).
     */
    private final class NameMap<V> {
        private String[] names = new String[16];
        private Object[] values = new Object[16];
        private int size;

        void putIfAbsent(String name, V value) {
            if (get(name) != null) {
                return;
            }
            if (2 * (size + 1) > names.length) {
                String[] oldNames = names;
                Object[] oldValues = values;
                names = new String[2 * oldNames.length];
                values = new Object[2 * oldNames.length];
                size = 0;
                for (int i = 0; i < oldNames.length; i++) {
                    if (oldNames[i] != null) {
                        insert(oldNames[i], oldValues[i]);
                    }
                }
            }
            insert(name, value);
        }

        private void insert(String name, Object value) {
            int mask = names.length - 1;
            int at = hashOf(name) & mask;
            while (names[at] != null) {
                at = (at + 1) & mask;
            }
            names[at] = name;
            values[at] = value;
            size++;
        }

        @SuppressWarnings("unchecked")
        V get(String name) {
            int mask = names.length - 1;
            for (int at = hashOf(name) & mask; names[at] != null; at = (at + 1) & mask) {
                if (Names.same(names[at], name)) {
                    return (V) values[at];
                }
            }
            return null;
        }

        boolean containsKey(String name) {
            return get(name) != null;
        }

        /** Equal for names equal ignoring case as {@link String#equalsIgnoreCase} compares them. */
        private static int hash(String name) {
            int h = 0;
            for (int i = 0; i < name.length(); i++) {
                char c = name.charAt(i);
                // ASCII (every FCL identifier) folds by itself; other letters as equalsIgnoreCase folds them
                h = 31 * h + (c < 0x80 ? (c >= 'A' && c <= 'Z' ? c + ('a' - 'A') : c)
                        : Character.toLowerCase(Character.toUpperCase(c)));
            }
            return h ^ (h >>> 16);
        }
    }

    /** Every named-term use of the block ({@link TermUse#of}), made once for the two rules that judge them. */
    List<TermUse> termUses() {
        if (termUses == null) {
            termUses = TermUse.of(this);
        }
        return termUses;
    }

    /** Every operand of the block ({@link OperandUse#all}), made once for the five rules that look at them. */
    List<OperandUse> operandUses() {
        if (operandUses == null) {
            operandUses = OperandUse.all(block);
        }
        return operandUses;
    }

    /**
     * {@link NameMap#hash} of the name asked about last: checking one use asks several maps about the same name,
     * and the reader shares one String per spelling (a scope is used on one thread only).
     */
    private int hashOf(String name) {
        if (name != hashedName) {
            hashedHash = NameMap.hash(name);
            hashedName = name;
        }
        return hashedHash;
    }

    /** The subconditions of the rule's condition in source order ({@link Conditions#subconditions}), memoised. */
    List<Condition> subconditions(Rule rule) {
        List<Condition> list = subconditions.get(rule);
        if (list == null) {
            list = Conditions.subconditions(rule.condition());
            subconditions.put(rule, list);
        }
        return list;
    }

    FunctionBlock block() {
        return block;
    }

    Optional<Variable> variable(String name) {
        return Optional.ofNullable(variables.get(name));
    }

    /** The variable declared by that name, or null (no Optional: asked of every subcondition of a large block). */
    Variable declaredVariable(String name) {
        return variables.get(name);
    }

    /** Whether the variable has a FUZZIFY block. */
    boolean fuzzified(String variable) {
        return fuzzifications.containsKey(variable);
    }

    boolean declared(String name) {
        return variables.containsKey(name);
    }

    boolean is(String name, VariableKind kind) {
        Variable v = variables.get(name);
        return v != null && v.kind() == kind;
    }

    Optional<Fuzzification> fuzzification(String variable) {
        return Optional.ofNullable(fuzzifications.get(variable));
    }

    Optional<Defuzzification> defuzzification(String variable) {
        return Optional.ofNullable(defuzzifications.get(variable));
    }

    /**
     * The terms an {@code IS} subcondition on this variable may name: present only when the
     * variable is a declared input with a FUZZIFY block (otherwise another rule reports the use).
     */
    Optional<List<Term>> conditionTerms(String variable) {
        if (!is(variable, VariableKind.INPUT)) {
            return Optional.empty();
        }
        Fuzzification f = fuzzifications.get(variable);
        return f == null ? Optional.empty() : Optional.of(f.terms());
    }

    /**
     * The terms an {@code IS} subconclusion on this variable may name: present only when the
     * variable is a declared output with a DEFUZZIFY block.
     */
    Optional<List<Term>> conclusionTerms(String variable) {
        if (!is(variable, VariableKind.OUTPUT)) {
            return Optional.empty();
        }
        Defuzzification d = defuzzifications.get(variable);
        return d == null ? Optional.empty() : Optional.of(d.terms());
    }

    /** Whether one of the terms is named {@code term} (case-insensitive). */
    static boolean hasTerm(List<Term> terms, String term) {
        for (Term t : terms) {
            if (t.name() == term) {
                return true;    // the reader shares one String per spelling: most uses are the very name defined
            }
        }
        for (Term t : terms) {
            if (Names.same(t.name(), term)) {
                return true;
            }
        }
        return false;
    }

    /**
     * The variables other than {@code except} whose FUZZIFY blocks ({@code inConditions}) or DEFUZZIFY
     * blocks (otherwise) define a term of that name, in block order.
     */
    List<String> ownersOfTerm(String term, String except, boolean inConditions) {
        List<String> owners = new ArrayList<>();
        if (inConditions) {
            for (Fuzzification f : block.fuzzifications()) {
                addOwner(owners, f.variable(), f.term(term).isPresent(), except);
            }
        } else {
            for (Defuzzification d : block.defuzzifications()) {
                addOwner(owners, d.variable(), d.term(term).isPresent(), except);
            }
        }
        return owners;
    }

    private static void addOwner(List<String> owners, String variable, boolean has, String except) {
        if (has && !Names.same(variable, except) && owners.stream().noneMatch(o -> Names.same(o, variable))) {
            owners.add(variable);
        }
    }

    /** The declared variable an undeclared name most likely misspells ({@link Names#closest}). */
    Optional<String> suggestVariable(String name) {
        if (declared(name)) {
            return Optional.empty();
        }
        return Names.closest(name, block.variables().stream().map(Variable::name).toList());
    }

    /** The term of {@code terms} an undefined term name most likely misspells. */
    static Optional<String> suggestTerm(String term, List<Term> terms) {
        return Names.closest(term, terms.stream().map(Term::name).toList());
    }

    /**
     * What a use of {@code variable IS term} most likely means: the names themselves when they are
     * declared, else the declared names they misspell (so a typo is reported once, as a typo, and the
     * term it meant is not also reported as unused).
     */
    String[] meant(String variable, String term, boolean inCondition) {
        String v = declared(variable) ? variable : suggestVariable(variable).orElse(variable);
        Optional<List<Term>> terms = inCondition ? conditionTerms(v) : conclusionTerms(v);
        String t = term;
        if (terms.isPresent() && !hasTerm(terms.get(), term)
                && ownersOfTerm(term, v, true).isEmpty() && ownersOfTerm(term, v, false).isEmpty()) {
            t = suggestTerm(term, terms.get()).orElse(term);
        }
        return new String[] {v, t};
    }

    /** "input 'temp'", "output 'valve'", "local variable 'x'" or "'x'" when undeclared. */
    String describe(String variable) {
        return variable(variable).map(Describe::variable).orElse("'" + variable + "'");
    }
}
