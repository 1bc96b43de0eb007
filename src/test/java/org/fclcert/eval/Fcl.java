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
public final class Fcl {
    static final SourceLocation AT = SourceLocation.UNKNOWN;

    private Fcl() {
    }

    public static Operand num(double v) {
        return Literal.of(v);
    }

    public static Operand var(String name) {
        return new VariableRef(name, AT);
    }

    /** Points from alternating x, degree constants. */
    public static MembershipFunction pts(double... xy) {
        List<Point> p = new ArrayList<>();
        for (int i = 0; i < xy.length; i += 2) {
            p.add(new Point(num(xy[i]), num(xy[i + 1]), AT));
        }
        return new MembershipFunction.Points(p);
    }

    /** Points from alternating operands (x, degree). */
    public static MembershipFunction ptsOf(Operand... xy) {
        List<Point> p = new ArrayList<>();
        for (int i = 0; i < xy.length; i += 2) {
            p.add(new Point(xy[i], xy[i + 1], AT));
        }
        return new MembershipFunction.Points(p);
    }

    public static MembershipFunction single(double v) {
        return new MembershipFunction.Singleton(num(v));
    }

    public static MembershipFunction single(Operand v) {
        return new MembershipFunction.Singleton(v);
    }

    public static Term term(String name, MembershipFunction f) {
        return new Term(name, f, AT);
    }

    public static Condition is(String variable, String term) {
        return new Condition.TermSubcondition(variable, term, false, AT);
    }

    public static Condition isNot(String variable, String term) {
        return new Condition.TermSubcondition(variable, term, true, AT);
    }

    public static Condition v(String variable) {
        return new Condition.VariableSubcondition(variable, AT);
    }

    public static Condition not(Condition c) {
        return new Condition.Not(c, AT);
    }

    public static Condition and(Condition... cs) {
        return new Condition.And(Arrays.asList(cs), AT);
    }

    public static Condition or(Condition... cs) {
        return new Condition.Or(Arrays.asList(cs), AT);
    }

    public static Condition paren(Condition c) {
        return new Condition.Parenthesized(c, AT);
    }

    public static Subconclusion then(String variable, String term) {
        return new Subconclusion(variable, Optional.of(term), Optional.empty(), AT);
    }

    public static Subconclusion then(String variable, String term, Operand weight) {
        return new Subconclusion(variable, Optional.of(term), Optional.of(weight), AT);
    }

    public static Subconclusion thenVar(String variable) {
        return new Subconclusion(variable, Optional.empty(), Optional.empty(), AT);
    }

    public static Subconclusion thenVar(String variable, Operand weight) {
        return new Subconclusion(variable, Optional.empty(), Optional.of(weight), AT);
    }

    public static Rule rule(String name, Condition c, Subconclusion... s) {
        return new Rule(name, c, Arrays.asList(s), AT);
    }

    public static Fuzzification fuzzify(String variable, Term... terms) {
        return new Fuzzification(variable, Arrays.asList(terms), AT);
    }

    /** A function block under construction. */
    public static Block block(String name) {
        return new Block(name);
    }

    public static Out defuzzify(String variable, DefuzzificationMethod method) {
        return new Out(variable, method);
    }

    public static Rules ruleBlock(String name) {
        return new Rules(name);
    }

    public static final class Block {
        private final String name;
        private final List<Variable> vars = new ArrayList<>();
        private final List<Fuzzification> fuzz = new ArrayList<>();
        private final List<Defuzzification> defuzz = new ArrayList<>();
        private final List<RuleBlock> blocks = new ArrayList<>();

        Block(String name) {
            this.name = name;
        }

        public Block input(String n) {
            return variable(n, VariableKind.INPUT, DataType.REAL, null);
        }

        public Block output(String n) {
            return variable(n, VariableKind.OUTPUT, DataType.REAL, null);
        }

        public Block local(String n) {
            return variable(n, VariableKind.LOCAL, DataType.REAL, null);
        }

        public Block variable(String n, VariableKind kind, DataType type, Double initial) {
            vars.add(new Variable(n, kind, type,
                    initial == null ? Optional.empty() : Optional.of(Literal.of(initial)), AT));
            return this;
        }

        public Block fuzzify(String variable, Term... terms) {
            fuzz.add(Fcl.fuzzify(variable, terms));
            return this;
        }

        public Block defuzzify(Out out) {
            defuzz.add(out.build());
            return this;
        }

        public Block rules(Rules r) {
            blocks.add(r.build());
            return this;
        }

        public FunctionBlock build() {
            return new FunctionBlock(name, vars, fuzz, defuzz, blocks, List.of(), AT);
        }

        public Program program() {
            return new Program("test.fcl", List.of(build()));
        }

        public FunctionBlockInstance instance() {
            return Evaluator.load(program()).newInstance();
        }
    }

    public static final class Out {
        private final String variable;
        private final DefuzzificationMethod method;
        private final List<Term> terms = new ArrayList<>();
        private Range range;
        private DefaultValue def = new DefaultValue.Constant((Literal) num(0), AT);

        Out(String variable, DefuzzificationMethod method) {
            this.variable = variable;
            this.method = method;
        }

        public Out term(String name, MembershipFunction f) {
            terms.add(Fcl.term(name, f));
            return this;
        }

        public Out range(double lo, double hi) {
            range = new Range((Literal) num(lo), (Literal) num(hi), AT);
            return this;
        }

        public Out defaultValue(double v) {
            def = new DefaultValue.Constant((Literal) num(v), AT);
            return this;
        }

        public Out noChange() {
            def = new DefaultValue.NoChange(AT);
            return this;
        }

        public Defuzzification build() {
            return new Defuzzification(variable, Optional.ofNullable(range), terms,
                    Optional.of(new Located<>(method, AT)), Optional.of(def), AT);
        }
    }

    public static final class Rules {
        private final String name;
        private AndAlgorithm and;
        private OrAlgorithm or;
        private ActivationMethod act;
        private AccumulationMethod accu = AccumulationMethod.MAX;
        private final List<Rule> rules = new ArrayList<>();

        Rules(String name) {
            this.name = name;
        }

        public Rules and(AndAlgorithm a) {
            and = a;
            return this;
        }

        public Rules or(OrAlgorithm o) {
            or = o;
            return this;
        }

        public Rules act(ActivationMethod a) {
            act = a;
            return this;
        }

        public Rules accu(AccumulationMethod a) {
            accu = a;
            return this;
        }

        public Rules rule(Condition c, Subconclusion... s) {
            rules.add(Fcl.rule(String.valueOf(rules.size() + 1), c, s));
            return this;
        }

        public RuleBlock build() {
            return new RuleBlock(name, located(and), located(or), located(act), located(accu), rules, AT);
        }

        private static <T> Optional<Located<T>> located(T v) {
            return v == null ? Optional.empty() : Optional.of(new Located<>(v, AT));
        }
    }
}
