package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.iut.spi.FclImplementation;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class JavaIutTest {
    private static final IutOptions FAST = IutOptions.defaults().withTimeout(Duration.ofMillis(1000));
    private static final String PROGRAM = String.join("\n",
            "FUNCTION_BLOCK adder",
            "VAR_INPUT a, b : REAL; END_VAR",
            "VAR_OUTPUT (* the sum *) y : REAL; count : REAL := 0.0; END_VAR",
            "END_FUNCTION_BLOCK",
            "FUNCTION_BLOCK other",
            "VAR_OUTPUT z : REAL; END_VAR",
            "END_FUNCTION_BLOCK");

    private static ImplementationUnderTest open(IutOptions options) throws IutException {
        return Iuts.open("java:" + SummingFcl.class.getName(), options);
    }

    @Test
    void helloLoadEvalResetAndExportGoThroughTheSpi() throws IutException {
        try (ImplementationUnderTest iut = open(FAST)) {
            IutInfo info = iut.hello();
            assertEquals(new IutInfo("summing", "0.1", "java:" + SummingFcl.class.getName(),
                    List.of("B-FB", "B-COGS"), Map.of()), info);
            assertEquals(new LoadOutcome.Loaded(List.of("adder", "other")), iut.load(PROGRAM));
            // y = a + b = 1.5 + 2; count is the instance's state
            assertEquals(Map.of("y", 3.5, "count", 1.0), iut.eval(null, Map.of("a", 1.5, "b", 2.0)));
            assertEquals(Map.of("y", 3.5, "count", 2.0), iut.eval("ADDER", Map.of("a", 1.5, "b", 2.0)));
            iut.reset();
            assertEquals(1.0, iut.eval(null, Map.of("a", 0.0, "b", 0.0)).get("count"));
            assertEquals(Optional.of(PROGRAM), iut.export());
        }
    }

    @Test
    void theOutputsAskedForAreThoseTheBlockDeclares() throws IutException {
        try (ImplementationUnderTest iut = open(FAST)) {
            iut.load(PROGRAM);
            // block 'other' declares only z, which this vendor does not know: its refusal is an eval error
            IutException e = assertThrows(IutException.class, () -> iut.eval("other", Map.of()));
            assertEquals(Kind.EVAL_ERROR, e.kind());
            assertTrue(e.getMessage().contains("no output z"), e.getMessage());
            assertEquals(Kind.EVAL_ERROR, assertThrows(IutException.class, () -> iut.eval("nope", Map.of())).kind());
        }
    }

    @Test
    void aRejectionKeepsItsMessageAndLine() throws IutException {
        try (ImplementationUnderTest iut = open(FAST)) {
            LoadOutcome outcome = iut.load("FUNCTION_BLOCK f\n\nREJECT\nEND_FUNCTION_BLOCK\n");
            assertEquals(new LoadOutcome.Rejected("REJECT is not allowed", OptionalInt.of(3)), outcome);
            assertEquals(Kind.EVAL_ERROR, assertThrows(IutException.class, () -> iut.eval(null, Map.of())).kind());
        }
    }

    @Test
    void vendorExceptionsAreEvalErrorsInEvaluationAndCrashesElsewhere() throws IutException {
        try (ImplementationUnderTest iut = open(FAST)) {
            IutException onLoad = assertThrows(IutException.class, () -> iut.load("THROW_ON_LOAD"));
            assertEquals(Kind.CRASH, onLoad.kind());
            assertTrue(onLoad.getMessage().contains("cannot cope"), onLoad.getMessage());
            iut.load(PROGRAM);
            IutException boom = assertThrows(IutException.class, () -> iut.eval(null, Map.of("boom", 1.0)));
            assertEquals(Kind.EVAL_ERROR, boom.kind());
            assertTrue(boom.getMessage().contains("boom input"), boom.getMessage());
            iut.reset(); // the vendor keeps set inputs: forget 'boom'
            IutException die = assertThrows(IutException.class, () -> iut.eval(null, Map.of("die", 1.0)));
            assertEquals(Kind.CRASH, die.kind());
            assertTrue(die.getMessage().contains("StackOverflowError"), die.getMessage());
        }
    }

    @Test
    void aHungCallTimesOutAndTheNextCallGetsAFreshInstance() throws IutException {
        try (ImplementationUnderTest iut = open(FAST)) {
            iut.load(PROGRAM);
            iut.eval(null, Map.of("a", 1.0));
            long start = System.nanoTime();
            IutException hang = assertThrows(IutException.class, () -> iut.eval(null, Map.of("hang", 1.0)));
            long millis = (System.nanoTime() - start) / 1_000_000;
            assertEquals(Kind.TIMEOUT, hang.kind());
            assertTrue(millis >= 1000 && millis < 4000, "cut after " + millis + " ms");
            // a new instance: its evaluation count starts again
            assertEquals(1.0, iut.eval(null, Map.of("a", 1.0)).get("count"));
        }
    }

    @Test
    void hungCallsBeyondTheRestartBudgetGiveUp() throws IutException {
        // in process, a hung call is abandoned on its thread (in a child JVM the JVM is killed: JavaChildJvmTest)
        IutOptions quick = IutOptions.defaults().withTimeout(Duration.ofMillis(300)).withRestartBudget(1)
                .withInProcess(true);
        try (ImplementationUnderTest iut = open(quick)) {
            iut.load(PROGRAM);
            assertEquals(Kind.TIMEOUT, assertThrows(IutException.class, () -> iut.eval(null, Map.of("hang", 1.0))).kind());
            assertEquals(Kind.TIMEOUT, assertThrows(IutException.class, () -> iut.eval(null, Map.of("hang", 1.0))).kind());
            IutException gaveUp = assertThrows(IutException.class, () -> iut.eval(null, Map.of("a", 1.0)));
            assertEquals(Kind.GAVE_UP, gaveUp.kind());
            assertTrue(gaveUp.getMessage().contains("did not return"), gaveUp.getMessage());
        }
    }

    @Test
    void aMissingOrUnsuitableClassIsAnInfraError() {
        for (String spec : List.of("java:com.example.NoSuchFcl", "java:java.lang.String", "java:",
                "java:" + NoDefaultConstructor.class.getName())) {
            IutException e = assertThrows(IutException.class, () -> Iuts.open(spec, FAST), spec);
            assertEquals(Kind.INFRA, e.kind(), spec);
        }
    }

    /** Implements the SPI, but fclcert cannot construct it. */
    public static final class NoDefaultConstructor extends Delegating {
        public NoDefaultConstructor(String unused) {}
    }

    /** A base with the SPI methods, so the class above only differs in its constructor. */
    public abstract static class Delegating implements FclImplementation {
        @Override
        public String name() {
            return "x";
        }

        @Override
        public String version() {
            return "x";
        }

        @Override
        public org.fclcert.iut.spi.FclLoadResult load(String fcl) {
            return org.fclcert.iut.spi.FclLoadResult.rejected("never");
        }
    }

    @Test
    void aVendorClassIsLoadedFromTheGivenClasspath(@TempDir Path dir) throws IOException, IutException {
        Path source = dir.resolve("src/vendor/TinyFcl.java");
        Files.createDirectories(source.getParent());
        Files.writeString(source, String.join("\n",
                "package vendor;",
                "import org.fclcert.iut.spi.*;",
                "public class TinyFcl implements FclImplementation {",
                "  public String name() { return \"tiny\"; }",
                "  public String version() { return \"9\"; }",
                "  public FclLoadResult load(String fcl) { return FclLoadResult.rejected(\"tiny rejects all\", 2); }",
                "}"));
        Path classes = dir.resolve("classes");
        String spiLocation = Path.of(FclImplementation.class.getProtectionDomain().getCodeSource().getLocation().getPath())
                .toString();
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        int status = javac.run(null, null, null, "-d", classes.toString(), "-cp", spiLocation, source.toString());
        assertEquals(0, status);

        IutException notOnDefault = assertThrows(IutException.class, () -> Iuts.open("java:vendor.TinyFcl", FAST));
        assertEquals(Kind.INFRA, notOnDefault.kind());
        try (ImplementationUnderTest iut = Iuts.open("java:vendor.TinyFcl", FAST.withClasspath(List.of(classes)))) {
            assertEquals("tiny", iut.hello().name());
            assertEquals(new LoadOutcome.Rejected("tiny rejects all", OptionalInt.of(2)), iut.load("x\ny\n"));
        }
    }
}
