package org.fclcert.orchestration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ResultsFile;
import org.fclcert.harness.RunListener;
import org.fclcert.harness.Runner;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@link RunControl}: a stopped run ends on its own; one that does not is sealed and its implementation closed. */
class RunControlTest {
    private static final Path MINI = Path.of("src/test/resources/corpus-mini");

    @TempDir
    Path dir;

    @Test
    void aRunStoppedFromAnotherThreadRecordsTheRestAsNotRunAndWritesItsReports() throws Exception {
        RunControl control = new RunControl();
        CountDownLatch firstCase = new CountDownLatch(1);
        RunListener listener = new RunListener() {
            @Override
            public void caseFinished(CaseResult result, int index, int total) {
                if (index == 0) {
                    firstCase.countDown();
                    // stop from another thread, as a shutdown hook does, and wait for the run to take note
                    Thread hook = new Thread(() -> assertTrue(control.stop("interrupted (test)", Duration.ofSeconds(30))));
                    hook.start();
                    while (!"interrupted (test)".equals(control.stopped())) {
                        Thread.onSpinWait();
                    }
                }
            }
        };
        Certification.Request request = Certification.Request.builder("reference", Corpus.load(MINI)).outDir(dir)
                .build();
        Certification.Outcome outcome = Certification.run(request, listener, Certification.Hooks.NONE, control);
        assertEquals("interrupted (test)", outcome.stopped());
        Report r = outcome.report();
        assertEquals(13, r.summary().cases());
        assertEquals(1, r.summary().passed());
        assertEquals(12, r.summary().skipped());
        assertFalse(r.run().complete());
        ResultsFile results = ResultsFile.read(dir.resolve("results.jsonl"));
        assertEquals(13, results.results().size(), "every case once in results.jsonl");
        for (CaseResult c : results.results().subList(1, 13)) {
            assertEquals(CaseStatus.SKIPPED, c.status());
            assertEquals(Runner.STOPPED + "interrupted (test)", c.message());
        }
        assertEquals(13, JsonReport.read(dir.resolve("report.json")).cases().size());
    }

    /** An implementation that never returns from load, deaf to interruption, and says when it is closed. */
    private static final class Deaf implements ImplementationUnderTest {
        final CountDownLatch loading = new CountDownLatch(1);
        final CountDownLatch closed = new CountDownLatch(1);

        @Override
        public IutInfo hello() {
            return new IutInfo("deaf", "1", "test", List.of(), Map.of());
        }

        @Override
        public LoadOutcome load(String fcl) {
            loading.countDown();
            while (closed.getCount() > 0) {
                try {
                    closed.await();
                } catch (InterruptedException deaf) {
                    // ignored: this implementation does not stop
                }
            }
            throw new IllegalStateException("closed under the run (what a run must never record)");
        }

        @Override
        public Map<String, Double> eval(String block, Map<String, Double> inputs) {
            return Map.of();
        }

        @Override
        public void reset() {
        }

        @Override
        public Optional<String> export() {
            return Optional.empty();
        }

        @Override
        public void close() {
            closed.countDown();
        }
    }

    @Test
    void aRunDeafToTheStopIsSealedAndItsImplementationClosed() throws Exception {
        RunControl control = new RunControl();
        Deaf deaf = new Deaf();
        Path results = dir.resolve("results.jsonl");
        Thread run = new Thread(() -> {
            try (ResultsFileSink sink = new ResultsFileSink(results, control)) {
                ImplementationUnderTest iut = control.signal.guard(deaf);
                sink.line("first");
                iut.load("FUNCTION_BLOCK f END_FUNCTION_BLOCK");
            } catch (Exception e) {
                // the load fails once the implementation is closed: the run's thread may do anything now
            }
            try {
                control.write(() -> Files.writeString(dir.resolve("late"), "written after the seal"));
            } catch (java.io.IOException e) {
                throw new AssertionError(e);
            }
        });
        run.start();
        assertTrue(deaf.loading.await(10, TimeUnit.SECONDS));
        assertFalse(control.stop("interrupted (test)", Duration.ofMillis(300)), "the run did not end in the grace");
        assertTrue(deaf.closed.await(10, TimeUnit.SECONDS), "closed by the stop itself");
        run.join(10_000);
        assertEquals(List.of("first"), Files.readAllLines(results), "nothing written after the seal");
        assertFalse(Files.exists(dir.resolve("late")));
    }

    /** A file written only through {@link RunControl#write}. */
    private static final class ResultsFileSink implements AutoCloseable {
        private final Path file;
        private final RunControl control;

        ResultsFileSink(Path file, RunControl control) {
            this.file = file;
            this.control = control;
        }

        void line(String text) throws java.io.IOException {
            control.write(() -> Files.writeString(file, text + "\n", java.nio.file.StandardOpenOption.CREATE,
                    java.nio.file.StandardOpenOption.APPEND));
        }

        @Override
        public void close() throws java.io.IOException {
            line("closing line written after the seal");
        }
    }
}
