package org.fclcert.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.fclcert.model.Limits;

/** Reading and writing program files for the commands, with I/O failures turned into one plain sentence. */
final class SourceFiles {
    private SourceFiles() {
    }

    /** A file's reason for not being readable or writable, as a short phrase. */
    static final class FileProblem extends Exception {
        FileProblem(String path, String reason) {
            super("cannot read " + path + ": " + reason);
        }

        FileProblem(String message) {
            super(message);
        }
    }

    /**
     * The file's text as UTF-8; bytes that are not UTF-8 (say a Latin-1 comment) become U+FFFD
     * rather than failing, since FCL itself is plain ASCII and the reader reports any stray character.
     * A leading byte order mark, as some Windows editors write, is not part of the text.
     */
    static String read(String path) throws FileProblem {
        Path p = Path.of(path);
        if (Files.isDirectory(p)) {
            throw new FileProblem(path, "it is a directory");
        }
        if (Files.exists(p) && !Files.isRegularFile(p)) {
            // checked before opening: opening a FIFO blocks, and /dev/zero never ends
            throw new FileProblem(path, "not a regular file (a device, pipe or socket); fclcert reads only files");
        }
        try {
            byte[] bytes = readBounded(p, path);
            return StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPLACE)
                    .onUnmappableCharacter(CodingErrorAction.REPLACE)
                    .decode(ByteBuffer.wrap(bytes)).toString().replaceFirst("^\uFEFF", "");
        } catch (NoSuchFileException e) {
            throw new FileProblem(path, "no such file");
        } catch (AccessDeniedException e) {
            throw new FileProblem(path, "permission denied");
        } catch (IOException e) {
            throw new FileProblem(path, String.valueOf(e.getMessage()));
        }
    }

    /** At most Limits.MAX_SOURCE_BYTES, also when the file grows while it is read. */
    private static byte[] readBounded(Path p, String path) throws IOException, FileProblem {
        if (Files.size(p) > Limits.MAX_SOURCE_BYTES) {
            throw tooLarge(path);
        }
        try (InputStream in = Files.newInputStream(p)) {
            byte[] bytes = in.readNBytes((int) Limits.MAX_SOURCE_BYTES + 1);
            if (bytes.length > Limits.MAX_SOURCE_BYTES) {
                throw tooLarge(path);
            }
            return bytes;
        }
    }

    private static FileProblem tooLarge(String path) {
        return new FileProblem(path, "larger than fclcert's limit of " + Limits.MAX_SOURCE_BYTES / (1024 * 1024)
                + " MiB (org.fclcert.model.Limits.MAX_SOURCE_BYTES)");
    }

    static void write(String path, String text) throws FileProblem {
        try {
            Files.writeString(Path.of(path), text, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new FileProblem("cannot write " + path + ": " + e.getMessage());
        }
    }
}
