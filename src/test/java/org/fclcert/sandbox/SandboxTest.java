package org.fclcert.sandbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The launcher itself: what a sandboxed command sees and what stops it, with plain shell commands. */
class SandboxTest {
    private record Ran(int exit, String output) {
    }

    private static Ran run(Sandbox sandbox, String script) throws IOException, InterruptedException {
        Process p = sandbox.processBuilder(List.of("/bin/sh", "-c", script)).redirectErrorStream(true).start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "ended");
        return new Ran(p.exitValue(), out);
    }

    @Test
    void theEnvironmentIsClearedButForPathLocaleAndTheSandboxsOwnHome() throws Exception {
        Bubblewrap.assumeWorking();
        Ran r = run(Sandbox.of(SandboxSettings.defaults()), "env | cut -d= -f1 | sort | tr '\\n' ' '; ls -A \"$HOME\" | wc -l");
        assertEquals(0, r.exit(), r.output());
        for (String name : r.output().strip().split("\\s+")) {
            assertTrue(List.of("HOME", "TMPDIR", "PATH", "LANG", "LC_ALL", "LC_CTYPE", "TZ", "PYENV_VERSION", "PWD",
                    "SHLVL", "_", "0").contains(name), "unexpected variable " + name + " in: " + r.output());
        }
    }

    @Test
    void aFileAboveTheSizeLimitEndsTheWriterWithSigxfszAndTheMessageSaysSo() throws Exception {
        Bubblewrap.assumeWorking();
        Sandbox sandbox = Sandbox.of(SandboxSettings.defaults().withLimits(Limits.defaults().withFileSizeBytes(1 << 20)));
        Ran r = run(sandbox, "head -c 5000000 /dev/zero > big; echo never");
        // the shell reports its child's death by SIGXFSZ (25) as 128 + 25, and goes on
        assertTrue(r.output().contains("never"), r.output());
        Ran direct = run(sandbox, "exec head -c 5000000 /dev/zero > big");
        assertEquals(128 + 25, direct.exit(), direct.output());
        assertEquals(Optional.of("it was stopped by the sandbox's file size limit of 1 MiB (SIGXFSZ)"),
                sandbox.limitHit(direct.exit()));
    }

    @Test
    void theProcessLimitRefusesTheForkBeyondIt() throws Exception {
        Bubblewrap.assumeWorking();
        Sandbox sandbox = Sandbox.of(SandboxSettings.defaults().withLimits(Limits.defaults().withProcesses(20)));
        Ran r = run(sandbox, "for i in $(seq 40); do sleep 5 & done; echo started");
        assertTrue(r.output().contains("fork") || r.output().contains("Resource temporarily unavailable"), r.output());
    }

    @Test
    void theSystemIsReadOnlyAndTheHostsTmpInvisible(@TempDir Path host) throws Exception {
        Bubblewrap.assumeWorking();
        Files.writeString(host.resolve("secret"), "s");
        Ran r = run(Sandbox.of(SandboxSettings.defaults()), "touch /usr/x 2>&1; cat " + "'" + host.resolve("secret")
                + "' 2>&1; echo ok > /tmp/mine && cat /tmp/mine");
        assertTrue(r.output().contains("Read-only file system") || r.output().contains("Permission denied"), r.output());
        assertTrue(r.output().contains("No such file"), r.output());
        assertTrue(r.output().strip().endsWith("ok"), "a private /tmp of its own: " + r.output());
    }

    @Test
    void anExtraBindIsReadableButNotWritable(@TempDir Path host) throws Exception {
        Bubblewrap.assumeWorking();
        Path licence = host.resolve("licence.txt");
        Files.writeString(licence, "granted");
        Sandbox sandbox = Sandbox.of(SandboxSettings.defaults().withReadOnly(List.of(licence)));
        Ran r = run(sandbox, "cat '" + licence + "'; echo; (echo x >> '" + licence + "') 2>/dev/null || echo refused");
        assertEquals("granted\nrefused\n", r.output());
        assertEquals("granted", Files.readString(licence));
    }

    @Test
    void withoutTheSandboxTheCommandIsUnchanged() throws Exception {
        Sandbox off = Sandbox.of(SandboxSettings.none());
        assertEquals(List.of("python3", "x.py"), off.command(List.of("python3", "x.py")));
        assertEquals(Isolation.Kind.DISABLED, off.isolation().kind());
        assertFalse(off.active());
        assertEquals(Duration.ZERO.isNegative(), Sandbox.cpuTime(ProcessHandle.current()).isNegative());
    }

    @Test
    void anInterpreterUnderTheHomeDirectoryBringsItsWholeInstallation() {
        Path home = Path.of("/home/ann");
        assertEquals(Path.of("/home/ann/.pyenv"), Binds.installation(Path.of("/home/ann/.pyenv/shims/python3"),
                Optional.of(home)));
        assertEquals(Path.of("/home/ann/.sdkman/candidates/java/17"), Binds.installation(
                Path.of("/home/ann/.sdkman/candidates/java/17/bin/java"), Optional.empty()));
        assertEquals(Path.of("/opt/ffll"), Binds.installation(Path.of("/opt/ffll/bin/ffll-bridge"), Optional.of(home)));
        // not a hidden directory of the home: only the program's own directory (never the home itself)
        assertEquals(Path.of("/home/ann/tools"), Binds.installation(Path.of("/home/ann/tools/iut"), Optional.of(home)));
    }

    @Test
    void aScriptBesideTheCheckoutRootIsBoundAloneNeverTheCheckout(@TempDir Path checkout) throws Exception {
        Path script = Files.writeString(checkout.resolve("iut.py"), "");
        Path nested = Files.createDirectories(checkout.resolve("examples/iut")).resolve("basic.py");
        Files.writeString(nested, "");
        Binds b = Binds.forCommand(Path.of("/usr/bin/python3"), List.of("iut.py", "examples/iut/basic.py"), checkout,
                Optional.empty(), SandboxSettings.defaults());
        assertEquals(List.of(nested.getParent(), script), b.readOnly());
        assertEquals(checkout, b.workingDirectory());
    }

    /**
     * A native program linked by rpath against a library in a directory of its own (as FFLL's bridge is): the
     * sandbox binds that directory itself (ldd), so the program starts without the adapter binding it by hand.
     */
    @Test
    void aProgramsSharedLibraryOutsideTheSystemIsBoundFromLdd(@TempDir Path host) throws Exception {
        Bubblewrap.assumeWorking();
        // JUnit's temporary directory is private to its owner; the sandboxed program runs as another uid when root
        Files.setPosixFilePermissions(host, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-xr-x"));
        Path lib = Files.createDirectories(host.resolve("lib"));
        Path bin = Files.createDirectories(host.resolve("prog"));   // not "bin": its parent would be bound whole
        Files.writeString(lib.resolve("answer.c"), "int answer(void) { return 42; }\n");
        Files.writeString(bin.resolve("main.c"), "#include <stdio.h>\nint answer(void);\n"
                + "int main(void) { printf(\"answer %d\\n\", answer()); return 0; }\n");
        compile("gcc", "-shared", "-fPIC", "-o", lib.resolve("libanswer.so").toString(), lib.resolve("answer.c").toString());
        compile("gcc", "-o", bin.resolve("main").toString(), bin.resolve("main.c").toString(), "-L" + lib, "-lanswer",
                "-Wl,-rpath," + lib);
        Path program = bin.resolve("main");
        Path realHost = host.toRealPath();
        assertEquals(List.of(lib.resolve("libanswer.so").toRealPath()), Binds.sharedLibraries(program).stream()
                .filter(l -> l.startsWith(realHost)).toList());
        Process p = Sandbox.of(SandboxSettings.defaults()).processBuilder(List.of(program.toString()))
                .redirectErrorStream(true).start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals("answer 42\n", out);
        assertEquals(0, p.exitValue());
        assertEquals(List.of(), Binds.sharedLibraries(lib.resolve("answer.c")), "a text file links nothing");
    }

    private static void compile(String... command) throws Exception {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        org.junit.jupiter.api.Assumptions.assumeTrue(p.waitFor() == 0, "cannot compile with gcc here: " + out);
    }
}
