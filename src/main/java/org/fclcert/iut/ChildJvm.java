package org.fclcert.iut;

import java.io.File;
import java.io.IOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.jar.JarFile;
import java.util.jar.Manifest;

/**
 * Starting a Java program of fclcert's own in a JVM of its own (the library bridges and {@code java:} without
 * {@code --in-process}): the same {@code java} fclcert runs on, and the class path fclcert itself was loaded from.
 * The command is launched through {@link ProcessIut}, so the JVM runs in the sandbox.
 */
final class ChildJvm {
    private ChildJvm() {}

    /** The {@code java} of the JVM fclcert runs on (else {@code java} on the PATH). */
    static String javaExecutable() {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        return Files.isExecutable(java) ? java.toString() : "java";
    }

    /** Where a class was loaded from (its jar or class directory), when the JVM says. */
    static Optional<String> location(Class<?> c) {
        CodeSource source = c.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            return Optional.empty();
        }
        try {
            return Optional.of(Path.of(source.getLocation().toURI()).toString());
        } catch (URISyntaxException | IllegalArgumentException e) {
            return Optional.empty();
        }
    }

    /**
     * fclcert's own class path, as files: the URLs of the loader that loaded fclcert where it is a URL class loader
     * (the Maven plugin's realm), else {@code java.class.path} with the {@code Class-Path} of a manifest-only jar
     * (as surefire starts tests) written out, so that the sandbox can bind each entry.
     */
    static List<String> ownClasspath() {
        Set<String> entries = new LinkedHashSet<>();
        location(ChildJvm.class).ifPresent(entries::add);
        if (ChildJvm.class.getClassLoader() instanceof URLClassLoader loader) {
            for (URL url : loader.getURLs()) {
                file(url).ifPresent(entries::add);
            }
        }
        String path = System.getProperty("java.class.path", "");
        for (String entry : path.split(File.pathSeparator)) {
            if (!entry.isBlank()) {
                addWithManifest(Path.of(entry).toAbsolutePath().normalize(), entries);
            }
        }
        return new ArrayList<>(entries);
    }

    private static void addWithManifest(Path entry, Set<String> entries) {
        if (!entries.add(entry.toString()) || !Files.isRegularFile(entry)) {
            return;
        }
        try (JarFile jar = new JarFile(entry.toFile())) {
            Manifest manifest = jar.getManifest();
            String classPath = manifest == null ? null : manifest.getMainAttributes().getValue("Class-Path");
            if (classPath == null) {
                return;
            }
            for (String item : classPath.strip().split("\\s+")) {
                try {
                    URL url = entry.toUri().resolve(item).toURL();
                    file(url).ifPresent(f -> addWithManifest(Path.of(f), entries));
                } catch (IOException | IllegalArgumentException e) {
                    // an entry that names no file: nothing to bind
                }
            }
        } catch (IOException e) {
            // not a jar: kept as it is
        }
    }

    private static Optional<String> file(URL url) {
        try {
            return "file".equals(url.getProtocol()) ? Optional.of(Path.of(url.toURI()).normalize().toString())
                    : Optional.empty();
        } catch (URISyntaxException | IllegalArgumentException e) {
            return Optional.empty();
        }
    }
}
