package org.fclcert.write;

import static org.fclcert.write.M.AT;

import java.util.Arrays;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import java.util.function.Supplier;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.Operand;
import org.fclcert.model.OptionsBlock;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;

/**
 * Random programs in the shape a reader produces (every construct the model can hold, but not
 * necessarily semantically valid: names need not resolve, since only reading is exercised). Conditions
 * follow the reader's normal form: AND operands are never AND/OR, OR operands never OR, and NOT applies
 * to a subcondition or a parenthesized condition, unless wrapped in {@link Condition.Parenthesized}.
 */
final class RandomPrograms {
    private final Random random;
    private int serial;

    RandomPrograms(long seed) {
        this.random = new Random(seed);
    }

    Program program(String sourceName) {
        return new Program(sourceName, list(1, 3, this::functionBlock));
    }

    private FunctionBlock functionBlock() {
        // 5.4 puts VAR sections after VAR_INPUT/VAR_OUTPUT, so a reader lists locals last
        List<Variable> variables = new ArrayList<>(list(1, 6, this::variable));
        variables.sort(java.util.Comparator.comparing(v -> v.kind() == VariableKind.LOCAL));
        return new FunctionBlock(name("fb"), variables, list(0, 3, this::fuzzification),
                list(0, 3, this::defuzzification), list(0, 3, this::ruleBlock), list(0, 2, this::options), AT);
    }

    private Variable variable() {
        VariableKind kind = pick(VariableKind.values());
        Optional<Literal> init = chance(0.3) ? Optional.of(literal()) : Optional.empty();
        return new Variable(name("v"), kind, pick(DataType.values()), init, AT);
    }

    private Fuzzification fuzzification() {
        return new Fuzzification(name("in"), list(1, 4, this::pointTerm), AT);
    }

    private Defuzzification defuzzification() {
        Optional<Range> range = chance(0.5) ? Optional.of(new Range(literal(), literal(), AT)) : Optional.empty();
        List<Term> terms = list(0, 4, chance(0.5) ? this::singletonTerm : this::pointTerm);
        Optional<Located<DefuzzificationMethod>> method = optional(0.8, () -> pick(Arrays.stream(DefuzzificationMethod.values()).filter(DefuzzificationMethod::standard).toArray(DefuzzificationMethod[]::new)));
        Optional<DefaultValue> dflt = chance(0.2) ? Optional.empty()
                : chance(0.5) ? Optional.of(new DefaultValue.NoChange(AT))
                : Optional.of(new DefaultValue.Constant(literal(), AT));
        return new Defuzzification(name("out"), range, terms, method, dflt, AT);
    }

    private Term pointTerm() {
        return new Term(name("t"), new org.fclcert.model.MembershipFunction.Points(list(1, 6, this::point)), AT);
    }

    private Term singletonTerm() {
        return new Term(name("s"), new org.fclcert.model.MembershipFunction.Singleton(operand()), AT);
    }

    private Point point() {
        return new Point(operand(), chance(0.8) ? literal() : operand(), AT);
    }

    private RuleBlock ruleBlock() {
        return new RuleBlock(name("rb"), optional(0.7, () -> pick(Arrays.stream(AndAlgorithm.values()).filter(AndAlgorithm::standard).toArray(AndAlgorithm[]::new))),
                optional(0.4, () -> pick(Arrays.stream(OrAlgorithm.values()).filter(OrAlgorithm::standard).toArray(OrAlgorithm[]::new))), optional(0.4, () -> pick(Arrays.stream(ActivationMethod.values()).filter(ActivationMethod::standard).toArray(ActivationMethod[]::new))),
                optional(0.8, () -> pick(Arrays.stream(AccumulationMethod.values()).filter(AccumulationMethod::standard).toArray(AccumulationMethod[]::new))), list(0, 5, this::rule), AT);
    }

    private Rule rule() {
        String name = chance(0.8) ? Integer.toString(random.nextInt(1000)) : name("r");
        return new Rule(name, condition(3), list(1, 4, this::subconclusion), AT);
    }

    private Subconclusion subconclusion() {
        Optional<String> term = chance(0.8) ? Optional.of(name("t")) : Optional.empty();
        Optional<Operand> weight = chance(0.3) ? Optional.of(operand()) : Optional.empty();
        return new Subconclusion(name("out"), term, weight, AT);
    }

    /** A condition in reader normal form; {@code depth} bounds the nesting of parentheses. */
    private Condition condition(int depth) {
        List<Condition> terms = list(1, 3, () -> conjunction(depth));
        return terms.size() == 1 ? terms.get(0) : new Condition.Or(terms, AT);
    }

    private Condition conjunction(int depth) {
        List<Condition> factors = list(1, 3, () -> factor(depth));
        return factors.size() == 1 ? factors.get(0) : new Condition.And(factors, AT);
    }

    private Condition factor(int depth) {
        Condition primary = primary(depth);
        return chance(0.2) ? new Condition.Not(primary, AT) : primary;
    }

    private Condition primary(int depth) {
        if (depth > 0 && chance(0.25)) {
            return new Condition.Parenthesized(condition(depth - 1), AT);
        }
        if (chance(0.2)) {
            return new Condition.VariableSubcondition(name("in"), AT);
        }
        return new Condition.TermSubcondition(name("in"), name("t"), chance(0.2), AT);
    }

    private Operand operand() {
        return chance(0.7) ? literal() : new org.fclcert.model.VariableRef(name("p"), AT);
    }

    /** Integer and real literals of everyday and extreme magnitudes, of either sign. */
    Literal literal() {
        if (chance(0.5)) {
            return new Literal(random.nextInt(2001) - 1000, true, AT);
        }
        double magnitude = chance(0.7) ? random.nextDouble() * 100 : Math.pow(10, random.nextInt(40) - 20) * random.nextDouble();
        double value = chance(0.3) ? -magnitude : magnitude;
        return new Literal(value == 0 ? 0.5 : value, false, AT);
    }

    private OptionsBlock options() {
        List<String> lines = list(0, 3, () -> "param_" + random.nextInt(100) + " = " + random.nextInt(100) + ";");
        return new OptionsBlock(String.join("\n  ", lines), AT);
    }

    /** Unique, lower-case, non-keyword identifiers with a distinguishing prefix. */
    private String name(String prefix) {
        return prefix + "_" + (serial++);
    }

    private <T> Optional<Located<T>> optional(double p, Supplier<T> value) {
        return chance(p) ? Optional.of(new Located<>(value.get(), AT)) : Optional.empty();
    }

    private <T> List<T> list(int min, int max, Supplier<T> element) {
        int n = min + random.nextInt(max - min + 1);
        List<T> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            out.add(element.get());
        }
        return out;
    }

    private <T> T pick(T[] values) {
        return values[random.nextInt(values.length)];
    }

    private boolean chance(double p) {
        return random.nextDouble() < p;
    }
}
