package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A bridge script in the shared temporary directory is reused only when it is the very bytes fclcert ships. */
class BridgeFilesTest {
    private static final byte[] CONTENT = ("print('bridge " + System.nanoTime() + "')\n").getBytes(StandardCharsets.UTF_8);

    @Test
    void aPlantedFileOrLinkIsReplacedByTheShippedBytes(@TempDir Path elsewhere) throws Exception {
        Path script = BridgeFiles.script("bridge-test", "b.py", CONTENT, "the test bridge");
        assertArrayEquals(CONTENT, Files.readAllBytes(script));
        assertEquals(script, BridgeFiles.script("bridge-test", "b.py", CONTENT, "the test bridge"));

        // another user's file of the same name, other bytes: not run, rewritten
        Files.writeString(script, "import os; os.system('evil')\n");
        assertArrayEquals(CONTENT, Files.readAllBytes(BridgeFiles.script("bridge-test", "b.py", CONTENT, "x")));

        // a link to a file holding the same bytes: not followed, replaced by a file of fclcert's own
        Path target = elsewhere.resolve("same.py");
        Files.write(target, CONTENT);
        Files.delete(script);
        Files.createSymbolicLink(script, target);
        Path again = BridgeFiles.script("bridge-test", "b.py", CONTENT, "x");
        assertFalse(Files.isSymbolicLink(again));
        assertArrayEquals(CONTENT, Files.readAllBytes(again));
        assertEquals(true, Files.isRegularFile(again, LinkOption.NOFOLLOW_LINKS));
        Files.delete(again);
    }
}
