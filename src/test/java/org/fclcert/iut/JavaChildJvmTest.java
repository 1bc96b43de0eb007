package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.fclcert.cli.Main;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.report.JsonReport;
import org.fclcert.sandbox.Bubblewrap;
import org.fclcert.sandbox.Isolation;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 27: a {@code java:} implementation runs in a child JVM inside the sandbox unless {@code --in-process} is
 * given. The hostile {@link SpyFcl} writes into the working directory (the checkout: tests run at its root) and
 * lists the user's home directory; in the sandbox neither reaches the host, in process both do. A vendor calling
 * {@code System.exit} in the child costs only the request under way.
 */
class JavaChildJvmTest {
    private static final IutOptions OPTIONS = IutOptions.defaults().withTimeout(Duration.ofSeconds(5));
    private static final Path MARK = Path.of(SpyFcl.MARK).toAbsolutePath();
    private static final Path HOME = Path.of(System.getProperty("user.home")).toAbsolutePath();

    private static String program() {
        return String.join("\n",
                "FUNCTION_BLOCK spy",
                "(* spy-read: " + HOME + " *)",
                "VAR_INPUT a, b, exit : REAL; END_VAR",
                "VAR_OUTPUT sum, seen : REAL; END_VAR",
                "END_FUNCTION_BLOCK");
    }

    private static ImplementationUnderTest spy(IutOptions options) throws IutException {
        return Iuts.open("java:" + SpyFcl.class.getName(), options);
    }

    private static long homeEntries() throws IOException {
        try (Stream<Path> entries = Files.list(HOME)) {
            return entries.count();
        }
    }

    @AfterEach
    void removeMark() throws IOException {
        Files.deleteIfExists(MARK);
    }

    @Test
    void inTheSandboxItNeitherWritesIntoTheCheckoutNorSeesTheHome() throws Exception {
        Bubblewrap.assumeWorking();
        assertTrue(homeEntries() > 0, "the host's home has entries to hide: " + HOME);
        try (ImplementationUnderTest iut = spy(OPTIONS)) {
            assertEquals(new LoadOutcome.Loaded(List.of("spy")), iut.load(program()));
            Map<String, Double> out = iut.eval(null, Map.of("a", 1.0, "b", 2.0));
            assertEquals(3.0, out.get("sum"));
            // the home is an empty one of the sandbox's, but for the way to the class path's jars bound in it
            long throughHome = ChildJvm.ownClasspath().stream().map(Path::of).filter(p -> p.startsWith(HOME))
                    .map(p -> HOME.relativize(p).getName(0)).distinct().count();
            assertTrue(throughHome < homeEntries(), "the test needs a home entry fclcert's class path does not use");
            assertEquals((double) throughHome, out.get("seen"), "entries of the home it sees");
            Isolation isolation = iut.isolation();
            assertEquals(Isolation.Kind.SANDBOX, isolation.kind());
            assertTrue(isolation.description().startsWith("a child JVM (java: without --in-process); bubblewrap "),
                    isolation.description());
        }
        assertFalse(Files.exists(MARK), "the file it wrote stayed in the sandbox");
    }

    @Test
    void aMissingClassPathEntryIsPassedOverAsTheJvmDoes(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        // a build's class path names target/test-classes whether or not it exists (the Maven plugin's ITs do)
        Path missing = dir.resolve("target/test-classes");
        try (ImplementationUnderTest iut = spy(OPTIONS.withClasspath(List.of(missing)))) {
            iut.load(program());
            assertEquals(3.0, iut.eval(null, Map.of("a", 1.0, "b", 2.0)).get("sum"));
        }
        IutException refused = org.junit.jupiter.api.Assertions.assertThrows(IutException.class,
                () -> Iuts.open("java:com.example.NoSuchFcl", OPTIONS.withClasspath(List.of(missing))));
        assertTrue(refused.getMessage().contains("com.example.NoSuchFcl"), refused.getMessage());
    }

    @Test
    void inProcessItDoesBothAndTheIsolationSaysSo() throws Exception {
        try (ImplementationUnderTest iut = spy(OPTIONS.withInProcess(true))) {
            iut.load(program());
            Map<String, Double> out = iut.eval(null, Map.of("a", 1.0, "b", 2.0));
            assertEquals(3.0, out.get("sum"));
            assertEquals((double) homeEntries(), out.get("seen"), "it lists the user's real home");
            Isolation isolation = iut.isolation();
            assertEquals(Isolation.Kind.IN_PROCESS, isolation.kind());
            assertTrue(isolation.description().contains("--in-process"), isolation.description());
        }
        assertTrue(Files.exists(MARK), "in process its file lands in the checkout");
    }

