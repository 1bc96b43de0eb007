package org.fclcert.orchestration;

import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.ResultSink;
import org.fclcert.harness.RunHeader;
import org.fclcert.iut.StopSignal;
import org.fclcert.probe.DataCheckEntry;

/**
 * Stopping a certification from outside its thread: the command line's shutdown hook on Ctrl-C or SIGTERM.
 * {@link #stop} asks the run to stop and waits a bounded time for it to end on its own; the run's thread then
 * records the case under way and every later one as not run, writes the reports and closes the implementation,
 * so that {@code results.jsonl} and the reports agree and hold every case once. Only when the run does not end
 * within the grace (an in-process implementation deaf to interruption) does the caller's thread seal the outputs
 * — nothing more is written to them, so nothing the run's thread does after the stop can reach them — and close
 * the implementation itself.
 */
public final class RunControl {
    final StopSignal signal = new StopSignal();
    private final CountDownLatch ended = new CountDownLatch(1);
    private final Object outputs = new Object();
    private boolean frozen;

    /**
     * Stops the run for {@code why} and waits at most {@code grace} for it to end.
     *
     * @return true when the run ended within the grace (results and reports written, the implementation closed);
     *         false when the outputs were sealed instead: {@code results.jsonl} then holds every case that
     *         finished, and {@code fclcert report --from} makes the reports from it
     */
    public boolean stop(String why, Duration grace) {
        signal.stop(why);
        try {
            if (ended.await(grace.toMillis(), TimeUnit.MILLISECONDS)) {
                return true;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        synchronized (outputs) {
            // waits for a write under way to finish, so that no file is left half written
            frozen = true;
        }
        signal.closeAll();
        return false;
    }

    /** Whether the run has been stopped, and why (null while it runs or when it was not). */
    public String stopped() {
        return signal.reason();
    }

    /** The run has ended: its outputs are written and the implementation is closed. */
    void ended() {
        ended.countDown();
    }

    @FunctionalInterface
    interface Write {
        void run() throws IOException;
    }

    /** Runs one write of the run's outputs, unless they are sealed; false when they are. */
    boolean write(Write write) throws IOException {
        synchronized (outputs) {
            if (frozen) {
                return false;
            }
            write.run();
            return true;
        }
    }

    /** {@code sink}, each of whose writes is one {@link #write}. */
    ResultSink guard(ResultSink sink) {
        return new ResultSink() {
            @Override
            public void header(RunHeader header) throws IOException {
                write(() -> sink.header(header));
            }

            @Override
            public void accept(CaseResult result) throws IOException {
                write(() -> sink.accept(result));
            }

            @Override
            public void dataCheckList(List<DataCheckEntry> entries) throws IOException {
                write(() -> sink.dataCheckList(entries));
            }
        };
    }
}
