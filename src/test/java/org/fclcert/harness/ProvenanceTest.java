package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.fclcert.iut.IutInfo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The implementation's identity as fclcert measures it, beside the name it gives itself (issue 26). */
class ProvenanceTest {
    @TempDir
    Path dir;

    /** sha256sum(1): a method independent of fclcert's. */
    private static String sha256sum(Path file) throws Exception {
        Process p = new ProcessBuilder("sha256sum", file.toString()).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor());
        return out.split("\\s+")[0];
    }

    private static IutInfo info(String name) {
        return new IutInfo(name, "9.9", "cmd", List.of(), Map.of());
    }

    @Test
    void aJavaImplementationIsIdentifiedByTheHashOfEveryClassPathEntry() throws Exception {
        Path jar = Files.write(dir.resolve("acme-fcl.jar"), "not really a jar".getBytes(StandardCharsets.UTF_8));
        Provenance.IutIdentity id = Provenance.identify(info("fclcert reference evaluator"), "java:com.acme.AcmeFcl",
                List.of(jar));
        assertEquals("java", id.kind());
        assertEquals(List.of(new Provenance.FileHash(jar.toRealPath().toString(), sha256sum(jar))), id.files());
        assertEquals("fclcert reference evaluator", id.claimedName(), "the name it gives itself is kept as its claim");
    }

    @Test
    void aProcessIsIdentifiedByItsResolvedExecutableAndTheFilesItsCommandNames() throws Exception {
        Path script = Path.of("src/test/resources/iut/lookup.py");
        Provenance.IutIdentity id = Provenance.identify(info("lookup"), "process:python3 " + script + " --fast", null);
        assertEquals("process", id.kind());
        Path python = Path.of(id.executable());
        assertTrue(python.isAbsolute() && Files.isExecutable(python), id.executable());
        assertEquals(2, id.files().size(), id.files().toString());
        assertEquals(sha256sum(python), id.files().get(0).sha256());
        assertEquals(script.toRealPath().toString(), id.files().get(1).path());
        assertEquals(sha256sum(script), id.files().get(1).sha256());
    }
}
