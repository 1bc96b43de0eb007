package org.fclcert.model;

/**
 * One entry of fclcert's catalogue of diagnostic codes: the stable code tools key on, how serious it is,
 * the clause or table of IEC 61131-7 it cites and what it means, in one line.
 *
 * <p>Each family of codes has one owner, which declares its entries: {@code syntax.SyntaxCode} (the strict
 * reader, FCL-Snnn and FCL-W1nn), {@code syntax.dialect.DialectCode} (the dialect readers, FCL-Dnnn,
 * FCL-S3nn, FCL-W3nn), the check rules themselves ({@code check.CheckCode}, FCL-Cnnn and FCL-W0nn, one
 * declared by each rule), {@code eval.EvaluationCode} (FCL-Vnnn) and {@code write.ConversionCode}
 * (FCL-Xnnn). {@code cli.DiagnosticCatalogue} lists them all, and a test keeps docs/diagnostics.md equal to
 * that list. A producer reports a {@link Diagnostic} with one of these, never a code spelled as a string.
 */
public interface DiagnosticCode {
    /** The stable code, e.g. {@code FCL-C002}. */
    default String code() {
        return entry().code();
    }

    /** The severity the code is reported with. */
    default Severity severity() {
        return entry().severity();
    }

    /** The clause or table the code cites, e.g. {@code 5.2.4} or {@code Table 3}; {@code —} when none. */
    default String clause() {
        return entry().clause();
    }

    /** One line saying what the code means. */
    default String meaning() {
        return entry().meaning();
    }

    /** The four facts of the entry; an enum of codes holds one per constant, so it need not repeat the accessors. */
    Entry entry();

    /** The facts of one catalogue entry, as {@link DiagnosticCode} gives them. */
    record Entry(String code, Severity severity, String clause, String meaning) {
    }
}
