package org.fclcert.iut;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.fclcert.iut.IutException.Kind;

/**
 * FFLL 2.2.1, the Free Fuzzy Logic Library (C++, BSD), as an implementation under test. FFLL crashes (a
 * segmentation fault) on some programs, taking its host with it, so it runs in a process of its own: a small
 * bridge of fclcert's ({@code ffll_bridge.cpp}, a resource of this package) compiled with g++ against the
 * library and driven by {@link ProcessIut}, which restarts it after a crash.
 *
 * <p>Why a C++ bridge and not JNA in a child JVM: FFLL's C API addresses inputs by index and has no call that
 * names them; the bridge reads the names from FFLL's own model ({@code FuzzyModelBase}) and exports with FFLL's
 * own writer ({@code save_to_fcl_file}), which are C++ and out of JNA's reach. It also starts in milliseconds, which
 * matters for an implementation that is restarted after every crash; and it needs only the g++ every machine
 * here has, no new dependency.
 *
 * <p>Spec: {@code ffll} or {@code ffll:LIBRARY}, LIBRARY the shared library ({@code libffll*.so}) or the directory
 * holding it; its headers are expected in {@code include/} beside it. Without LIBRARY: the environment variable
 * {@code FCLCERT_FFLL} or the system property {@code fclcert.ffll}, else {@code shared/peers/ffll} in the working
 * directory or one of its parents (a checkout with the shared peers beside it).
 */
final class FfllIut {
    static final String SPEC = "ffll";
    static final String ENVIRONMENT = "FCLCERT_FFLL";
    static final String PROPERTY = "fclcert.ffll";
    private static final String SOURCE = "ffll_bridge.cpp";
    private static final Path SHARED = Path.of("shared", "peers", "ffll");
    private static final Pattern VERSION = Pattern.compile("FFLL (\\d+\\.\\d+(?:\\.\\d+)?)");
    private static final long COMPILE_SECONDS = 120;

    private FfllIut() {}

    static ImplementationUnderTest open(String spec, IutOptions options) throws IutException {
        String rest = spec.substring(SPEC.length());
        Path library = rest.startsWith(":") && !rest.substring(1).isBlank()
                ? library(Path.of(rest.substring(1).strip()))
                : defaultLibrary().orElseThrow(() -> new IutException(Kind.INFRA, "FFLL was not found: give its"
                        + " library as --iut ffll:PATH-TO/libffll.so, or set " + ENVIRONMENT + " (looked for "
                        + SHARED + " in the working directory and its parents)"));
        Path bridge = bridge(library);
        // the sandbox binds the bridge's directory and the library it links by rpath (ldd), read-only
        return new ProcessIut(spec, List.of(bridge.toString(), version(library)), options);
    }

