package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.fclcert.model.Diagnostic;
import org.fclcert.model.Severity;
import org.fclcert.model.SourceLocation;
import org.fclcert.write.StandardConversion.Finding;
import org.fclcert.write.StandardConversion.Kind;
import org.junit.jupiter.api.Test;

/** A conversion finding is a catalogue Diagnostic (FCL-X001/X002), or a note without a code when exact. */
class ConversionDiagnosticsTest {
    private static final SourceLocation AT = SourceLocation.of("t.fcl", 16, 5);

    @Test
    void anExactConversionIsNoDiagnostic() {
        Finding exact = new Finding("O-HEDGE-ANY", AT, new Kind.Exact(), "written without the hedge");
        assertTrue(exact.diagnostic(false).isEmpty());
        assertTrue(exact.diagnostic(true).isEmpty());
    }

    @Test
    void anApproximationIsAnX002WarningWithItsBoundRoundedUp() {
        // 0.012345 to 3 significant digits, rounded up so that it stays a bound: 0.0124
        Finding f = new Finding("O-SHAPE-GAUSSIAN", AT, new Kind.Approximated(0.012345), "term 'poor' as 21 points");
        Diagnostic d = f.diagnostic(false).orElseThrow();
        assertEquals(ConversionCode.APPROXIMATED, d.diagnosticCode());
        assertEquals(Severity.WARNING, d.severity());
        assertEquals("t.fcl:16:5: warning FCL-X002: O-SHAPE-GAUSSIAN: approximated, largest membership error at most"
                + " 0.0124: term 'poor' as 21 points", d.toString());
        assertEquals("0.25", StandardConversion.upTo3Digits(0.25));
        assertEquals("0.101", StandardConversion.upTo3Digits(0.1));   // the double 0.1 is a little above 1/10
    }

    @Test
    void aConstructStandardFclCannotSayIsAnX001ErrorOrAWarningWhenLossIsAllowed() {
        Finding f = new Finding("METHOD MoM", AT, new Kind.NotExpressible("CoG"), "no Table 1 method");
        Diagnostic refused = f.diagnostic(false).orElseThrow();
        assertEquals(ConversionCode.NOT_EXPRESSIBLE, refused.diagnosticCode());
        assertEquals("t.fcl:16:5: error FCL-X001: METHOD MoM is not expressible in standard FCL: no Table 1 method",
                refused.toString());
        Diagnostic allowed = f.diagnostic(true).orElseThrow();
        assertEquals(Severity.WARNING, allowed.severity());
        assertEquals("FCL-X001", allowed.code());
    }
}
