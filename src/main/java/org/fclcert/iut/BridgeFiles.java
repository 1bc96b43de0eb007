package org.fclcert.iut;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Arrays;
import java.util.HexFormat;
import org.fclcert.iut.IutException.Kind;

/**
 * The bridges fclcert ships as resources (the FFLL, pyfuzzylite and Octave ones), put where a process can run them:
 * in a cache under the temporary directory, one directory per content hash, each file moved into place when
 * complete so a half-written one is never seen. The temporary directory is shared with other users, so a file
 * already there is reused only when it is a regular file (not a link) holding exactly the expected bytes.
 */
final class BridgeFiles {
    private BridgeFiles() {}

    /** The bytes of a resource next to {@code owner}; {@code what} names it in messages ("the Octave bridge"). */
    static byte[] resource(Class<?> owner, String name, String what) throws IutException {
        try (InputStream in = owner.getResourceAsStream(name)) {
            if (in == null) {
                throw new IutException(Kind.INFRA, what + " " + name + " is missing from fclcert");
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new IutException(Kind.INFRA, "could not read " + what + ": " + e.getMessage());
        }
    }

    /** A short hex SHA-256 of the parts, in order: the name of a cache directory. */
    static String key(byte[]... parts) {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            for (byte[] part : parts) {
                sha.update(part);
            }
            return HexFormat.of().formatHex(sha.digest(), 0, 12);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK has no SHA-256", e);
        }
    }

    /** The cache directory {@code fclcert-<name>/<key>} under the temporary directory (not created). */
    static Path directory(String name, String key) {
        return Path.of(System.getProperty("java.io.tmpdir"), "fclcert-" + name, key);
    }

    /**
     * {@code content} as the file {@code fileName} of the cache directory {@code name}, keyed by the content's
     * hash: written readable by all (the sandbox may run the interpreter as another user) unless the same bytes are
     * already there.
     */
    static Path script(String name, String fileName, byte[] content, String what) throws IutException {
        Path dir = directory(name, key(content));
        Path script = dir.resolve(fileName);
        try {
            if (Files.isRegularFile(script, LinkOption.NOFOLLOW_LINKS)
                    && Arrays.equals(Files.readAllBytes(script), content)) {
                return script;
            }
            Files.createDirectories(dir);
            Path partial = Files.createTempFile(dir, fileName, ".partial");
            Files.write(partial, content);
            try {
                // a temporary file is private to its owner
                Files.setPosixFilePermissions(partial, PosixFilePermissions.fromString("rw-r--r--"));
            } catch (UnsupportedOperationException e) {
                // not a POSIX file system: its defaults apply
            }
            moveIntoPlace(partial, script);
            return script;
        } catch (IOException e) {
            throw new IutException(Kind.INFRA, "could not write " + what + " to " + dir + ": " + e.getMessage());
        }
    }

    /** Moves a complete file over its final name, atomically where the file system can. */
    static void moveIntoPlace(Path partial, Path target) throws IOException {
        try {
            Files.move(partial, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(partial, target, StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
