package org.fclcert.harness;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.iut.ForwardingIut;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.syntax.dialect.Dialect;

/**
 * The implementation as one case sees it under its {@link Disguise}: eval requests go out in the disguise's
 * names and replies come back in the corpus's, an exported text is turned back into the corpus's names; every
 * request and reply is kept as it crossed the wire ({@link Exchange}), the case's evidence. {@code close} does
 * not close the implementation (the run owns it).
 */
final class DisguisedIut extends ForwardingIut {
    private final Disguise disguise;
    private final List<Exchange> exchanges = new ArrayList<>();

    DisguisedIut(ImplementationUnderTest inner, Disguise disguise) {
        super(inner);
        this.disguise = disguise;
    }

    /** What crossed the wire so far. */
    List<Exchange> exchanges() {
        return List.copyOf(exchanges);
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        return recordedLoad(() -> delegate().load(fcl));
    }

    /** A program written in a library's layout (the semantic axis), forwarded as such and kept as a load. */
    @Override
    public LoadOutcome loadWritten(String text, Dialect layout) throws IutException {
        return recordedLoad(() -> delegate().loadWritten(text, layout));
    }

    private interface LoadCall {
        LoadOutcome call() throws IutException;
    }

    private LoadOutcome recordedLoad(LoadCall call) throws IutException {
        try {
            LoadOutcome outcome = call.call();
            exchanges.add(Exchange.load(outcome));
            return outcome;
        } catch (IutException e) {
            exchanges.add(Exchange.failed("load", null, null, e));
            throw e;
        } catch (RuntimeException | StackOverflowError e) {
            exchanges.add(Exchange.broke("load", null, null, e));
            throw e;
        }
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        String sentBlock = disguise.sent(block);
        Map<String, Double> sent = disguise.sent(inputs);
        try {
            Map<String, Double> got = delegate().eval(sentBlock, sent);
            exchanges.add(Exchange.eval(sentBlock, sent, got == null ? Map.of() : got));
            return disguise.received(got);
        } catch (IutException e) {
            exchanges.add(Exchange.failed("eval", sentBlock, sent, e));
            throw e;
        } catch (RuntimeException | StackOverflowError e) {
            exchanges.add(Exchange.broke("eval", sentBlock, sent, e));
            throw e;
        }
    }

    @Override
    public void reset() throws IutException {
        try {
            delegate().reset();
            exchanges.add(Exchange.plain("reset"));
        } catch (IutException e) {
            exchanges.add(Exchange.failed("reset", null, null, e));
            throw e;
        }
    }

    @Override
    public Optional<String> export() throws IutException {
        try {
            Optional<String> text = delegate().export();
            exchanges.add(Exchange.export(text.orElse(null)));
            return text.map(disguise::undisguised);
        } catch (IutException e) {
            exchanges.add(Exchange.failed("export", null, null, e));
            throw e;
        } catch (RuntimeException | StackOverflowError e) {
            exchanges.add(Exchange.broke("export", null, null, e));
            throw e;
        }
    }

    @Override
    public void close() {
        // the run closes the implementation
    }
}
