package org.fclcert.iut;

import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;

/**
 * One FCL implementation as the harness drives it, whatever it really is (fclcert's own evaluator,
 * a vendor's Java class, or a separate process speaking JSON lines). One session holds at most one
 * loaded program and one instance of one of its function blocks at a time.
 *
 * <p>Every failure of the implementation arrives as an {@link IutException} whose {@link
 * IutException.Kind} tells the harness how to record it; no other exception escapes. Implementations
 * are not thread-safe: one harness thread drives one session.
 */
public interface ImplementationUnderTest extends AutoCloseable {

    /** Who the implementation says it is, and which features it claims to realise. */
    IutInfo hello() throws IutException;

    /**
     * Loads a program, replacing the one loaded before. The text keeps the line numbers of the corpus
     * file it came from, so a rejection's line can be compared with the case's expected line.
     */
    LoadOutcome load(String fcl) throws IutException;

    /**
     * Sets the given inputs on the instance of {@code block} ({@code null} = the program's first function
     * block), evaluates once and returns every output (VAR_OUTPUT names as declared). There is one
     * instance per function block; it keeps its state between calls (the ordered vectors of one case
     * run on one instance) until {@link #reset()} or the next {@link #load}.
     */
    /**
     * Loads a program written in a library's layout (the semantic axis, {@code certify --present-as}). An
     * implementation gets the text as it is, through {@link #load}; only fclcert's reference evaluator, which
     * reads the standard's layout by default, reads it with fclcert's reader of {@code layout}.
     */
    default LoadOutcome loadWritten(String text, org.fclcert.syntax.dialect.Dialect layout) throws IutException {
        return load(text);
    }

    Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException;

    /** Fresh state for every instance; the program stays loaded. */
    void reset() throws IutException;

    /**
     * The loaded program written back as FCL text by the implementation; empty when it cannot export.
     * Asking with no program loaded is an {@link IutException.Kind#EVAL_ERROR} (or whatever a process IUT
     * answers).
     */
    Optional<String> export() throws IutException;

    /**
     * Peak resident memory of the implementation in bytes, where it can be measured (a process IUT on
     * Linux); empty otherwise. An addition to the shared contract, used by the probe.
     */
    default OptionalLong peakMemoryBytes() {
        return OptionalLong.empty();
    }

    /**
     * How long the last {@link #eval} took by the implementation's own clock, in milliseconds, when it
     * says (a process IUT's optional {@code elapsedMs} in its eval reply); empty otherwise. Used by the probe.
     */
    default java.util.OptionalDouble lastEvalMillis() {
        return java.util.OptionalDouble.empty();
    }

    /**
     * The isolation the implementation runs under, as the certificate records it. Adapters that launch a process
     * answer with their sandbox's; everything else is called inside fclcert's JVM.
     */
    default org.fclcert.sandbox.Isolation isolation() {
        return org.fclcert.sandbox.Isolation.inProcess("called inside fclcert's own JVM");
    }

    /**
     * How often the implementation broke down and was restarted so far (a process IUT); none for an implementation
     * that is never restarted. The harness counts a case's crashes by the difference around it.
     */
    default IutHealth health() {
        return IutHealth.NONE;
    }

    /** Ends the session and frees its resources; never throws. */
    @Override
    void close();
}
