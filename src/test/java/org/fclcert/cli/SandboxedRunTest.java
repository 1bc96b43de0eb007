package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.report.JsonReport;
import org.fclcert.report.Report;
import org.fclcert.sandbox.Bubblewrap;
import org.fclcert.sandbox.Isolation;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fclcert certify} under the default sandbox against an implementation that attacks the host
 * ({@code src/test/resources/iut/hostile.py}: {@code escape}, {@code burst}, {@code write-gb}). Network isolation
 * is tested only against a listener this test opens on 127.0.0.1; nothing is sent anywhere else.
 */
class SandboxedRunTest {
    private static final String CORPUS = "src/test/resources/corpus-process";
    private static final String HOSTILE = "process:python3 src/test/resources/iut/hostile.py ";

    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private PrintStream oldOut;
    private PrintStream oldErr;

    @BeforeEach
    void capture() {
        Bubblewrap.assumeWorking();
        oldOut = System.out;
        oldErr = System.err;
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    @AfterEach
    void restore() {
        if (oldOut != null) {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
    }

    private Report certify(Path outDir, String iut, String... more) throws Exception {
        List<String> args = new ArrayList<>(List.of("certify", "--iut", iut, "--corpus", CORPUS,
                "--out", outDir.toString(), "--no-probe", "--timeout", "10s", "--no-fresh-evidence"));
        args.addAll(List.of(more));
        int exit = Main.run(args.toArray(String[]::new));
        assertEquals(0, exit, () -> "exit " + exit + "; stderr: " + err);
        return JsonReport.read(outDir.resolve("report.json"));
    }

    /** What the implementation said it saw, from its version string ({@code key=value;…}). */
    private static Map<String, String> seen(Report r) {
        Map<String, String> seen = new LinkedHashMap<>();
        for (String kv : r.iut().version().split(";")) {
            int eq = kv.indexOf('=');
            seen.put(kv.substring(0, eq), kv.substring(eq + 1));
        }
        return seen;
    }

    /** Host processes whose command line holds {@code marker}. */
    private static List<Long> processesWith(String marker) {
        try (Stream<Path> procs = Files.list(Path.of("/proc"))) {
            return procs.filter(p -> p.getFileName().toString().matches("\\d+")).filter(p -> {
                try {
                    return new String(Files.readAllBytes(p.resolve("cmdline")), StandardCharsets.UTF_8)
                            .contains(marker);
                } catch (IOException e) {
                    return false;
                }
            }).map(p -> Long.parseLong(p.getFileName().toString())).toList();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Accepts connections on 127.0.0.1 (an ephemeral port) and counts them, until closed. */
    private static final class Listener implements AutoCloseable {
        final ServerSocket socket;
        final AtomicInteger accepted = new AtomicInteger();
        final Thread thread;

        Listener() throws IOException {
            socket = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
            socket.setSoTimeout(200);
            thread = new Thread(() -> {
                while (!socket.isClosed()) {
                    try (Socket s = socket.accept()) {
                        accepted.incrementAndGet();
                    } catch (SocketTimeoutException e) {
                        // poll again
                    } catch (IOException e) {
                        return;
                    }
                }
            });
            thread.setDaemon(true);
            thread.start();
        }

        int port() {
            return socket.getLocalPort();
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }

    private String escape(Path checkout, Path outDir, Path realHome, int port, String marker) {
        return HOSTILE + "escape " + String.join(" ", checkout.toString(), outDir.toString(),
                checkout.resolve(CORPUS).toString(), realHome.toString(), Integer.toString(port), marker);
    }

    @Test
    void theImplementationCannotReachTheHostAndLeavesNothingBehind() throws Exception {
        Path checkout = Path.of("").toAbsolutePath();
        Path realHome = Path.of(System.getProperty("user.home"));
        Path planted = checkout.resolve("written-by-iut.txt");
        String marker = "fclcert-orphan-" + UUID.randomUUID();
        Files.deleteIfExists(planted);
        Report r;
        try (Listener listener = new Listener()) {
            r = certify(dir, escape(checkout, dir, realHome, listener.port(), marker));
            Thread.sleep(300);
            assertEquals(0, listener.accepted.get(), "no connection reached the test's listener");
        }
        byte[] reportMd = Files.readAllBytes(dir.resolve("report.md"));
        Map<String, String> seen = seen(r);
        assertEquals(Isolation.Kind.SANDBOX, r.iut().isolation().kind());
        assertEquals(CaseStatus.PASSED, r.cases().stream().filter(c -> c.id().equals("B-FB-001")).findFirst()
                .map(CaseResult::status).orElseThrow(), "the implementation still answered correctly");
        assertFalse(Files.exists(planted), "nothing written into the checkout");
        assertFalse(Files.exists(dir.resolve("written-by-iut.txt")), "nothing written into the output directory");
        assertEquals("FileNotFoundError", seen.get("out"), "the output directory is not there: " + seen);
        assertEquals("", seen.get("home"), "an empty home: " + seen);
        assertEquals("absent", seen.get("corpus"), seen.toString());
        assertEquals("absent", seen.get("m2"), "no ~/.m2: " + seen);
        assertFalse(seen.get("realhome").contains(".m2") || seen.get("realhome").contains(".ssh"), seen.toString());
        assertEquals("ConnectionRefusedError", seen.get("connect"), "only a loopback of its own: " + seen);
        assertTrue(Files.readString(dir.resolve("report.md")).contains("Isolation: bubblewrap "));

        Thread.sleep(4000);   // the forger would have written by now (it waits 3 s)
        assertEquals(List.of(), processesWith(marker), "no process the implementation started survives the run");
        assertArrayEquals(reportMd, Files.readAllBytes(dir.resolve("report.md")), "report.md unchanged after the run");
    }

    /** The same attack without the sandbox succeeds, so the test above can fail (run in a scratch directory). */
    @Test
    void withoutTheSandboxTheSameAttackSucceeds(@TempDir Path scratch) throws Exception {
        Path outDir = scratch.resolve("out");
        String marker = "fclcert-orphan-" + UUID.randomUUID();
        Report r;
        try (Listener listener = new Listener()) {
            r = certify(outDir, escape(scratch, outDir, scratch, listener.port(), marker), "--no-sandbox");
            Thread.sleep(300);
            assertEquals(1, listener.accepted.get(), "the unsandboxed implementation reached the listener");
        }
        assertEquals(Isolation.Kind.DISABLED, r.iut().isolation().kind());
        assertEquals("ok", seen(r).get("connect"));
        assertTrue(Files.exists(scratch.resolve("written-by-iut.txt")));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("warning: the implementation was not sandboxed"));
        assertTrue(Files.readString(outDir.resolve("report.md")).contains("Isolation: NOT SANDBOXED: none: --no-sandbox"));
        Thread.sleep(4000);
        assertTrue(Files.readString(outDir.resolve("report.md")).endsWith("FORGED\n"), "the forgery the sandbox stops");
        for (long pid : processesWith(marker)) {
            ProcessHandle.of(pid).ifPresent(ProcessHandle::destroyForcibly);
        }
    }

    @Test
    void aBurstOfProcessesIsStoppedByTheProcessLimitAsTheImplementationsFailure() throws Exception {
        Report r = certify(dir, HOSTILE + "burst 300", "--case", "B-FB-001");
        CaseResult c = r.cases().get(0);
        assertEquals(CaseStatus.ERRORED, c.status(), c.message());
        assertTrue(c.message().contains("the IUT exited while answering 'eval'"), c.message());
        assertTrue(Files.readString(dir.resolve("report.md")).contains("Resource temporarily unavailable"),
                "its stderr shows the refused fork");
        assertEquals(List.of(), processesWith("hostile.py\0burst"), "none of the burst survives the run");
    }

    @Test
    void aGigabyteWriteIsStoppedByTheFileSizeLimitAsTheImplementationsFailure() throws Exception {
        Report r = certify(dir, HOSTILE + "write-gb", "--case", "B-FB-001");
        CaseResult c = r.cases().get(0);
        assertEquals(CaseStatus.ERRORED, c.status(), c.message());
        // Python ignores SIGXFSZ, so the write fails with EFBIG instead of the signal killing it
        assertTrue(c.message().contains("the IUT exited while answering 'eval'"), c.message());
        assertTrue(Files.readString(dir.resolve("report.md")).contains("File too large"), "its stderr shows EFBIG");
        try (Stream<Path> files = Files.walk(Path.of("").toAbsolutePath(), 2)) {
            assertTrue(files.noneMatch(p -> p.getFileName().toString().equals("big.bin")), "no big.bin on the host");
        }
    }
}
