package org.fclcert.iut;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.zip.ZipFile;
import org.fclcert.iut.IutException.Kind;

/**
 * jFuzzyLogic (LGPL-3) as an implementation under test, isolated in a child JVM: {@code java -cp <fclcert's
 * classes>:<jFuzzyLogic jar>:<antlr-runtime 3 jar> org.fclcert.iut.JFuzzyLogicBridge}, which speaks the
 * JSON-lines protocol, so {@link ProcessIut} drives it with its timeouts, restarts and memory readings.
 * jFuzzyLogic prints to standard output, keeps static state and overflows its stack on deep nesting; in a JVM
 * of its own none of that reaches fclcert.
 *
 * <p>Spec: {@code jfuzzylogic:JAR}, optionally followed by more class path entries separated by the platform's
 * path separator ({@code jfuzzylogic:jFuzzyLogic.jar:antlr-runtime-3.1.3.jar}). jFuzzyLogic needs
 * {@code org.antlr:antlr-runtime:3.1.3} at run time, found in this order: a class path entry given in the spec
 * or with {@code --classpath}; the jar itself (the project's released jar bundles it); fclcert's own class path;
 * the local Maven repository ({@code -Dmaven.repo.local}, else {@code ~/.m2/repository}).
 */
final class JFuzzyLogicIut {
    static final String SPEC = "jfuzzylogic";
    static final String ANTLR3_CLASS = "org/antlr/runtime/RecognitionException.class";
    static final String ANTLR3_JAR = "org/antlr/antlr-runtime/3.1.3/antlr-runtime-3.1.3.jar";

    private JFuzzyLogicIut() {}

    static ImplementationUnderTest open(String spec, IutOptions options) throws IutException {
        String rest = spec.substring(SPEC.length());
        String entries = rest.startsWith(":") ? rest.substring(1).strip() : "";
        if (entries.isEmpty()) {
            throw new IutException(Kind.INFRA, "malformed implementation under test '" + spec
                    + "': use jfuzzylogic:PATH-TO-JAR (jFuzzyLogic is not on Maven Central; build it from its source"
                    + " or use its released jar)");
        }
        List<Path> given = new ArrayList<>();
        for (String entry : entries.split(File.pathSeparator)) {
            if (!entry.isBlank()) {
                given.add(Path.of(entry.strip()));
            }
        }
        Path jar = given.get(0);
        if (!Files.isRegularFile(jar)) {
            throw new IutException(Kind.INFRA, "jFuzzyLogic jar " + jar + " does not exist");
        }
        if (!contains(jar, "net/sourceforge/jFuzzyLogic/FIS.class")) {
            throw new IutException(Kind.INFRA, jar + " holds no net.sourceforge.jFuzzyLogic.FIS: is it jFuzzyLogic?");
        }
        List<Path> extra = new ArrayList<>(given.subList(1, given.size()));
        extra.addAll(options.classpath());
        for (Path p : extra) {
            if (!Files.exists(p)) {
                throw new IutException(Kind.INFRA, "class path entry " + p + " for jFuzzyLogic does not exist");
            }
        }
        Set<String> classpath = new LinkedHashSet<>();
        classpath.addAll(ownClasspath());
        classpath.add(jar.toAbsolutePath().toString());
        extra.forEach(p -> classpath.add(p.toAbsolutePath().toString()));
        if (!contains(jar, ANTLR3_CLASS) && extra.stream().noneMatch(p -> contains(p, ANTLR3_CLASS))) {
            Path antlr = antlrRuntime().orElseThrow(() -> new IutException(Kind.INFRA,
                    "jFuzzyLogic needs org.antlr:antlr-runtime:3.1.3 at run time, and it was found neither beside"
                            + " the jar, nor on fclcert's class path, nor in the local Maven repository: give it as"
                            + " --iut jfuzzylogic:" + jar + File.pathSeparator + "PATH-TO/antlr-runtime-3.1.3.jar, or"
                            + " fetch it with mvn dependency:get -Dartifact=org.antlr:antlr-runtime:3.1.3"));
            classpath.add(antlr.toString());
        }
        List<String> command = List.of(ChildJvm.javaExecutable(), "-Xmx512m", "-Djava.awt.headless=true",
                "-cp", String.join(File.pathSeparator, classpath), JFuzzyLogicBridge.class.getName());
        return new ProcessIut(spec, command, options);
    }

    /** Where fclcert's own classes (the bridge) and Jackson, which it uses, come from. */
    private static List<String> ownClasspath() throws IutException {
        List<String> entries = new ArrayList<>();
        for (Class<?> c : List.of(JFuzzyLogicBridge.class, com.fasterxml.jackson.databind.ObjectMapper.class,
                com.fasterxml.jackson.core.JsonFactory.class, com.fasterxml.jackson.annotation.JsonInclude.class)) {
            String location = ChildJvm.location(c).orElseThrow(() -> new IutException(Kind.INFRA,
                    "cannot tell where " + c.getName() + " was loaded from, to start jFuzzyLogic's JVM"));
            if (!entries.contains(location)) {
                entries.add(location);
            }
        }
        return entries;
    }

    /** antlr-runtime 3 from fclcert's class path (as in its tests), else from the local Maven repository. */
    static Optional<Path> antlrRuntime() {
        try {
            Class<?> c = Class.forName("org.antlr.runtime.RecognitionException", false, JFuzzyLogicIut.class.getClassLoader());
            Optional<String> here = ChildJvm.location(c);
            if (here.isPresent()) {
                return Optional.of(Path.of(here.get()));
            }
        } catch (ClassNotFoundException | LinkageError e) {
            // not on the class path: look in the Maven repository
        }
        String repo = System.getProperty("maven.repo.local");
        Path base = repo != null && !repo.isBlank() ? Path.of(repo)
                : Path.of(System.getProperty("user.home"), ".m2", "repository");
        Path jar = base.resolve(ANTLR3_JAR);
        return Files.isRegularFile(jar) ? Optional.of(jar.toAbsolutePath()) : Optional.empty();
    }

    private static boolean contains(Path jarOrDir, String entry) {
        if (Files.isDirectory(jarOrDir)) {
            return Files.exists(jarOrDir.resolve(entry));
        }
        try (ZipFile zip = new ZipFile(jarOrDir.toFile())) {
            return zip.getEntry(entry) != null;
        } catch (IOException e) {
            return false;
        }
    }
}
