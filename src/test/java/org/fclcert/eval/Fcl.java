package org.fclcert.eval;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
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
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;

/** Test-only builder of model programs, so evaluator tests do not depend on the reader. */
final class Fcl {
    static final SourceLocation AT = SourceLocation.UNKNOWN;

    private Fcl() {
    }

    static Operand num(double v) {
        return Literal.of(v);
    }

    static Operand var(String name) {
        return new VariableRef(name, AT);
    }

    /** Points from alternating x, degree constants. */
    static MembershipFunction pts(double... xy) {
        List<Point> p = new ArrayList<>();
        for (int i = 0; i < xy.length; i += 2) {
            p.add(new Point(num(xy[i]), num(xy[i + 1]), AT));
        }
        return new MembershipFunction.Points(p);
    }

    /** Points from alternating operands (x, degree). */
    static MembershipFunction ptsOf(Operand... xy) {
        List<Point> p = new ArrayList<>();
        for (int i = 0; i < xy.length; i += 2) {
            p.add(new Point(xy[i], xy[i + 1], AT));
        }
        return new MembershipFunction.Points(p);
    }

    static MembershipFunction single(double v) {
        return new MembershipFunction.Singleton(num(v));
    }

    static MembershipFunction single(Operand v) {
        return new MembershipFunction.Singleton(v);
    }

    static Term term(String name, MembershipFunction f) {
        return new Term(name, f, AT);
    }

    static Condition is(String variable, String term) {
        return new Condition.TermSubcondition(variable, term, false, AT);
    }

    static Condition isNot(String variable, String term) {
        return new Condition.TermSubcondition(variable, term, true, AT);
    }

    static Condition v(String variable) {
        return new Condition.VariableSubcondition(variable, AT);
    }

    static Condition not(Condition c) {
        return new Condition.Not(c, AT);
    }

    static Condition and(Condition... cs) {
        return new Condition.And(Arrays.asList(cs), AT);
    }

    static Condition or(Condition... cs) {
        return new Condition.Or(Arrays.asList(cs), AT);
    }

    static Condition paren(Condition c) {
        return new Condition.Parenthesized(c, AT);
    }

    static Subconclusion then(String variable, String term) {
        return new Subconclusion(variable, Optional.of(term), Optional.empty(), AT);
    }

    static Subconclusion then(String variable, String term, Operand weight) {
        return new Subconclusion(variable, Optional.of(term), Optional.of(weight), AT);
    }

    static Subconclusion thenVar(String variable) {
        return new Subconclusion(variable, Optional.empty(), Optional.empty(), AT);
    }

    static Subconclusion thenVar(String variable, Operand weight) {
        return new Subconclusion(variable, Optional.empty(), Optional.of(weight), AT);
    }

    static Rule rule(String name, Condition c, Subconclusion... s) {
        return new Rule(name, c, Arrays.asList(s), AT);
    }

    static Fuzzification fuzzify(String variable, Term... terms) {
        return new Fuzzification(variable, Arrays.asList(terms), AT);
    }

    /** A function block under construction. */
    static Block block(String name) {
        return new Block(name);
    }

    static Out defuzzify(String variable, DefuzzificationMethod method) {
        return new Out(variable, method);
    }

    static Rules ruleBlock(String name) {
        return new Rules(name);
    }

    static final class Block {
        private final String name;
        private final List<Variable> vars = new ArrayList<>();
        private final List<Fuzzification> fuzz = new ArrayList<>();
        private final List<Defuzzification> defuzz = new ArrayList<>();
        private final List<RuleBlock> blocks = new ArrayList<>();

        Block(String name) {
            this.name = name;
        }

        Block input(String n) {
            return variable(n, VariableKind.INPUT, DataType.REAL, null);
        }

        Block output(String n) {
            return variable(n, VariableKind.OUTPUT, DataType.REAL, null);
        }

        Block local(String n) {
            return variable(n, VariableKind.LOCAL, DataType.REAL, null);
        }

        Block variable(String n, VariableKind kind, DataType type, Double initial) {
            vars.add(new Variable(n, kind, type,
                    initial == null ? Optional.empty() : Optional.of(Literal.of(initial)), AT));
            return this;
        }

        Block fuzzify(String variable, Term... terms) {
            fuzz.add(Fcl.fuzzify(variable, terms));
            return this;
        }

        Block defuzzify(Out out) {
            defuzz.add(out.build());
            return this;
        }

        Block rules(Rules r) {
            blocks.add(r.build());
            return this;
        }

        FunctionBlock build() {
            return new FunctionBlock(name, vars, fuzz, defuzz, blocks, List.of(), AT);
        }

        Program program() {
            return new Program("test.fcl", List.of(build()));
        }

        FunctionBlockInstance instance() {
            return Evaluator.load(program()).newInstance();
        }
    }

    static final class Out {
        private final String variable;
        private final DefuzzificationMethod method;
        private final List<Term> terms = new ArrayList<>();
        private Range range;
        private DefaultValue def = new DefaultValue.Constant((Literal) num(0), AT);

        Out(String variable, DefuzzificationMethod method) {
            this.variable = variable;
            this.method = method;
        }

        Out term(String name, MembershipFunction f) {
            terms.add(Fcl.term(name, f));
            return this;
        }

        Out range(double lo, double hi) {
            range = new Range((Literal) num(lo), (Literal) num(hi), AT);
            return this;
        }

        Out defaultValue(double v) {
            def = new DefaultValue.Constant((Literal) num(v), AT);
            return this;
        }

        Out noChange() {
            def = new DefaultValue.NoChange(AT);
            return this;
        }

        Defuzzification build() {
            return new Defuzzification(variable, Optional.ofNullable(range), terms,
                    Optional.of(new Located<>(method, AT)), Optional.of(def), AT);
        }
    }

    static final class Rules {
        private final String name;
        private AndAlgorithm and;
        private OrAlgorithm or;
        private ActivationMethod act;
        private AccumulationMethod accu = AccumulationMethod.MAX;
        private final List<Rule> rules = new ArrayList<>();

        Rules(String name) {
            this.name = name;
        }

        Rules and(AndAlgorithm a) {
            and = a;
            return this;
        }

        Rules or(OrAlgorithm o) {
            or = o;
            return this;
        }

        Rules act(ActivationMethod a) {
            act = a;
            return this;
        }

        Rules accu(AccumulationMethod a) {
            accu = a;
            return this;
        }

        Rules rule(Condition c, Subconclusion... s) {
            rules.add(Fcl.rule(String.valueOf(rules.size() + 1), c, s));
            return this;
        }

        RuleBlock build() {
            return new RuleBlock(name, located(and), located(or), located(act), located(accu), rules, AT);
        }

        private static <T> Optional<Located<T>> located(T v) {
            return v == null ? Optional.empty() : Optional.of(new Located<>(v, AT));
        }
    }
}
