package org.fclcert.write;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Program;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Term;

/**
 * Turns a program a dialect reader produced into a program of standard FCL (IEC 61131-7 as the strict reader
 * reads it), saying for each non-standard construct whether it converted exactly, approximately (with the
 * largest error) or not at all. {@code fclcert convert} writes the result with the {@link CanonicalWriter}.
 *
 * <p>The conversion is a list of {@link ConstructConversion}s ({@link #CONVERSIONS}), one per kind of
 * construct, applied in order; each rewrites what it knows and reports a {@link Finding} per construct. To
 * teach the converter a new construct (a named shape, a hedge), add a conversion to that list, or a case to
 * {@link #convertTerm} for a new kind of membership function.
 */
public final class StandardConversion {

    /** How to convert: {@code approximatePoints} is the number of points for curves (0: do not approximate). */
    public record Options(int approximatePoints) {
        public static final Options DEFAULT = new Options(0);
    }

    /** How a construct converted. */
    public sealed interface Kind {
        /** Standard FCL says exactly the same. */
        record Exact() implements Kind {
        }

        /** Standard FCL says nearly the same: {@code maxError} is the largest membership error. */
        record Approximated(double maxError) implements Kind {
        }

        /** Standard FCL cannot say it; {@code replacement} says what the converted program has in its place. */
        record NotExpressible(String replacement) implements Kind {
        }
    }

    /** One construct of the original program and how it converted. */
    public record Finding(String construct, SourceLocation location, Kind kind, String message) {
    }

    /** The standard program and the findings, in source order. */
    public record Result(Program program, List<Finding> findings) {
        public Result {
            findings = List.copyOf(findings);
        }

        /** True when the converted program means exactly what the original does. */
        public boolean exact() {
            return findings.stream().allMatch(f -> f.kind() instanceof Kind.Exact);
        }
    }

    /** One kind of construct: rewrites it to standard FCL in the program, adding a finding per use. */
    public interface ConstructConversion {
        Program apply(Program program, Options options, List<Finding> findings);
    }

    /** The conversions, applied in this order. */
    static final List<ConstructConversion> CONVERSIONS = List.of(
            StandardConversion::dialectSyntax,
            StandardConversion::terms,
            StandardConversion::methods);

    public Result convert(Program program) {
        return convert(program, Options.DEFAULT);
    }

    public Result convert(Program program, Options options) {
        List<Finding> findings = new ArrayList<>();
        Program p = program;
        for (ConstructConversion c : CONVERSIONS) {
            p = c.apply(p, options, findings);
        }
        findings.sort(Comparator.comparing(Finding::location));
        return new Result(new Program(p.sourceName(), p.functionBlocks()), findings);
    }

    // ---------------------------------------------------------------- the conversions

    /**
     * Constructs a dialect reader already expressed in the standard model (a term-only subcondition is a
     * 'variable IS term', ACCUM is ACCU, ...): the model is standard, so each converts exactly.
     */
    private static Program dialectSyntax(Program program, Options options, List<Finding> findings) {
        for (FeatureUse u : program.dialectFeatures()) {
            findings.add(new Finding(u.feature().id(), u.location(), new Kind.Exact(),
                    DialectSyntaxText.standardForm(u.feature())));
        }
        return program;
    }

    /** Every term's membership function in a form of 5.2.2 (points or a singleton). */
    private static Program terms(Program program, Options options, List<Finding> findings) {
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            List<Fuzzification> fuzzifications = new ArrayList<>();
            for (Fuzzification f : fb.fuzzifications()) {
                fuzzifications.add(new Fuzzification(f.variable(), convertTerms(f.terms(), options, findings),
                        f.location()));
            }
            List<Defuzzification> defuzzifications = new ArrayList<>();
            for (Defuzzification d : fb.defuzzifications()) {
                defuzzifications.add(new Defuzzification(d.variable(), d.range(),
                        convertTerms(d.terms(), options, findings), d.method(), d.defaultValue(), d.location()));
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fuzzifications, defuzzifications,
                    fb.ruleBlocks(), fb.options(), fb.location()));
        }
        return new Program(program.sourceName(), blocks, program.dialectFeatures());
    }

    private static List<Term> convertTerms(List<Term> terms, Options options, List<Finding> findings) {
        List<Term> out = new ArrayList<>(terms.size());
        for (Term t : terms) {
            out.add(convertTerm(t, options, findings));
        }
        return out;
    }

    /**
     * One term. Points and singletons are standard already. EXTENSION POINT for named shapes: a new kind of
     * {@link MembershipFunction} gets a branch here returning exact points (triangle, trapezoid, rectangle,
     * ramp: no finding needed beyond Exact) or, with {@code options.approximatePoints() > 0}, a polyline with
     * a {@link Kind.Approximated} finding carrying the largest membership error; without points, a
     * {@link Kind.NotExpressible} finding.
     */
    static Term convertTerm(Term t, Options options, List<Finding> findings) {
        MembershipFunction f = t.function();
        if (f instanceof MembershipFunction.Points || f instanceof MembershipFunction.Singleton) {
            return t;
        }
        findings.add(new Finding("term '" + t.name() + "'", t.location(), new Kind.NotExpressible("kept as read"),
                "term '" + t.name() + "': no conversion to points is known for its membership function"));
        return t;
    }

    /**
     * Defuzzification methods outside Table 1. MoM has no standard equivalent (CoG, CoA, LM and RM all
     * give other values on a plateau): not expressible; the converted program uses CoG, the method FFLL
     * itself falls back to.
     */
    private static Program methods(Program program, Options options, List<Finding> findings) {
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlock fb : program.functionBlocks()) {
            List<Defuzzification> defuzzifications = new ArrayList<>();
            for (Defuzzification d : fb.defuzzifications()) {
                Optional<Located<DefuzzificationMethod>> method = d.method();
                if (method.isPresent() && !method.get().value().standard()) {
                    DefuzzificationMethod replacement = d.terms().stream()
                            .allMatch(t -> t.function() instanceof MembershipFunction.Singleton)
                            ? DefuzzificationMethod.COGS : DefuzzificationMethod.COG;
                    findings.add(new Finding("METHOD " + method.get().value().keyword(), method.get().location(),
                            new Kind.NotExpressible("METHOD : " + replacement.keyword()),
                            "METHOD " + method.get().value().keyword() + " of " + d.variable() + " (O-MOM, mean of"
                                    + " maximum) has no equivalent among the methods of Table 1; the converted"
                                    + " program uses " + replacement.keyword() + ", which gives other values"));
                    method = Optional.of(new Located<>(replacement, method.get().location()));
                }
                defuzzifications.add(new Defuzzification(d.variable(), d.range(), d.terms(), method,
                        d.defaultValue(), d.location()));
            }
            blocks.add(new FunctionBlock(fb.name(), fb.variables(), fb.fuzzifications(), defuzzifications,
                    fb.ruleBlocks(), fb.options(), fb.location()));
        }
        return new Program(program.sourceName(), blocks, program.dialectFeatures());
    }
}
