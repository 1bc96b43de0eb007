package org.fclcert.iut;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.fclcert.iut.IutException.Kind;

/**
 * The Octave fuzzy-logic-toolkit (0.4.6 in Debian's {@code octave-fuzzy-logic-toolkit}), MATLAB's
 * {@code readfis}/{@code evalfis} interface, as an implementation under test. One long-lived {@code octave-cli}
 * per session runs fclcert's bridge {@code octave_flt_bridge.m} (a resource of this package), which speaks the
 * JSON-lines protocol: programs arrive as FIS text (the kind's {@code --present-as} is FIS, written by
 * {@code org.fclcert.write.FisWriter}), are written to the process's private temporary directory and read by
 * {@code readfis}; {@code eval} is {@code evalfis}. It runs as any {@code process:} implementation
 * ({@link ProcessIut}): inside the sandbox, with its timeouts, restarts and process-tree kill.
 *
 * <p>Spec: {@code octave-flt} or {@code octave-flt:OCTAVE-CLI}, the {@code octave-cli} to run (default: the one
 * on PATH; {@code scripts/ensure-octave} installs it with the toolkit).
 */
final class OctaveFltIut {
    static final String SPEC = "octave-flt";
    private static final String SOURCE = "octave_flt_bridge.m";

    private OctaveFltIut() {}

    static ImplementationUnderTest open(String spec, IutOptions options) throws IutException {
        String rest = spec.substring(SPEC.length());
        Path octave = rest.startsWith(":") && !rest.substring(1).isBlank() ? Path.of(rest.substring(1).strip())
                : onPath("octave-cli").orElseThrow(() -> new IutException(Kind.INFRA, "octave-cli was not found on"
                        + " PATH: install Octave and its fuzzy-logic-toolkit (scripts/ensure-octave), or give"
                        + " --iut octave-flt:PATH-TO/octave-cli"));
        if (!Files.isExecutable(octave)) {
            throw new IutException(Kind.INFRA, "no executable octave-cli at " + octave);
        }
        Path bridge = bridge();
        List<Path> readable = new ArrayList<>(options.sandbox().readOnly());
        readable.add(bridge.toAbsolutePath().getParent());
        IutOptions sandboxed = options.withSandbox(options.sandbox().withReadOnly(readable));
        return new ProcessIut(spec, List.of(octave.toString(), "--no-gui", "--quiet", "--no-init-file",
                "--no-history", bridge.toString()), sandboxed);
    }

    private static Optional<Path> onPath(String command) {
        String path = System.getenv("PATH");
        return path == null ? Optional.empty() : Stream.of(path.split(java.io.File.pathSeparator))
                .filter(d -> !d.isBlank()).map(d -> Path.of(d, command)).filter(Files::isExecutable).findFirst();
    }

    /** The bridge script, written once per content (by its hash) into fclcert's cache under the temporary directory. */
    static Path bridge() throws IutException {
        byte[] source;
        try (InputStream in = OctaveFltIut.class.getResourceAsStream(SOURCE)) {
            if (in == null) {
                throw new IutException(Kind.INFRA, "the Octave bridge " + SOURCE + " is missing from fclcert");
            }
            source = in.readAllBytes();
        } catch (IOException e) {
            throw new IutException(Kind.INFRA, "could not read the Octave bridge: " + e.getMessage());
        }
        try {
            String key = HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(source), 0, 12);
            Path dir = Path.of(System.getProperty("java.io.tmpdir"), "fclcert-octave-bridge", key);
            Path script = dir.resolve(SOURCE);
            if (Files.isRegularFile(script) && Files.size(script) == source.length) {
                return script;
            }
            Files.createDirectories(dir);
            Path partial = Files.createTempFile(dir, "bridge", ".partial");
            Files.write(partial, source);
            // a temporary file is private to its owner; the sandbox may run octave-cli as another user
            Files.setPosixFilePermissions(partial, java.nio.file.attribute.PosixFilePermissions.fromString("rw-r--r--"));
            try {
                Files.move(partial, script, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(partial, script, StandardCopyOption.REPLACE_EXISTING);
            }
            return script;
        } catch (IOException | NoSuchAlgorithmException e) {
            throw new IutException(Kind.INFRA, "could not write the Octave bridge: " + e.getMessage());
        }
    }
}
