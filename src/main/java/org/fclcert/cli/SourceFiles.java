package org.fclcert.cli;

import java.io.IOException;
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
        try {
            byte[] bytes = STDIN.equals(path) ? readStdin() : Limits.readFile(Path.of(path));
            return StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPLACE)
                    .onUnmappableCharacter(CodingErrorAction.REPLACE)
                    .decode(ByteBuffer.wrap(bytes)).toString().replaceFirst("^\uFEFF", "");
        } catch (Limits.Unreadable e) {
            throw new FileProblem(name(path), e.getMessage());
        } catch (NoSuchFileException e) {
            throw new FileProblem(path, "no such file");
        } catch (AccessDeniedException e) {
            throw new FileProblem(path, "permission denied");
        } catch (IOException e) {
            throw new FileProblem(name(path), String.valueOf(e.getMessage()));
        }
    }

    /** The argument that names standard input. */
    static final String STDIN = "-";

    /** The name standard input goes by in locations and messages. */
    static final String STDIN_NAME = "<stdin>";

    /** The name a path goes by in locations and messages: {@code <stdin>} for {@code -}, else the path itself. */
    static String name(String path) {
        return STDIN.equals(path) ? STDIN_NAME : path;
    }

    /** Standard input to its end, held to the same size limit as a file. */
    private static byte[] readStdin() throws IOException, FileProblem {
        byte[] bytes = System.in.readNBytes((int) Limits.MAX_SOURCE_BYTES + 1);
        if (bytes.length > Limits.MAX_SOURCE_BYTES) {
            throw new FileProblem(STDIN_NAME, "more than " + Limits.MAX_SOURCE_BYTES + " bytes");
        }
        return bytes;
    }

    static void write(String path, String text) throws FileProblem {
        try {
            Files.writeString(Path.of(path), text, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new FileProblem("cannot write " + path + ": " + e.getMessage());
        }
    }
}
