package org.fclcert.check;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Names;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * Name lookup in one function block, case-insensitive. Where a name is declared twice (itself an
 * error, reported by its own rule), the first declaration is the one that counts, so that one
 * mistake does not cascade into a diagnostic at every use.
 */
final class Scope {
    private final Map<String, Variable> variables = new HashMap<>();
    private final Map<String, Fuzzification> fuzzifications = new HashMap<>();
    private final Map<String, Defuzzification> defuzzifications = new HashMap<>();
    private final FunctionBlock block;

    /** The last scope built on this thread, held weakly: every rule of one check run asks for the same block. */
    private static final ThreadLocal<WeakReference<Scope>> LAST = new ThreadLocal<>();

    /**
     * The scope of this block, built once per check run rather than once per rule (a block is immutable,
     * and so is a scope after construction, so sharing it is invisible).
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
        block.variables().forEach(v -> variables.putIfAbsent(Names.key(v.name()), v));
        block.fuzzifications().forEach(f -> fuzzifications.putIfAbsent(Names.key(f.variable()), f));
        block.defuzzifications().forEach(d -> defuzzifications.putIfAbsent(Names.key(d.variable()), d));
    }

    FunctionBlock block() {
        return block;
    }

    Optional<Variable> variable(String name) {
        return Optional.ofNullable(variables.get(Names.key(name)));
    }

    boolean declared(String name) {
        return variables.containsKey(Names.key(name));
    }

    boolean is(String name, VariableKind kind) {
        return variable(name).map(v -> v.kind() == kind).orElse(false);
    }

    Optional<Fuzzification> fuzzification(String variable) {
        return Optional.ofNullable(fuzzifications.get(Names.key(variable)));
    }

    Optional<Defuzzification> defuzzification(String variable) {
        return Optional.ofNullable(defuzzifications.get(Names.key(variable)));
    }

    /**
     * The terms an {@code IS} subcondition on this variable may name: present only when the
     * variable is a declared input with a FUZZIFY block (otherwise another rule reports the use).
     */
    Optional<List<Term>> conditionTerms(String variable) {
        if (!is(variable, VariableKind.INPUT)) {
            return Optional.empty();
        }
        return fuzzification(variable).map(Fuzzification::terms);
    }

    /**
     * The terms an {@code IS} subconclusion on this variable may name: present only when the
     * variable is a declared output with a DEFUZZIFY block.
     */
    Optional<List<Term>> conclusionTerms(String variable) {
        if (!is(variable, VariableKind.OUTPUT)) {
            return Optional.empty();
        }
        return defuzzification(variable).map(Defuzzification::terms);
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
        if (terms.isPresent() && terms.get().stream().noneMatch(x -> Names.same(x.name(), term))
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
