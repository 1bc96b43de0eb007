package org.fclcert.iut;

import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalLong;
import org.fclcert.sandbox.Isolation;
import org.fclcert.syntax.dialect.Dialect;

/**
 * An implementation that passes every call on to another one: the base of the wrappers (recording, guarding,
 * disguising), which override only what they add. A method added to {@link ImplementationUnderTest} is forwarded
 * here, once, so that no wrapper silently answers with the interface's default instead of the implementation's
 * (a crash behind a wrapper that did not forward {@code health} went uncounted).
 */
public abstract class ForwardingIut implements ImplementationUnderTest {
    private final ImplementationUnderTest delegate;

    protected ForwardingIut(ImplementationUnderTest delegate) {
        this.delegate = java.util.Objects.requireNonNull(delegate, "delegate");
    }

    /** The implementation the calls go to. */
    protected final ImplementationUnderTest delegate() {
        return delegate;
    }

    @Override
    public IutInfo hello() throws IutException {
        return delegate.hello();
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        return delegate.load(fcl);
    }

    @Override
    public LoadOutcome loadWritten(String text, Dialect layout) throws IutException {
        return delegate.loadWritten(text, layout);
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        return delegate.eval(block, inputs);
    }

    @Override
    public void reset() throws IutException {
        delegate.reset();
    }

    @Override
    public Optional<String> export() throws IutException {
        return delegate.export();
    }

    @Override
    public OptionalLong peakMemoryBytes() {
        return delegate.peakMemoryBytes();
    }

    @Override
    public OptionalDouble lastEvalMillis() {
        return delegate.lastEvalMillis();
    }

    @Override
    public Isolation isolation() {
        return delegate.isolation();
    }

    @Override
    public IutHealth health() {
        return delegate.health();
    }

    @Override
    public void close() {
        delegate.close();
    }
}
