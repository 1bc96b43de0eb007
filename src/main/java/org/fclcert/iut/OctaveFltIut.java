package org.fclcert.iut;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
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

    /** The bridge script, in fclcert's cache under the temporary directory ({@link BridgeFiles}). */
    static Path bridge() throws IutException {
        return BridgeFiles.script("octave-bridge", SOURCE,
                BridgeFiles.resource(OctaveFltIut.class, SOURCE, "the Octave bridge"), "the Octave bridge");
    }
}