    /** The FFLL found without a spec: environment, system property, then {@code shared/peers/ffll} up the tree. */
    static Optional<Path> defaultLibrary() {
        for (String given : new String[] {System.getenv(ENVIRONMENT), System.getProperty(PROPERTY)}) {
            if (given != null && !given.isBlank()) {
                return findLibrary(Path.of(given.strip()));
            }
        }
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Optional<Path> found = findLibrary(dir.resolve(SHARED));
            if (found.isPresent()) {
                return found;
            }
        }
        return Optional.empty();
    }

    private static Path library(Path given) throws IutException {
        return findLibrary(given).orElseThrow(() -> new IutException(Kind.INFRA, "no FFLL library at " + given
                + ": give the shared library (libffll*.so) or the directory that holds it"));
    }

    private static Optional<Path> findLibrary(Path given) {
        if (Files.isRegularFile(given)) {
            return Optional.of(given.toAbsolutePath().normalize());
        }
        if (!Files.isDirectory(given)) {
            return Optional.empty();
        }
        try (Stream<Path> files = Files.list(given)) {
            return files.filter(p -> p.getFileName().toString().matches("libffll.*\\.so(\\..*)?"))
                    .filter(Files::isRegularFile).sorted().findFirst().map(p -> p.toAbsolutePath().normalize());
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    /** FFLL's version as the README beside the library names it, else the library's file name. */
    static String version(Path library) {
        Path readme = library.resolveSibling("README.md");
        try {
            Matcher m = VERSION.matcher(Files.readString(readme, StandardCharsets.UTF_8));
            if (m.find()) {
                return m.group(1) + " (" + library.getFileName() + ")";
            }
        } catch (IOException | RuntimeException e) {
            // no README: the file name says which build it is
        }
        return library.getFileName().toString();
    }

    /**
     * The bridge built for {@code library}: compiled once per bridge source and library (by their hash) into
     * fclcert's cache under the temporary directory, and reused; a half-written build is never seen (it is
     * moved into place when complete).
     */
    static Path bridge(Path library) throws IutException {
        byte[] source = BridgeFiles.resource(FfllIut.class, SOURCE, "the FFLL bridge's source");
        Path include = library.resolveSibling("include");
        if (!Files.isRegularFile(include.resolve("FFLLAPI.h"))) {
            throw new IutException(Kind.INFRA, "FFLL's headers were not found in " + include
                    + " (the bridge is compiled against them; they come with the library)");
        }
        String key = hash(source, library);
        Path dir = BridgeFiles.directory("ffll-bridge", key);
        Path binary = dir.resolve("ffll-bridge");
        if (Files.isExecutable(binary)) {
            return binary;
        }
        try {
            Files.createDirectories(dir);
            Path cpp = Files.createTempFile(dir, "ffll_bridge", ".cpp");
            Files.write(cpp, source);
            Path partial = Files.createTempFile(dir, "ffll-bridge", ".partial");
            List<String> command = new ArrayList<>(List.of("g++", "-O2", "-std=c++14", "-w", "-fpermissive",
                    "-include", include.resolve("posix_shim.h").toString(), "-I" + include, cpp.toString(),
                    library.toString(), "-Wl,-rpath," + library.getParent(), "-o", partial.toString()));
            if (!Files.isRegularFile(include.resolve("posix_shim.h"))) {
                command.subList(5, 7).clear();
            }
            Process g = new ProcessBuilder(command).redirectErrorStream(true).start();
            String output;
            try (InputStream out = g.getInputStream()) {
                output = new String(out.readAllBytes(), StandardCharsets.UTF_8);
            }
            if (!g.waitFor(COMPILE_SECONDS, TimeUnit.SECONDS)) {
                ProcessSession.killTree(g);
                throw new IutException(Kind.INFRA, "compiling the FFLL bridge took longer than " + COMPILE_SECONDS + " s");
            }
            Files.deleteIfExists(cpp);
            if (g.exitValue() != 0) {
                Files.deleteIfExists(partial);
                throw new IutException(Kind.INFRA, "g++ could not compile the FFLL bridge against " + library + ":\n"
                        + IutText.kept(output.strip()));
            }
            BridgeFiles.moveIntoPlace(partial, binary);
            return binary;
        } catch (IOException e) {
            throw new IutException(Kind.INFRA, "could not build the FFLL bridge (is g++ installed?): " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IutException(Kind.INFRA, "interrupted while compiling the FFLL bridge");
        }
    }



    private static String hash(byte[] source, Path library) throws IutException {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            sha.update(source);
            sha.update(library.toString().getBytes(StandardCharsets.UTF_8));
            sha.update(Long.toString(Files.size(library)).getBytes(StandardCharsets.UTF_8));
            sha.update(Files.getLastModifiedTime(library).toString().getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(sha.digest(), 0, 12);
        } catch (NoSuchAlgorithmException | IOException e) {
            throw new IutException(Kind.INFRA, "could not read the FFLL library " + library + ": " + e.getMessage());
        }
    }
}
