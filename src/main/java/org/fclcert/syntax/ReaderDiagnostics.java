package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.antlr.v4.runtime.Token;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.SourceLocation;

/**
 * Collects the reader's diagnostics for one text and, at the end, sorts them into source order and
 * caps them so that one early mistake cannot bury the user in follow-up messages.
 */
final class ReaderDiagnostics {
    /** Errors reported before the rest are summarised in one FCL-S099 error. */
    static final int MAX_ERRORS = org.fclcert.model.Limits.MAX_ERRORS_PER_FILE;
    /** Warnings of one code reported before the rest are summarised in one warning. */
    static final int MAX_WARNINGS_PER_CODE = org.fclcert.model.Limits.MAX_WARNINGS_PER_CODE;
    /** Errors kept at most; past this many the reader stops (memory stays bounded on any input). */
    static final int STOP_AFTER_ERRORS = 1_000;

    private final String sourceName;
    private final List<Diagnostic> all = new ArrayList<>();
    private final java.util.Set<SourceLocation> errorPlaces = new java.util.TreeSet<>(SourceLocation::compareTo);
    private final Map<String, Integer> warningCounts = new HashMap<>();
    private int errorCount;
    private boolean errors;
    private boolean endOfTextExplained;

    ReaderDiagnostics(String sourceName) {
        this.sourceName = sourceName;
    }

    SourceLocation at(Token token) {
        return location(sourceName, token);
    }

    /** Where a token starts, as every diagnostic and model element gives it (line and column from 1). */
    static SourceLocation location(String sourceName, Token token) {
        return SourceLocation.of(sourceName, Math.max(1, token.getLine()), token.getCharPositionInLine() + 1);
    }

    SourceLocation at(int line, int column) {
        return SourceLocation.of(sourceName, line, column);
    }

    void error(Token at, DiagnosticCode code, String message) {
        error(at(at), code, message);
    }

    /** Reports an error, unless one is already reported at the same place (one message per place). */
    void error(SourceLocation at, DiagnosticCode code, String message) {
        errors = true;
        if (errorCount >= STOP_AFTER_ERRORS) {
            errorCount++;
        } else if (errorPlaces.add(at)) {
            errorCount++;
            all.add(Diagnostic.error(at, code, message));
        }
    }

    /** True once so many errors are known that reading further would only add noise. */
    boolean tooMany() {
        return errorCount >= STOP_AFTER_ERRORS;
    }

    /** The state to return to if what is reported after this point must be taken back. */
    record Mark(int size, int errorCount, boolean errors, Map<String, Integer> warningCounts) {
    }

    Mark mark() {
        return new Mark(all.size(), errorCount, errors, Map.copyOf(warningCounts));
    }

    /** Takes back everything reported since the mark (a parse attempt that is redone). */
    void rollback(Mark mark) {
        while (all.size() > mark.size()) {
            Diagnostic d = all.remove(all.size() - 1);
            if (d.isError()) {
                errorPlaces.remove(d.location());
            }
        }
        errorCount = mark.errorCount();
        errors = mark.errors();
        warningCounts.clear();
        warningCounts.putAll(mark.warningCounts());
    }

    /** Marks that an error already explains why the text ends early (an unterminated comment). */
    void explainEndOfText() {
        endOfTextExplained = true;
    }

    boolean endOfTextExplained() {
        return endOfTextExplained;
    }

    void warning(Token at, DiagnosticCode code, String message) {
        int n = warningCounts.merge(code.code(), 1, Integer::sum);
        if (n <= MAX_WARNINGS_PER_CODE + 1) {   // one more than shown marks where the summary goes
            all.add(Diagnostic.warning(at(at), code, message));
        }
    }

    /** The warnings reported so far. */
    List<Diagnostic> warnings() {
        return all.stream().filter(d -> !d.isError()).toList();
    }

    /**
     * Keeps a warning found by another reading of the same text (the repaired one, {@link SyntaxRepair}) unless
     * this collector already has it (same code at the same place).
     */
    void keepWarning(Diagnostic warning) {
        boolean known = all.stream().anyMatch(d -> d.code().equals(warning.code()) && d.location().sameAs(warning.location()));
        if (!known && warningCounts.merge(warning.code(), 1, Integer::sum) <= MAX_WARNINGS_PER_CODE + 1) {
            all.add(warning);
        }
    }

    /** This collector as a token filter's report. */
    ReaderOptions.Report asReport() {
        return new ReaderOptions.Report() {
            @Override
            public SourceLocation at(Token token) {
                return ReaderDiagnostics.this.at(token);
            }

            @Override
            public void error(Token at, DiagnosticCode code, String message) {
                ReaderDiagnostics.this.error(ReaderDiagnostics.this.at(at), code, message);
            }

            @Override
            public void warning(Token at, DiagnosticCode code, String message) {
                ReaderDiagnostics.this.warning(at, code, message);
            }
        };
    }

    boolean hasErrors() {
        return errors;
    }

    /** The diagnostics in source order, errors capped at {@link #MAX_ERRORS}. */
    List<Diagnostic> finish() {
        List<Diagnostic> sorted = new ArrayList<>(all);
        sorted.sort(Comparator.comparing(Diagnostic::location));
        List<Diagnostic> kept = new ArrayList<>();
        Map<String, Integer> warningsPerCode = new HashMap<>();
        Map<String, Diagnostic> firstDroppedWarning = new HashMap<>();
        int errorsSeen = 0;
        Diagnostic firstDroppedError = null;
        for (Diagnostic d : sorted) {
            if (d.isError()) {
                errorsSeen++;
                if (errorsSeen <= MAX_ERRORS) {
                    kept.add(d);
                } else if (firstDroppedError == null) {
                    firstDroppedError = d;
                }
            } else {
                int n = warningsPerCode.merge(d.code(), 1, Integer::sum);
                if (n <= MAX_WARNINGS_PER_CODE) {
                    kept.add(d);
                } else {
                    firstDroppedWarning.putIfAbsent(d.code(), d);
                }
            }
        }
        for (Map.Entry<String, Diagnostic> e : firstDroppedWarning.entrySet()) {
            int more = warningCounts.get(e.getKey()) - MAX_WARNINGS_PER_CODE;
            kept.add(Diagnostic.warning(e.getValue().location(), e.getValue().diagnosticCode(),
                    more + " more " + e.getKey() + " warning(s) like the ones above are not shown"));
        }
        if (firstDroppedError != null) {
            int more = errorCount - MAX_ERRORS;
            kept.add(Diagnostic.error(firstDroppedError.location(), SyntaxCode.TOO_MANY_ERRORS,
                    "too many syntax errors: " + more + " more not reported"
                            + (tooMany() ? " (reading stopped early)" : "") + "; fix the ones above first"));
        }
        kept.sort(Comparator.comparing(Diagnostic::location));
        return kept;
    }
}