    @Test
    void systemExitMidRunCostsOnlyThatRequest() throws Exception {
        try (ImplementationUnderTest iut = spy(OPTIONS)) {
            iut.load(program());
            assertEquals(3.0, iut.eval(null, Map.of("a", 1.0, "b", 2.0)).get("sum"));
            IutException exit = assertThrows(IutException.class, () -> iut.eval(null, Map.of("exit", 1.0)));
            assertEquals(Kind.CRASH, exit.kind());
            assertTrue(exit.getMessage().contains("exited while answering 'eval'") && exit.getMessage().contains("3"),
                    exit.getMessage());
            // the next request starts a fresh JVM, which is given the program again
            assertEquals(7.0, iut.eval(null, Map.of("a", 3.0, "b", 4.0)).get("sum"));
            assertEquals(new IutHealth(1, 1), iut.health());
        }
    }

    @Test
    void aConstructorThatThrowsIsNamedAtHello() throws Exception {
        try (ImplementationUnderTest iut = Iuts.open("java:" + Unconstructible.class.getName(), OPTIONS)) {
            IutException e = assertThrows(IutException.class, iut::hello);
            assertTrue(e.getMessage().contains("the constructor of " + Unconstructible.class.getName() + " threw"),
                    e.getMessage());
        }
    }

    /**
     * The certificate says how the class ran: report.md, report.html and junit.xml name the child JVM and its
     * sandbox, or --in-process and no isolation; the file it writes reaches the checkout only in process.
     */
    @Test
    void theCertificateSaysWhetherItRanInAChildJvmOrInProcess(@TempDir Path dir) throws Exception {
        Bubblewrap.assumeWorking();
        String[] run = {"certify", "--iut", "java:" + SpyFcl.class.getName(), "--corpus",
                "src/test/resources/corpus-process", "--no-probe", "--no-fresh-evidence", "--out"};
        StringWriter err = new StringWriter();
        int exit = Main.run(new PrintWriter(new StringWriter()), new PrintWriter(err), concat(run, dir.resolve("child")));
        assertEquals(0, exit, err.toString());
        assertFalse(Files.exists(MARK), "the file it wrote stayed in the sandbox");
        String isolation = "a child JVM (java: without --in-process); bubblewrap ";
        assertTrue(Files.readString(dir.resolve("child/report.md")).contains("- Isolation: " + isolation),
                "report.md");
        assertTrue(Files.readString(dir.resolve("child/report.html")).contains("Isolation: " + isolation), "report.html");
        assertTrue(Files.readString(dir.resolve("child/junit.xml")).contains("name=\"iut.isolation\" value=\""
                + isolation), "junit.xml");
        assertEquals(Isolation.Kind.SANDBOX, JsonReport.read(dir.resolve("child/report.json")).iut().isolation().kind());

        exit = Main.run(new PrintWriter(new StringWriter()), new PrintWriter(err),
                concat(concat(run, dir.resolve("in-process")), "--in-process"));
        assertEquals(0, exit, err.toString());
        assertTrue(Files.exists(MARK), "in process, the file it wrote is in the checkout");
        String none = "NOT SANDBOXED: none: --in-process: the java: implementation was called inside fclcert's own JVM";
        assertTrue(Files.readString(dir.resolve("in-process/report.md")).contains("- Isolation: " + none), "report.md");
        assertTrue(Files.readString(dir.resolve("in-process/junit.xml")).contains(none), "junit.xml");
        assertEquals(Isolation.Kind.IN_PROCESS,
                JsonReport.read(dir.resolve("in-process/report.json")).iut().isolation().kind());
    }

    private static String[] concat(String[] run, Path out) {
        return concat(run, out.toString());
    }

    private static String[] concat(String[] run, String option) {
        String[] all = java.util.Arrays.copyOf(run, run.length + 1);
        all[run.length] = option;
        return all;
    }

    /** Implements the SPI; its constructor throws (only in the child JVM, where it is constructed). */
    public static final class Unconstructible extends JavaIutTest.Delegating {
        public Unconstructible() {
            throw new IllegalStateException("no licence");
        }
    }
}
