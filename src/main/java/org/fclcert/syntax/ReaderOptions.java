package org.fclcert.syntax;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.antlr.v4.runtime.Token;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.SourceLocation;

/**
 * What a reader built on the strict pipeline may change: the one extension point the dialect readers
 * (org.fclcert.syntax.dialect) use to reuse the strict grammar and model builder instead of having grammars
 * of their own. {@link #STRICT} is the standard exactly; {@link #OPEN_LEVEL} is the standard plus the
 * Open Level methods (Table 10) that fit the standard's syntax ({@code METHOD : MoM;}), the language the
 * conformance corpus and the reference implementation read.
 *
 * @param nonStandardMethods        METHOD words outside Table 1 the builder accepts (the feature detector
 *                                  reports them as Open Level features)
 * @param endFuzzifyClosesDefuzzify END_FUZZIFY may close a DEFUZZIFY block without an error (FFLL, the draft)
 * @param draftFormsAccepted        the forms the standard's own texts disagree on (RANGE last, RANGE :=,
 *                                  OPTION/END_OPTION) are accepted without the FCL-W101..W103 warnings
 * @param tokenFilter               rewrites the lexer's tokens (comments included) before the pre-scan
 */
public record ReaderOptions(Set<DefuzzificationMethod> nonStandardMethods, boolean endFuzzifyClosesDefuzzify,
        boolean draftFormsAccepted, TokenFilter tokenFilter) {

    public static final ReaderOptions STRICT = new ReaderOptions(Set.of(), false, false, TokenFilter.NONE);
    public static final ReaderOptions OPEN_LEVEL = new ReaderOptions(EnumSet.of(DefuzzificationMethod.MOM), false,
            false, TokenFilter.NONE);

    public ReaderOptions {
        nonStandardMethods = Set.copyOf(nonStandardMethods);
    }

    /**
     * Sees every token the lexer made, comments included, and returns the tokens the strict pipeline goes
     * on with (it may drop, replace or insert tokens; new tokens should carry the position of the text they
     * stand for). It reports through {@code report}; it must not throw.
     */
    public interface TokenFilter {
        TokenFilter NONE = (tokens, report) -> tokens;

        List<Token> filter(List<Token> tokens, Report report);
    }

    /** How a token filter reports: located diagnostics with codes of the filter's own catalogue family. */
    public interface Report {
        SourceLocation at(Token token);

        void error(Token at, DiagnosticCode code, String message);

        void warning(Token at, DiagnosticCode code, String message);
    }
}
