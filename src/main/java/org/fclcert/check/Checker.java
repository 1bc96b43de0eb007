package org.fclcert.check;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;

/**
 * Runs the semantic checks on a program the reader accepted. Usage: {@code new Checker().check(program)}.
 * Every rule runs (one mistake is reported by the one rule that owns it, and rules skip what another
 * rule owns, so errors do not cascade); the result is sorted by source position, then code.
 */
public final class Checker {
    /** Orders diagnostics by file, line, column, then code. */
    public static final Comparator<Diagnostic> BY_POSITION =
            Comparator.comparing(Diagnostic::location).thenComparing(Diagnostic::code);

    private final List<CheckRule> rules;

    /** The rules keep no state, so every checker of all rules shares one list (made once, not per analysis). */
    private static final List<CheckRule> STANDARD = standardRules();

    /** A checker running all of fclcert's rules ({@link #standardRules()}). */
    public Checker() {
        this(STANDARD);
    }

    public Checker(List<CheckRule> rules) {
        this.rules = List.copyOf(rules);
    }

    /** Every check rule, in code order: FCL-C001 to FCL-C032, FCL-C040 and FCL-C041 (dialect shapes), then the warnings FCL-W001 to FCL-W005. */
    public static List<CheckRule> standardRules() {
        return List.of(
                new NoUndefinedVariables(), new NoUndefinedTerms(), new TermsBelongToTheirVariable(),
                new UniqueVariableNames(), new UniqueTermNames(), new UniqueRuleBlockNames(), new UniqueRuleNames(),
                new FuzzifyOnlyInputs(), new DefuzzifyOnlyOutputs(), new PointsAscending(),
                new DegreesWithinUnitInterval(), new WeightsWithinUnitInterval(), new ParameterVariablesAreInputs(),
                new AndOrPaired(), new OperatorDeclaredWhenUsed(), new MethodDeclared(), new DefaultDeclared(),
                new AccumulationDeclared(), new CogsOnlyOnSingletons(), new CoaNotOnSingletons(),
                new OutputTermsOfOneKind(), new OneAccumulationPerOutput(), new RangeAscending(),
                new ConclusionsOnOutputs(), new BoundedOutputSets(), new NestingWithinLimit(),
                new SubconditionsOnInputs(), new OneFuzzificationPerVariable(), new AtLeastTwoPoints(),
                new InitialValueFitsType(), new SubconclusionsOnDefuzzifiedOutputs(), new UniqueFunctionBlockNames(),
                new ShapeParameterCount(), new ShapeParametersValid(),
                new NoUnusedTerms(), new NoEmptyRuleBlocks(), new NoUnconcludedOutputs(), new NoZeroWeights(),
                new RulesCoverTheInputSpace());
    }

    public List<CheckRule> rules() {
        return rules;
    }

    /** All findings of all rules, sorted by position. */
    public List<Diagnostic> check(Program program) {
        List<Diagnostic> found = new ArrayList<>();
        for (CheckRule rule : rules) {
            rule.check(program, found::add);
        }
        found.sort(BY_POSITION);
        return List.copyOf(found);
    }
}
