package org.fclcert.check;

import org.fclcert.model.DataType;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Literal;
import org.fclcert.model.Variable;

/**
 * FCL-C030: a variable's initial value is representable in its declared type (IEC 61131-3 data
 * types, 5.2.1): a whole number within range for the integer types, a finite value within range
 * for REAL and LREAL. A real literal with a whole value (e.g. {@code 2.0} for INT) is accepted.
 */
public final class InitialValueFitsType implements FunctionBlockRule {
    /** The code this rule owns. */
    public static final CheckCode CODE = CheckCode.error("FCL-C030", "5.2.1 (IEC 61131-3 data types)",
            "every initial value can be represented in its variable's data type");

    @Override
    public CheckCode diagnosticCode() {
        return CODE;
    }

    @Override
    public void check(FunctionBlock block, DiagnosticSink sink) {
        for (Variable v : block.variables()) {
            if (v.initialValue().isEmpty()) {
                continue;
            }
            Literal init = v.initialValue().get();
            String problem = problem(init, v.type());
            if (problem != null) {
                sink.report(finding(init.location(), "initial value " + written(init) + " of "
                        + Describe.variable(v) + " " + problem + " (5.2.1)"));
            }
        }
    }

    private static String written(Literal init) {
        boolean whole = Double.isFinite(init.value()) && init.value() == Math.rint(init.value());
        return init.integral() && whole ? init.exactValue().toBigInteger().toString() : Describe.number(init.value());
    }

    /* Compared exactly: as doubles, LINT 9223372036854775808 equals Long.MAX_VALUE (both 2^63). */
    private static String problem(Literal init, DataType type) {
        double value = init.value();
        if (!Double.isFinite(value) || init.exactValue().compareTo(type.exactMin()) < 0
                || init.exactValue().compareTo(type.exactMax()) > 0) {
            return "is outside the range of " + type + " (" + bound(type, type.exactMin(), type.min()) + " .. "
                    + bound(type, type.exactMax(), type.max()) + ")";
        }
        if (type.isInteger() && value != Math.rint(value)) {
            return "is not a whole number, but " + type + " holds only integers";
        }
        return null;
    }

    private static String bound(DataType type, java.math.BigDecimal exact, double value) {
        return type.isInteger() ? exact.toBigInteger().toString() : Describe.number(value);
    }
}
