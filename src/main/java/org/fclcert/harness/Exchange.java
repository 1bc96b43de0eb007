package org.fclcert.harness;

import com.fasterxml.jackson.annotation.JsonInclude;
import java.util.List;
import java.util.Map;
import org.fclcert.iut.IutException;
import org.fclcert.iut.LoadOutcome;

/**
 * One request of a case and the implementation's reply, as sent and received (in the disguise's names): the
 * evidence a case line of {@code results.jsonl} keeps ({@code replies}), from which {@code report --from},
 * {@code report --verify}, {@code compare} and {@code fclcert:verify} judge the case again ({@link Rejudge}).
 *
 * <p>{@code op} is {@code load}, {@code eval}, {@code reset} or {@code export}. A load: {@code blocks} when it
 * loaded, {@code rejected} (the message) and {@code line} when it was rejected. An eval: {@code block},
 * {@code in}, and {@code out}. An export: {@code text}, absent when the implementation does not export. Any
 * request that failed: {@code error} (the message), {@code errorKind} and {@code stderr}.
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record Exchange(String op, String block, Map<String, Double> in, Map<String, Double> out,
        List<String> blocks, String rejected, Integer line, String text, String error, String errorKind,
        String stderr) {

    static Exchange load(LoadOutcome outcome) {
        if (outcome instanceof LoadOutcome.Rejected r) {
            return new Exchange("load", null, null, null, null, r.message(),
                    r.line().isPresent() ? r.line().getAsInt() : null, null, null, null, null);
        }
        return new Exchange("load", null, null, null, ((LoadOutcome.Loaded) outcome).blocks(), null, null, null, null,
                null, null);
    }

    static Exchange eval(String block, Map<String, Double> in, Map<String, Double> out) {
        return new Exchange("eval", block, in, out, null, null, null, null, null, null, null);
    }

    static Exchange plain(String op) {
        return new Exchange(op, null, null, null, null, null, null, null, null, null, null);
    }

    static Exchange export(String text) {
        return new Exchange("export", null, null, null, null, null, null, text, null, null, null);
    }

    /** A request that ended in {@code e}; for an eval with its block and inputs. */
    static Exchange failed(String op, String block, Map<String, Double> in, IutException e) {
        return new Exchange(op, block, in, null, null, null, null, null, e.getMessage(), e.kind().name(),
                e.stderrTail());
    }

    /** What {@link #broke} records as the kind of an in-process failure outside the contract. */
    static final String RUNTIME = "RUNTIME";
    static final String STACK_OVERFLOW = "STACK_OVERFLOW";

    /** A request to an in-process implementation that threw outside its contract (a RuntimeException, a stack overflow). */
    static Exchange broke(String op, String block, Map<String, Double> in, Throwable e) {
        return new Exchange(op, block, in, null, null, null, null, null, String.valueOf(e),
                e instanceof StackOverflowError ? STACK_OVERFLOW : RUNTIME, null);
    }

    /** Raises the recorded failure again: an {@link IutException}, or what {@link #broke} recorded. */
    void raise() throws IutException {
        if (RUNTIME.equals(errorKind)) {
            String text = error;
            throw new RuntimeException(text) {
                private static final long serialVersionUID = 1L;

                @Override
                public String toString() {
                    return text;
                }
            };
        }
        if (STACK_OVERFLOW.equals(errorKind)) {
            throw new StackOverflowError();
        }
        throw exception();
    }

    /** The recorded failure, raised again. */
    IutException exception() {
        IutException.Kind kind;
        try {
            kind = IutException.Kind.valueOf(errorKind);
        } catch (RuntimeException e) {
            kind = IutException.Kind.PROTOCOL;
        }
        return new IutException(kind, error, stderr == null ? "" : stderr);
    }
}
