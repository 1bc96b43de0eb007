package org.fclcert.iut;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.Properties;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.iut.spi.FclImplementation;
import org.fclcert.iut.spi.FclInstance;
import org.fclcert.iut.spi.FclLoadResult;
import org.fclcert.iut.spi.FclProgram;
import org.fclcert.model.Names;

/**
 * jfuzzylite 6.0.1 (GPL-3, the Java twin of fuzzylite 6) behind the vendor SPI, reached only by reflection:
 * fclcert neither bundles nor needs it to compile. Spec {@code jfuzzylite} finds it on fclcert's class path,
 * {@code jfuzzylite:JAR} loads it from that jar in a class loader of its own. {@link JavaIut} then drives it
 * like any vendor class (worker thread, timeout, restart budget).
 *
 * <p>The program text is passed unchanged to {@code FclImporter.fromString}. jfuzzylite signals a rejection by
 * throwing a plain {@code RuntimeException} ({@code [syntax error] …}, {@code [factory error] …}) or, for a
 * number it cannot read, a {@code NumberFormatException}: those are clean rejections, with the line its message
 * names ({@link LibraryMessages#fuzzyliteLine}). Anything else thrown — a {@code NullPointerException}, an
 * index out of bounds, an {@link Error} — is an internal failure of the library and reported as a crash, so a
 * bug in the library never looks like a deliberate refusal. What the SPI cannot observe is stated in
 * {@code docs/iut-protocol.md}, "jfuzzylite": it builds only the first function block, and its variables start
 * at NaN (the adapter sets every input to 0, the initial value of a REAL, as the SPI's contract asks).
 */
final class JfuzzyliteImplementation implements FclImplementation {
    static final String SPEC = "jfuzzylite";
    private static final String IMPORTER = "com.fuzzylite.imex.FclImporter";
    private static final Pattern BLOCK = Pattern.compile("(?i)\\bFUNCTION_BLOCK\\s+([A-Za-z_][A-Za-z0-9_]*)");
    private static final Pattern COMMENT = Pattern.compile("\\(\\*.*?(\\*\\)|\\z)", Pattern.DOTALL);

    private final String version;
    private final Method fromString;
    private final Object importer;
    private final Method exportText;
    private final Object exporter;

    private JfuzzyliteImplementation(ClassLoader loader) throws ReflectiveOperationException {
        Class<?> importerType = Class.forName(IMPORTER, true, loader);
        this.importer = importerType.getConstructor().newInstance();
        this.fromString = importerType.getMethod("fromString", String.class);
        Class<?> engineType = Class.forName("com.fuzzylite.Engine", true, loader);
        Class<?> exporterType = Class.forName("com.fuzzylite.imex.FclExporter", true, loader);
        this.exporter = exporterType.getConstructor().newInstance();
        this.exportText = exporterType.getMethod("toString", engineType);
        Class<?> library = initialiseKeepingLogging("com.fuzzylite.FuzzyLite", loader);
        // the library logs through java.util.logging; a certification run keeps its own output clean
        library.getMethod("setLogging", boolean.class).invoke(null, false);
        this.version = artifactVersion(loader).orElse(String.valueOf(library.getField("VERSION").get(null)));
    }

    /**
     * Initialises a class whose static initialiser replaces the JVM-wide java.util.logging configuration: jfuzzylite's
     * {@code FuzzyLite} reads its own {@code logging.properties} into the {@code LogManager} (root level ALL, a console
     * handler at ALL), after which every logger in the process prints its FINE to FINEST records (in a test run
     * JUnit's and Jazzer's, over a thousand lines). The root logger's level and handlers are put back as they were.
     */
    static Class<?> initialiseKeepingLogging(String className, ClassLoader loader) throws ClassNotFoundException {
        java.util.logging.Logger root = java.util.logging.Logger.getLogger("");
        synchronized (java.util.logging.LogManager.getLogManager()) {
            java.util.logging.Level level = root.getLevel();
            java.util.logging.Handler[] handlers = root.getHandlers();
            java.util.logging.Level[] levels = new java.util.logging.Level[handlers.length];
            for (int i = 0; i < handlers.length; i++) {
                levels[i] = handlers[i].getLevel();
            }
            Class<?> type = Class.forName(className, true, loader);
            if (root.getLevel() != level || !java.util.Arrays.equals(root.getHandlers(), handlers)) {
                for (java.util.logging.Handler h : root.getHandlers()) {
                    root.removeHandler(h);
                }
                for (int i = 0; i < handlers.length; i++) {
                    handlers[i].setLevel(levels[i]);
                    root.addHandler(handlers[i]);
                }
                root.setLevel(level);
            }
            return type;
        }
    }

