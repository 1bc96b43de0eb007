package org.fclcert.iut;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Timer;
import java.util.TimerTask;
import org.fclcert.syntax.dialect.Dialect;

/**
 * A request from outside a run to stop it: Ctrl-C or SIGTERM (the command line's shutdown hook), or the run's
 * time budget running out. The thread doing the run checks {@link #stopped()} between its steps; while it waits
 * for an implementation {@linkplain #guard guarded} by this signal, stopping interrupts it, so that the wait ends
 * at once instead of at the request's timeout. A call that the stop cut short — refused because the run had
 * stopped, or under way when it stopped, whatever the implementation then did (an IUT in the terminal's process
 * group receives the same Ctrl-C and dies of it) — fails with {@link IutException.Kind#STOPPED} and is counted
 * ({@link #cuts()}), so that the run reports that step as not run instead of blaming the implementation.
 * Thread-safe.
 */
public final class StopSignal {
    /** The reason the command line gives when Ctrl-C or a kill ends a run. */
    public static final String INTERRUPTED = "interrupted (SIGINT, SIGTERM or SIGHUP)";

    private String reason;
    /** Signals that stop when this one stops (a probe's own budget inside a certification run). */
    private final List<StopSignal> children = new ArrayList<>();
    /** The thread inside a guarded call, if any: the one a stop interrupts. */
    private Thread waiting;
    private int cuts;
    private final List<ImplementationUnderTest> open = new ArrayList<>();

    /**
     * Stops the run for {@code why} (a phrase: "interrupted (SIGINT, SIGTERM or SIGHUP)"); only the first stop counts.
     *
     * @return true when this call stopped the run, false when it had stopped already
     */
    public synchronized boolean stop(String why) {
        if (reason != null) {
            return false;
        }
        reason = why;
        if (waiting != null) {
            waiting.interrupt();
        }
        children.forEach(c -> c.stop(why));
        return true;
    }

    /** A signal of its own (it can stop alone, for a budget of its own) that also stops when this one stops. */
    public synchronized StopSignal child() {
        StopSignal c = new StopSignal();
        if (reason != null) {
            c.stop(reason);
        } else {
            children.add(c);
        }
        return c;
    }

    /** The reason of a stop by a budget: {@code the run budget of 30m ran out}. */
    public static String budgetRanOut(String what, Duration budget) {
        long ms = budget.toMillis();
        String text = ms % 3_600_000 == 0 ? ms / 3_600_000 + "h" : ms % 60_000 == 0 ? ms / 60_000 + "m"
                : ms % 1000 == 0 ? ms / 1000 + "s" : ms + "ms";
        return "the " + what + " budget of " + text + " ran out";
    }

    /** Cancels a timer of {@link #stopAfter}. */
    public interface Timing extends AutoCloseable {
        @Override
        void close();
    }

    public synchronized boolean stopped() {
        return reason != null;
    }

    /** Why the run stopped, or null while it runs. */
    public synchronized String reason() {
        return reason;
    }

    /** How many guarded calls a stop has cut short so far. */
    public synchronized int cuts() {
        return cuts;
    }

    /**
     * Stops the run {@code after} from now with the reason {@code why}, on a daemon timer; closing the returned
     * handle cancels the timer (call it when the run ends).
     */
    public Timing stopAfter(Duration after, String why) {
        Timer timer = new Timer("fclcert-budget", true);
        timer.schedule(new TimerTask() {
            @Override
            public void run() {
                stop(why);
            }
        }, Math.max(0, after.toMillis()));
        return timer::cancel;
    }

    /**
     * {@code iut}, each of whose calls ends at once when the run stops ({@link IutException.Kind#STOPPED});
     * {@link #closeAll()} closes it from another thread if the run does not end on its own.
     */
    public ImplementationUnderTest guard(ImplementationUnderTest iut) {
        synchronized (this) {
            open.add(iut);
        }
        return new Guarded(iut);
    }

    /**
     * Closes every guarded implementation not closed yet (killing a process IUT and what it started): the last
     * resort of a shutdown hook when the run did not end within its grace. The run's thread may still be inside
     * one of them; what it does after this is no longer recorded by a careful caller.
     */
    public void closeAll() {
        List<ImplementationUnderTest> left;
        synchronized (this) {
            left = List.copyOf(open);
            open.clear();
        }
        left.forEach(ImplementationUnderTest::close);
    }

    private synchronized void enter(String op) throws IutException {
        if (reason != null) {
            cuts++;
            throw stoppedDuring(op);
        }
        waiting = Thread.currentThread();
    }

    /** Ends a call; true when the run stopped during it (the interrupt it caused is cleared). */
    private synchronized boolean leave() {
        waiting = null;
        if (reason == null) {
            return false;
        }
        Thread.interrupted();
        cuts++;
        return true;
    }

    private IutException stoppedDuring(String op) {
        return new IutException(IutException.Kind.STOPPED, "the run was stopped (" + reason + ") during '" + op + "'");
    }

    private synchronized void closed(ImplementationUnderTest iut) {
        open.remove(iut);
    }

    @FunctionalInterface
    private interface Call<T> {
        T run() throws IutException;
    }

    /** The implementation with each call entered and left on the signal. */
    private final class Guarded extends ForwardingIut {
        Guarded(ImplementationUnderTest delegate) {
            super(delegate);
        }

        private <T> T call(String op, Call<T> call) throws IutException {
            enter(op);
            T value;
            try {
                value = call.run();
            } catch (IutException | RuntimeException | Error e) {
                if (leave()) {
                    throw stoppedDuring(op);
                }
                throw e;
            }
            if (leave()) {
                throw stoppedDuring(op);
            }
            return value;
        }

        @Override
        public IutInfo hello() throws IutException {
            return call("hello", delegate()::hello);
        }

        @Override
        public LoadOutcome load(String fcl) throws IutException {
            return call("load", () -> delegate().load(fcl));
        }

        @Override
        public LoadOutcome loadWritten(String text, Dialect layout) throws IutException {
            return call("load", () -> delegate().loadWritten(text, layout));
        }

        @Override
        public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
            return call("eval", () -> delegate().eval(block, inputs));
        }

        @Override
        public void reset() throws IutException {
            call("reset", () -> {
                delegate().reset();
                return null;
            });
        }

        @Override
        public Optional<String> export() throws IutException {
            return call("export", delegate()::export);
        }

        @Override
        public void close() {
            closed(delegate());
            delegate().close();
        }
    }
}
