package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.model.Literal;
import org.fclcert.model.Feature;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Names;
import org.fclcert.model.Operand;
import org.fclcert.model.Point;
import org.fclcert.model.ShapeKind;
import org.fclcert.model.Term;
import org.fclcert.model.VariableRef;
import org.fclcert.syntax.dialect.DialectLexer.Kind;
import org.fclcert.syntax.dialect.DialectLexer.Token;

/**
 * The terms of a library dialect ({@code TERM t := ...;}) for the {@link DialectParser}: points, a
 * singleton, a named shape of the library's {@link ShapeNames} table, or one of its own forms
 * ({@link LibraryDialect#specialTerm}).
 */
final class DialectTermParser {
    private final DialectParser p;

    DialectTermParser(DialectParser parser) {
        this.p = parser;
    }


    Term term(DialectParser.TermContext where) {
        Token kw = p.next();
        String termName = p.name();
        if (p.peek().kind() == Kind.COLON && p.peek(1).kind() == Kind.ASSIGN) {
            p.error(p.peek(), DialectCode.SYNTAX, "expected ':=' but found ': :='");
            throw new DialectParser.Skip();
        }
        p.expect(Kind.ASSIGN, "':='");
        MembershipFunction f = membershipFunction(where);
        Token end = p.expect(Kind.SEMI, "';' after the term");
        if (p.dialect.oneLineStatements() && end.line() != kw.line()) {
            p.error(end, DialectCode.STATEMENT_SPANS_LINES, p.library + " reads a TERM from one line;"
                    + " this one continues on line " + end.line());
        }
        return new Term(termName, f, p.at(kw));
    }

    private MembershipFunction membershipFunction(DialectParser.TermContext where) {
        Token t = p.peek();
        if (t.kind() == Kind.LPAREN) {
            return new MembershipFunction.Points(points());
        }
        if (t.kind() == Kind.NUMBER) {
            return new MembershipFunction.Singleton(p.number(false));
        }
        if (t.kind() != Kind.WORD) {
            throw p.fail(t, "points, a number or a membership-function name");
        }
        p.next();
        Optional<MembershipFunction> special = p.dialect.specialTerm(p, t, where);
        if (special.isPresent()) {
            return special.get();
        }
        Optional<ShapeKind> kind = p.dialect.shapes().kind(t.text());
        if (kind.isEmpty()) {
            boolean known = p.dialect.shapes().known(t.text());
            p.error(t, known ? DialectCode.UNSUPPORTED : DialectCode.UNKNOWN_SHAPE, known
                    ? "fclcert does not evaluate " + p.library + "'s '" + t.text() + "' terms"
                    + (where == DialectParser.TermContext.INPUT ? " in an input" : "")
                    : "'" + t.text() + "' is not a membership function of " + p.library);
            throw new DialectParser.Skip();
        }
        List<Literal> written = new ArrayList<>();
        while (p.peek().kind() == Kind.NUMBER) {
            written.add(p.number(false));
        }
        if (p.dialect.variablesAsPoints() && p.peek().kind() == Kind.WORD) {
            return withVariables(t, kind.get(), written);
        }
        return new MembershipFunction.NamedShape(kind.get(), p.dialect.shapes().canonical(kind.get(), written));
    }

    /**
     * jFuzzyLogic's linear shapes with variables among their parameters ({@code trian a mid 10}): the points they
     * stand for, with the variables as the standard's variable points (5.2.2). A curve with a variable parameter is
     * not evaluated (located error).
     */
    private MembershipFunction withVariables(Token name, ShapeKind kind, List<Literal> numbers) {
        List<Operand> written = new ArrayList<>(numbers);
        while (p.peek().kind() == Kind.NUMBER || p.peek().kind() == Kind.WORD) {
            written.add(operand());
        }
        if (kind != ShapeKind.TRIANGLE && kind != ShapeKind.TRAPEZOID || written.size() != kind.arity()) {
            p.error(name, DialectCode.UNSUPPORTED, "fclcert evaluates " + p.library + "'s '" + name.text() + "' with"
                    + " variables as parameters only for trian (3 parameters) and trape (4)");
            throw new DialectParser.Skip();
        }
        double[] degrees = kind == ShapeKind.TRIANGLE ? new double[] {0, 1, 0} : new double[] {0, 1, 1, 0};
        List<Point> pts = new ArrayList<>();
        for (int i = 0; i < written.size(); i++) {
            pts.add(new Point(written.get(i), Literal.of(degrees[i]), p.at(name)));
        }
        p.feature(Feature.valueOf("O_SHAPE_" + kind.name()), p.at(name));
        return new MembershipFunction.Points(pts);
    }

    /** (x, y) (x, y) ...; no commas between the points (both libraries reject them). */
    List<Point> points() {
        List<Point> pts = new ArrayList<>();
        while (p.peek().kind() == Kind.LPAREN) {
            Token open = p.next();
            Operand x = operand();
            p.expect(Kind.COMMA, "',' between x and degree");
            Operand y = operand();
            p.expect(Kind.RPAREN, "')'");
            pts.add(new Point(x, y, p.at(open)));
            if (p.peek().kind() == Kind.COMMA) {
                p.error(p.peek(), DialectCode.NOT_IN_DIALECT, p.library + " rejects ',' between points");
                p.next();
            }
        }
        return pts;
    }

    /** A number, or where the dialect allows it a variable's name (a point given by a variable, 5.2.2). */
    Operand operand() {
        Token t = p.peek();
        if (t.kind() == Kind.WORD && p.dialect.variablesAsPoints() && !t.text().equals("nan") && !t.text().equals("inf")) {
            p.next();
            p.dialect.pointVariable(p, t);
            return new VariableRef(t.text(), p.at(t));
        }
        return p.number(false);
    }

    /** Whether a FUZZIFY or DEFUZZIFY block of the variable has been read, or is being read. */
    static boolean blockRead(DialectParser p, String variable) {
        return Names.same(variable, p.openBlock) || p.fuzzifications.stream().anyMatch(f -> Names.same(f.variable(),
                variable)) || p.outputs.stream().anyMatch(o -> Names.same(o.variable, variable));
    }
}