    /** {@code jfuzzylite} or {@code jfuzzylite:JAR}, driven by {@link JavaIut}. */
    static ImplementationUnderTest open(String spec, IutOptions options) throws IutException {
        String rest = spec.substring(SPEC.length());
        URLClassLoader own = null;
        ClassLoader loader;
        if (rest.isEmpty()) {
            loader = JfuzzyliteImplementation.class.getClassLoader();
        } else {
            String jar = rest.startsWith(":") ? rest.substring(1).strip() : "";
            if (jar.isEmpty()) {
                throw new IutException(Kind.INFRA, "malformed implementation under test '" + spec
                        + "': use jfuzzylite (found on the class path) or jfuzzylite:PATH-TO-JAR");
            }
            Path path = Path.of(jar);
            if (!Files.isRegularFile(path)) {
                throw new IutException(Kind.INFRA, "jfuzzylite jar " + jar + " does not exist"
                        + " (it is com.fuzzylite:jfuzzylite:6.0.1 on Maven Central)");
            }
            try {
                // the platform loader as parent: jfuzzylite sees the JDK only, never fclcert's own classes
                own = new URLClassLoader("fclcert-jfuzzylite", new URL[] {path.toAbsolutePath().toUri().toURL()},
                        ClassLoader.getPlatformClassLoader());
            } catch (MalformedURLException e) {
                throw new IutException(Kind.INFRA, "bad jar path " + jar + ": " + e.getMessage());
            }
            loader = own;
        }
        try {
            return JavaIut.wrap(spec, options, new JfuzzyliteImplementation(loader), own);
        } catch (ReflectiveOperationException | LinkageError e) {
            close(own);
            throw new IutException(Kind.INFRA, "jfuzzylite was not found " + (own == null
                    ? "on the class path (give its jar: --iut jfuzzylite:PATH; it is com.fuzzylite:jfuzzylite:6.0.1 on Maven Central)"
                    : "in " + rest.substring(1).strip()) + " (" + e + ")");
        }
    }

    private static void close(URLClassLoader loader) {
        if (loader != null) {
            try {
                loader.close();
            } catch (IOException e) {
                // nothing more to free
            }
        }
    }

