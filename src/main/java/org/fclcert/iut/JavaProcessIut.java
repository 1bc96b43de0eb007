package org.fclcert.iut;

import java.io.File;
import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.sandbox.Isolation;

/**
 * {@code java:CLASS} without {@code --in-process}: the vendor's class runs in a child JVM ({@link JavaBridge}) started
 * through {@link ProcessIut}, so it is sandboxed like any process implementation (its class path entries bound
 * read-only), a crash or a {@code System.exit} costs only the request under way ({@link RestartPolicy}), and a hang
 * is ended by killing that JVM. Before anything starts, the class is looked up (without running any of its code)
 * so that a wrong name or class path is refused at once, as in process.
 */
final class JavaProcessIut {
    private JavaProcessIut() {}

    static ImplementationUnderTest open(String spec, String className, IutOptions options) throws IutException {
        if (className.isEmpty()) {
            throw new IutException(Kind.INFRA, "java: needs a class name, as in java:com.example.MyFcl");
        }
        // a missing entry is passed over, as the JVM's own -cp and the in-process class loader do (a build's class
        // path names target/test-classes whether or not it exists); a class found nowhere is refused just below
        List<String> given = new ArrayList<>();
        List<Path> present = new ArrayList<>();
        for (Path p : options.classpath()) {
            if (Files.exists(p)) {
                given.add(p.toAbsolutePath().normalize().toString());
                present.add(p);
            }
        }
        checkClass(className, present);
        Set<String> classpath = new LinkedHashSet<>(ChildJvm.ownClasspath());
        classpath.addAll(given);
        long heap = Math.max(64L << 20, options.sandbox().limits().memoryBytes() / 4);
        List<String> command = List.of(ChildJvm.javaExecutable(), "-Xmx" + (heap >> 20) + "m", "-XX:+UseSerialGC",
                "-XX:-UsePerfData", "-Djava.awt.headless=true", "-cp", String.join(File.pathSeparator, classpath),
                JavaBridge.class.getName(), className);
        return new InChildJvm(new ProcessIut(spec, command, options));
    }

    /** The class is there and implements the SPI; loaded without initialising it, so none of its code runs here. */
    private static void checkClass(String className, List<Path> entries) throws IutException {
        URL[] urls = new URL[entries.size()];
        for (int k = 0; k < urls.length; k++) {
            try {
                urls[k] = entries.get(k).toAbsolutePath().toUri().toURL();
            } catch (MalformedURLException e) {
                throw new IutException(Kind.INFRA, "bad classpath entry " + entries.get(k) + ": " + e.getMessage());
            }
        }
        try (URLClassLoader loader = new URLClassLoader("fclcert-iut-check", urls, JavaProcessIut.class.getClassLoader())) {
            JavaIut.checkConstructible(JavaIut.implementationClass(className, urls.length == 0 ? null : loader));
        } catch (IOException e) {
            // closing a class loader that read nothing more
        }
    }

    /** The process implementation, its isolation saying that it is the {@code java:} class in a child JVM. */
    private static final class InChildJvm extends ForwardingIut {
        InChildJvm(ImplementationUnderTest process) {
            super(process);
        }

        @Override
        public Isolation isolation() {
            Isolation process = delegate().isolation();
            return new Isolation(process.kind(), "a child JVM (java: without --in-process); " + process.description());
        }
    }
}
