package org.fclcert.iut;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.iut.IutException.Kind;

/**
 * pyfuzzylite (the current fuzzylite, in Python; PyPI {@code pyfuzzylite}) as an implementation under test. It reads
 * only fuzzylite's FLL, so its positive cases are presented as FLL ({@code --present-as auto}); the standard FCL of
 * the language axis goes to it unchanged and is refused by its FLL importer. A small bridge of fclcert's
 * ({@code pyfuzzylite_bridge.py}, a resource of this package) speaks the JSON-lines protocol and drives the library;
 * {@link ProcessIut} runs it, in the sandbox, with the same timeouts, restarts and process-tree kill as any
 * {@code process:} implementation.
 *
 * <p>Spec: {@code pyfuzzylite} or {@code pyfuzzylite:PYTHON}, PYTHON an interpreter that imports pyfuzzylite. Without
 * it: the environment variable {@code FCLCERT_PYFUZZYLITE} or the system property {@code fclcert.pyfuzzylite}, else
 * the virtual environment {@code scripts/ensure-pyfuzzylite} makes ({@link #DEFAULT_VERSION}, under
 * {@code $FCLCERT_CACHE}, else {@code ~/.fclcert}).
 */
final class PyfuzzyliteIut {
    static final String SPEC = "pyfuzzylite";
    static final String ENVIRONMENT = "FCLCERT_PYFUZZYLITE";
    static final String PROPERTY = "fclcert.pyfuzzylite";
    /** The version scripts/ensure-pyfuzzylite installs, and the name of its environment's directory. */
    static final String DEFAULT_VERSION = "8.0.6";
    private static final String SOURCE = "pyfuzzylite_bridge.py";

    private PyfuzzyliteIut() {}

    static ImplementationUnderTest open(String spec, IutOptions options) throws IutException {
        String rest = spec.substring(SPEC.length());
        Path python;
        if (rest.startsWith(":") && !rest.substring(1).isBlank()) {
            python = Path.of(rest.substring(1).strip());
            if (!Files.isExecutable(python)) {
                throw new IutException(Kind.INFRA, "no Python interpreter at " + python + ": give one that imports"
                        + " pyfuzzylite, as --iut pyfuzzylite:PATH-TO/bin/python");
            }
        } else {
            python = defaultPython().orElseThrow(() -> new IutException(Kind.INFRA, "pyfuzzylite was not found:"
                    + " run scripts/ensure-pyfuzzylite (it makes a virtual environment with pyfuzzylite "
                    + DEFAULT_VERSION + " at " + environment() + "), or give its Python as --iut pyfuzzylite:PATH, or"
                    + " set " + ENVIRONMENT));
        }
        Path bridge = bridge();
        // the interpreter's environment (its site-packages) is not named by the command: bound read-only too
        List<Path> readable = new ArrayList<>(options.sandbox().readOnly());
        Path home = python.toAbsolutePath().getParent();
        readable.add(home.getParent() != null ? home.getParent() : home);
        IutOptions sandboxed = options.withSandbox(options.sandbox().withReadOnly(readable));
        return new ProcessIut(spec, List.of(python.toString(), bridge.toString()), sandboxed);
    }

    /** The directory of the virtual environment scripts/ensure-pyfuzzylite makes (whether or not it is there). */
    static Path environment() {
        String cache = System.getenv("FCLCERT_CACHE");
        Path root = cache != null && !cache.isBlank() ? Path.of(cache) : Path.of(System.getProperty("user.home"),
                ".fclcert");
        return root.resolve("pyfuzzylite-" + DEFAULT_VERSION);
    }

    /** The Python found without a spec: environment, system property, then the project's virtual environment. */
    static Optional<Path> defaultPython() {
        for (String given : new String[] {System.getenv(ENVIRONMENT), System.getProperty(PROPERTY)}) {
            if (given != null && !given.isBlank()) {
                Path p = Path.of(given.strip());
                return Files.isExecutable(p) ? Optional.of(p) : Optional.empty();
            }
        }
        Path p = environment().resolve("bin").resolve("python");
        return Files.isExecutable(p) ? Optional.of(p) : Optional.empty();
    }

    /** The bridge script, in fclcert's cache under the temporary directory ({@link BridgeFiles}). */
    static Path bridge() throws IutException {
        return BridgeFiles.script("pyfuzzylite-bridge", SOURCE,
                BridgeFiles.resource(PyfuzzyliteIut.class, SOURCE, "the pyfuzzylite bridge"), "the pyfuzzylite bridge");
    }
}
