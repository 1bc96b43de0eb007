package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.fclcert.iut.IutException.Kind;
import org.junit.jupiter.api.Test;

/** {@link StopSignal}: a guarded call ends at once when the run stops, and is counted as cut, never as the IUT's fault. */
class StopSignalTest {
    private static final String PROGRAM = "FUNCTION_BLOCK f\nEND_FUNCTION_BLOCK\n";

    @Test
    void aCallUnderWayWhenTheRunStopsEndsAtOnceAsStopped() throws Exception {
        StopSignal stop = new StopSignal();
        // hang_on_load.py never answers load: without the stop the call would wait for its 60 s timeout
        IutOptions patient = IutOptions.defaults().withTimeout(Duration.ofSeconds(60));
        try (ImplementationUnderTest iut = stop.guard(Iuts.open(ProcessIutTest.fake("hang_on_load.py"), patient))) {
            iut.hello();
            CompletableFuture<IutException> load = CompletableFuture.supplyAsync(() ->
                    assertThrows(IutException.class, () -> iut.load(PROGRAM)));
            Thread.sleep(500);
            assertTrue(stop.stop("interrupted (test)"));
            IutException e = load.get(10, TimeUnit.SECONDS);
            assertEquals(Kind.STOPPED, e.kind(), e.getMessage());
            assertEquals("the run was stopped (interrupted (test)) during 'load'", e.getMessage());
            assertEquals(1, stop.cuts());
            // later calls are refused without reaching the implementation, and counted
            IutException later = assertThrows(IutException.class, () -> iut.eval(null, Map.of("a", 1.0)));
            assertEquals(Kind.STOPPED, later.kind());
            assertEquals(2, stop.cuts());
            assertFalse(Thread.currentThread().isInterrupted());
        }
    }

    @Test
    void onlyTheFirstStopCountsAndAChildStopsWithItsParent() {
        StopSignal parent = new StopSignal();
        StopSignal child = parent.child();
        StopSignal own = parent.child();
        assertTrue(own.stop("the probe budget of 3m ran out"));
        assertFalse(parent.stopped(), "a child's own stop leaves the parent running");
        assertTrue(parent.stop("interrupted"));
        assertFalse(parent.stop("again"));
        assertEquals("interrupted", parent.reason());
        assertEquals("interrupted", child.reason());
        assertEquals("the probe budget of 3m ran out", own.reason(), "its first stop counts");
        assertEquals("interrupted", parent.child().reason(), "a child of a stopped signal is stopped");
    }

    @Test
    void aBudgetStopsAfterItsTimeAndCanBeCancelled() throws Exception {
        StopSignal stop = new StopSignal();
        try (StopSignal.Timing t = stop.stopAfter(Duration.ofMillis(50), StopSignal.budgetRanOut("run", Duration.ofMillis(50)))) {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (!stop.stopped() && System.nanoTime() < end) {
                Thread.sleep(10);
            }
        }
        assertEquals("the run budget of 50ms ran out", stop.reason());
        StopSignal cancelled = new StopSignal();
        cancelled.stopAfter(Duration.ofMillis(50), "never").close();
        Thread.sleep(200);
        assertFalse(cancelled.stopped());
        assertEquals("the probe budget of 3m ran out", StopSignal.budgetRanOut("probe", Duration.ofMinutes(3)));
        assertEquals("the run budget of 2h ran out", StopSignal.budgetRanOut("run", Duration.ofHours(2)));
        assertEquals("the run budget of 90s ran out", StopSignal.budgetRanOut("run", Duration.ofSeconds(90)));
    }
}
