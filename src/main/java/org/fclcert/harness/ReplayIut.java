package org.fclcert.harness;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalInt;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.LoadOutcome;

/**
 * An "implementation" that answers a case from its recorded evidence ({@link Exchange}), in order, so that the
 * case can be judged again by the very code that judged it ({@link Rejudge}). A request that is not the one
 * recorded next (another input, another operation, more requests than recorded) is a mismatch: the evidence
 * does not belong to this case under this run's seed; it is answered with a protocol fault and remembered.
 */
final class ReplayIut implements ImplementationUnderTest {
    private final List<Exchange> recorded;
    private int next;
    private String mismatch;

    ReplayIut(List<Exchange> recorded) {
        this.recorded = recorded == null ? List.of() : List.copyOf(recorded);
    }

    /** The first request that did not match the evidence, or null. */
    String mismatch() {
        if (mismatch == null && next < recorded.size()) {
            return "the evidence records " + (recorded.size() - next) + " request(s) more than judging the case makes"
                    + " (first: " + recorded.get(next).op() + ")";
        }
        return mismatch;
    }

    private Exchange take(String op, String block, Map<String, Double> in) throws IutException {
        if (mismatch != null) {
            throw new IutException(IutException.Kind.PROTOCOL, "replay stopped: " + mismatch);
        }
        if (next >= recorded.size()) {
            mismatch = "request " + (next + 1) + " (" + op + ") is not in the evidence";
        } else {
            Exchange e = recorded.get(next);
            if (!op.equals(e.op()) || "eval".equals(op) && (!Objects.equals(block, e.block()) || !in.equals(e.in()))) {
                mismatch = "request " + (next + 1) + " is " + op + (in == null ? "" : " " + in) + ", the evidence has "
                        + e.op() + (e.in() == null ? "" : " " + e.in());
            }
        }
        if (mismatch != null) {
            throw new IutException(IutException.Kind.PROTOCOL, "replay stopped: " + mismatch);
        }
        Exchange e = recorded.get(next++);
        if (e.error() != null) {
            e.raise();
        }
        return e;
    }

    @Override
    public IutInfo hello() {
        throw new UnsupportedOperationException("a replay answers the requests of a case, not hello");
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        Exchange e = take("load", null, null);
        if (e.rejected() != null) {
            return new LoadOutcome.Rejected(e.rejected(), e.line() == null ? OptionalInt.empty() : OptionalInt.of(e.line()));
        }
        return new LoadOutcome.Loaded(e.blocks() == null ? List.of() : e.blocks());
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        Exchange e = take("eval", block, inputs);
        return e.out() == null ? Map.of() : e.out();
    }

    @Override
    public void reset() throws IutException {
        take("reset", null, null);
    }

    @Override
    public Optional<String> export() throws IutException {
        return Optional.ofNullable(take("export", null, null).text());
    }

    @Override
    public void close() {
    }
}