    /** The Maven version the jar was built as (6.0.1); the library's own constant says only 6.0. */
    private static Optional<String> artifactVersion(ClassLoader loader) {
        try (InputStream in = loader.getResourceAsStream("META-INF/maven/com.fuzzylite/jfuzzylite/pom.properties")) {
            if (in == null) {
                return Optional.empty();
            }
            Properties p = new Properties();
            p.load(in);
            return Optional.ofNullable(p.getProperty("version"));
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    @Override
    public String name() {
        return "jfuzzylite";
    }

    @Override
    public String version() {
        return version;
    }

    @Override
    public FclLoadResult load(String fcl) {
        Object engine;
        try {
            engine = importEngine(fcl);
        } catch (Rejection r) {
            return FclLoadResult.rejected("jfuzzylite: " + r.getMessage(), r.line.orElse(0));
        }
        return FclLoadResult.loaded(new Program(fcl, engine));
    }

    /** A clean refusal by jfuzzylite, with the line its message names. */
    private static final class Rejection extends Exception {
        private static final long serialVersionUID = 1L;
        private final transient OptionalInt line;

        Rejection(String message, OptionalInt line) {
            super(message, null, false, false);
            this.line = line;
        }
    }

    /**
     * Imports the text. A deliberate refusal becomes a {@link Rejection}; any other throwable is rethrown as
     * it is, which {@link JavaIut} records as a crash.
     */
    private Object importEngine(String fcl) throws Rejection {
        try {
            return fromString.invoke(importer, fcl);
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause.getClass() == RuntimeException.class) {
                String message = String.valueOf(cause.getMessage());
                throw new Rejection(message, LibraryMessages.fuzzyliteLine(message, fcl));
            }
            if (cause instanceof NumberFormatException) {
                throw new Rejection("cannot read a number: " + cause.getMessage(), OptionalInt.empty());
            }
            throw internal("reading the program", cause);
        } catch (IllegalAccessException e) {
            throw new LibraryFailure("jfuzzylite's FclImporter.fromString cannot be called: " + e, e);
        }
    }

    /** The library failed inside: rethrown so that the harness records a crash, never a rejection. */
    static Error internal(String what, Throwable cause) {
        if (cause instanceof Error error) {
            throw error;
        }
        if (cause instanceof RuntimeException runtime) {
            return new LibraryFailure("jfuzzylite failed internally while " + what + ": " + describe(runtime), runtime);
        }
        return new LibraryFailure("jfuzzylite failed internally while " + what + ": " + describe(cause), cause);
    }

    private static String describe(Throwable t) {
        return t.getClass().getName() + (t.getMessage() == null ? "" : ": " + t.getMessage());
    }

    /**
     * An internal failure of a library under an adapter. An {@link Error}, so that {@link JavaIut} records a
     * crash wherever it is thrown (a runtime exception from {@code evaluate} would read as a refusal).
     */
    static final class LibraryFailure extends Error {
        private static final long serialVersionUID = 1L;

        LibraryFailure(String message, Throwable cause) {
            super(message, cause);
        }
    }

    private Object invoke(Object target, String method, Object... args) {
        try {
            Class<?>[] types = new Class<?>[args.length];
            for (int k = 0; k < args.length; k++) {
                types[k] = args[k] instanceof Double ? double.class : args[k].getClass();
            }
            Method m = target.getClass().getMethod(method, types);
            return m.invoke(target, args);
        } catch (InvocationTargetException e) {
            if (e.getCause().getClass() == RuntimeException.class) {
                // jfuzzylite's deliberate refusal to compute: an evaluation error, not a crash
                throw new IllegalStateException("jfuzzylite: " + e.getCause().getMessage(), e.getCause());
            }
            throw internal("calling " + method, e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new LibraryFailure("jfuzzylite has no usable " + method + ": " + e, e);
        }
    }

    /** The names of the function blocks as written (comments dropped); jfuzzylite builds the first only. */
    static List<String> blocksWritten(String fcl) {
        List<String> names = new ArrayList<>();
        Matcher m = BLOCK.matcher(COMMENT.matcher(fcl).replaceAll(" "));
        while (m.find()) {
            names.add(m.group(1));
        }
        return names;
    }

    private final class Program implements FclProgram {
        private final String fcl;
        private final Object firstEngine;
        private final List<String> blocks;

        Program(String fcl, Object engine) {
            this.fcl = fcl;
            this.firstEngine = engine;
            List<String> written = blocksWritten(fcl);
            List<String> names = new ArrayList<>();
            names.add(String.valueOf(invoke(engine, "getName")));
            for (int k = 1; k < written.size(); k++) {
                names.add(written.get(k));
            }
            this.blocks = List.copyOf(names);
        }

        @Override
        public List<String> blocks() {
            return blocks;
        }

        @Override
        public FclInstance newInstance(String block) {
            if (Names.same(block, blocks.get(0))) {
                return new Instance(fcl);
            }
            return new Unbuilt(block, blocks.get(0));
        }

        @Override
        public Optional<String> export() {
            try {
                return Optional.of(String.valueOf(exportText.invoke(exporter, firstEngine)));
            } catch (InvocationTargetException e) {
                throw internal("exporting FCL", e.getCause());
            } catch (IllegalAccessException e) {
                throw new LibraryFailure("jfuzzylite's FclExporter cannot be called: " + e, e);
            }
        }
    }

    /** A function block after the first: jfuzzylite never built it, so every evaluation is refused. */
    private static final class Unbuilt implements FclInstance {
        private final String message;

        Unbuilt(String block, String first) {
            message = "jfuzzylite builds only the first function block of a program ('" + first + "'), not '"
                    + block + "'";
        }

        @Override
        public void set(String name, double value) {
            throw new IllegalStateException(message);
        }

        @Override
        public void evaluate() {
            throw new IllegalStateException(message);
        }

        @Override
        public double get(String name) {
            throw new IllegalStateException(message);
        }

        @Override
        public void reset() {
            // nothing was built
        }
    }

    /** One engine imported afresh from the text, inputs at 0; reset imports it again. */
    private final class Instance implements FclInstance {
        private final String fcl;
        private Object engine;
        private List<?> inputs;
        private List<?> outputs;

        Instance(String fcl) {
            this.fcl = fcl;
            reset();
        }

        @Override
        public void set(String name, double value) {
            invoke(variable(inputs, name, "input"), "setValue", value);
        }

        @Override
        public void evaluate() {
            invoke(engine, "process");
        }

        @Override
        public double get(String name) {
            return (Double) invoke(variable(outputs, name, "output"), "getValue");
        }

        @Override
        public void reset() {
            try {
                engine = importEngine(fcl);
            } catch (Rejection r) {
                throw new LibraryFailure("jfuzzylite refused on a second import the program it had loaded: "
                        + r.getMessage(), r);
            }
            inputs = (List<?>) invoke(engine, "getInputVariables");
            outputs = (List<?>) invoke(engine, "getOutputVariables");
            // jfuzzylite starts every variable at NaN; an instance starts with its inputs at their initial value,
            // which for the REAL inputs jfuzzylite reads (it rejects declared initial values) is 0
            for (Object input : inputs) {
                invoke(input, "setValue", 0.0);
            }
        }

        /** jfuzzylite's names are case-sensitive; FCL's are not. */
        private Object variable(List<?> variables, String name, String kind) {
            List<String> names = new ArrayList<>();
            for (Object v : variables) {
                String declared = String.valueOf(invoke(v, "getName"));
                if (Names.same(declared, name)) {
                    return v;
                }
                names.add(declared);
            }
            throw new IllegalArgumentException("'" + name + "' is not an " + kind + " of the engine jfuzzylite built"
                    + " (its " + kind + "s: " + String.join(", ", names) + ")");
        }
    }
}
