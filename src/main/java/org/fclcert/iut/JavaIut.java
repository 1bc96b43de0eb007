package org.fclcert.iut;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.iut.spi.FclImplementation;
import org.fclcert.iut.spi.FclInstance;
import org.fclcert.iut.spi.FclLoadResult;
import org.fclcert.iut.spi.FclProgram;
import org.fclcert.model.Names;

/**
 * A vendor's Java implementation behind the SPI of {@link org.fclcert.iut.spi}. Every vendor call runs
 * on a worker thread under the per-request timeout. A call that hangs is abandoned with its worker and
 * its instances (the next eval makes new ones from the loaded program); each such abandonment counts
 * against the restart budget. An exception from vendor code never escapes: from set/evaluate/get it is
 * an {@link Kind#EVAL_ERROR}, anywhere else (and any {@link Error}) a {@link Kind#CRASH}.
 */
final class JavaIut implements ImplementationUnderTest {
    private final String spec;
    private final IutOptions options;
    private final URLClassLoader loader;
    private FclImplementation vendor;
    private ExecutorService worker = newWorker();
    private int abandoned;
    private String lastFailure = "";
    private String unisolated = "a built-in adapter called inside fclcert's own JVM, with fclcert's rights";

    private String programText;
    private FclProgram program;
    private List<String> blocks = List.of();
    private final Map<String, FclInstance> instances = new HashMap<>();
    private final Map<String, List<String>> outputs = new HashMap<>();

    private JavaIut(String spec, IutOptions options, URLClassLoader loader) {
        this.spec = spec;
        this.options = options;
        this.loader = loader;
    }

    static JavaIut open(String spec, String className, IutOptions options) throws IutException {
        if (className.isEmpty()) {
            throw new IutException(Kind.INFRA, "java: needs a class name, as in java:com.example.MyFcl");
        }
        URLClassLoader loader = options.classpath().isEmpty() ? null : classLoader(options.classpath());
        JavaIut iut = new JavaIut(spec, options, loader);
        try {
            Class<? extends FclImplementation> type = implementationClass(className, loader);
            iut.vendor = iut.call("the constructor of " + className, () -> construct(type), Kind.INFRA);
            iut.unisolated = "--in-process: the java: implementation was called inside fclcert's own JVM, with"
                    + " fclcert's rights (not in the sandbox)";
            return iut;
        } catch (IutException e) {
            iut.close();
            throw e.kind() == Kind.INFRA ? e : new IutException(Kind.INFRA, e.getMessage());
        }
    }

    /**
     * A built-in adapter that already is an {@link FclImplementation} (for example {@link JfuzzyliteImplementation}),
     * driven with the same worker thread, timeout and restart budget as a vendor's class. {@code loader}, when
     * not null, is closed with the session.
     */
    static JavaIut wrap(String spec, IutOptions options, FclImplementation adapter, URLClassLoader loader) {
        JavaIut iut = new JavaIut(spec, options, loader);
        iut.vendor = adapter;
        return iut;
    }

    private static URLClassLoader classLoader(List<Path> classpath) throws IutException {
        URL[] urls = new URL[classpath.size()];
        for (int k = 0; k < urls.length; k++) {
            try {
                urls[k] = classpath.get(k).toAbsolutePath().toUri().toURL();
            } catch (MalformedURLException e) {
                throw new IutException(Kind.INFRA, "bad classpath entry " + classpath.get(k) + ": " + e.getMessage());
            }
        }
        // the parent is fclcert's own loader, so the vendor's classes see the one SPI fclcert calls
        return new URLClassLoader("fclcert-iut", urls, JavaIut.class.getClassLoader());
    }

    static Class<? extends FclImplementation> implementationClass(String name, URLClassLoader loader)
            throws IutException {
        Class<?> type;
        try {
            type = Class.forName(name, false, loader == null ? JavaIut.class.getClassLoader() : loader);
        } catch (ClassNotFoundException | LinkageError e) {
            throw new IutException(Kind.INFRA, "class " + name + " was not found on the classpath"
                    + (loader == null ? "" : " " + List.of(loader.getURLs())) + " (" + e + ")");
        }
        if (!FclImplementation.class.isAssignableFrom(type)) {
            throw new IutException(Kind.INFRA, "class " + name + " does not implement " + FclImplementation.class.getName());
        }
        return type.asSubclass(FclImplementation.class);
    }

    /** Whether {@code type} can be constructed as fclcert constructs it, found without running any of its code. */
    static void checkConstructible(Class<? extends FclImplementation> type) throws IutException {
        if (java.lang.reflect.Modifier.isAbstract(type.getModifiers())) {
            throw new IutException(Kind.INFRA, "class " + type.getName() + " cannot be instantiated (abstract?)");
        }
        try {
            type.getConstructor();
        } catch (NoSuchMethodException e) {
            throw new IutException(Kind.INFRA, "class " + type.getName() + " needs a public constructor without arguments");
        }
    }

    private static FclImplementation construct(Class<? extends FclImplementation> type) throws IutException {
        try {
            return type.getConstructor().newInstance();
        } catch (NoSuchMethodException | IllegalAccessException e) {
            throw new IutException(Kind.INFRA, "class " + type.getName() + " needs a public constructor without arguments");
        } catch (InstantiationException e) {
            throw new IutException(Kind.INFRA, "class " + type.getName() + " cannot be instantiated (abstract?)");
        } catch (InvocationTargetException e) {
            throw new IutException(Kind.INFRA, "the constructor of " + type.getName() + " threw " + describe(e.getCause()));
        }
    }

    @Override
    public IutInfo hello() throws IutException {
        return call("hello", () -> new IutInfo(vendor.name(), vendor.version(), spec, vendor.claims(), vendor.limits()),
                Kind.CRASH);
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        program = null;
        programText = null;
        blocks = List.of();
        instances.clear();
        outputs.clear();
        FclLoadResult result = call("load", () -> vendor.load(fcl), Kind.CRASH);
        if (result instanceof FclLoadResult.Rejected rejected) {
            return new LoadOutcome.Rejected(rejected.message(), rejected.line());
        }
        if (!(result instanceof FclLoadResult.Loaded loaded)) {
            throw new IutException(Kind.CRASH, "load returned null");
        }
        List<String> names = call("blocks", () -> List.copyOf(loaded.program().blocks()), Kind.CRASH);
        program = loaded.program();
        programText = fcl;
        blocks = names;
        return new LoadOutcome.Loaded(names);
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        String name = blockName(block);
        FclInstance instance = instance(name);
        List<String> names = outputs.computeIfAbsent(Names.key(name), k -> DeclaredOutputs.of(programText, name));
        return call("eval", () -> evaluate(instance, inputs, names), Kind.CRASH);
    }

    private static Map<String, Double> evaluate(FclInstance instance, Map<String, Double> inputs, List<String> outputs)
            throws IutException {
        try {
            inputs.forEach(instance::set);
            instance.evaluate();
            Map<String, Double> values = new LinkedHashMap<>();
            for (String output : outputs) {
                values.put(output, instance.get(output));
            }
            return values;
        } catch (RuntimeException e) {
            throw new IutException(Kind.EVAL_ERROR, "the implementation refused to evaluate: " + describe(e));
        }
    }

    private String blockName(String block) throws IutException {
        if (program == null) {
            throw new IutException(Kind.EVAL_ERROR, "no program is loaded");
        }
        if (block == null) {
            if (blocks.isEmpty()) {
                throw new IutException(Kind.EVAL_ERROR, "the loaded program has no function block");
            }
            return blocks.get(0);
        }
        return blocks.stream().filter(b -> Names.same(b, block)).findFirst()
                .orElseThrow(() -> new IutException(Kind.EVAL_ERROR, "the program has no function block " + block));
    }

    private FclInstance instance(String block) throws IutException {
        FclInstance instance = instances.get(Names.key(block));
        if (instance == null) {
            FclProgram loaded = program;
            instance = call("newInstance", () -> loaded.newInstance(block), Kind.CRASH);
            if (instance == null) {
                throw new IutException(Kind.CRASH, "newInstance(" + block + ") returned null");
            }
            instances.put(Names.key(block), instance);
        }
        return instance;
    }

    @Override
    public void reset() throws IutException {
        for (FclInstance instance : List.copyOf(instances.values())) {
            call("reset", () -> {
                instance.reset();
                return null;
            }, Kind.CRASH);
        }
    }

    @Override
    public Optional<String> export() throws IutException {
        if (program == null) {
            throw new IutException(Kind.EVAL_ERROR, "no program is loaded");
        }
        FclProgram loaded = program;
        Optional<String> text = call("export", loaded::export, Kind.CRASH);
        return text == null ? Optional.empty() : text;
    }

    @Override
    public org.fclcert.sandbox.Isolation isolation() {
        return org.fclcert.sandbox.Isolation.inProcess(unisolated);
    }

    @Override
    public void close() {
        worker.shutdownNow();
        if (loader != null) {
            try {
                loader.close();
            } catch (IOException e) {
                // nothing more to free
            }
        }
    }

    /**
     * Runs one vendor call on the worker under the timeout. Our own {@link IutException}s pass through;
     * anything else the vendor throws becomes {@code failure}.
     */
    private <T> T call(String what, Callable<T> action, Kind failure) throws IutException {
        if (abandoned > options.restartBudget()) {
            throw new IutException(Kind.GAVE_UP, "stopped after " + options.restartBudget()
                    + " abandoned calls (the restart budget); last failure: " + lastFailure);
        }
        Future<T> future = worker.submit(action);
        try {
            return future.get(options.timeout().toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            abandon(future);
            lastFailure = what + " did not return within " + options.timeout().toMillis() + " ms";
            throw new IutException(Kind.TIMEOUT, lastFailure);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof IutException own) {
                throw own;
            }
            Kind kind = e.getCause() instanceof Error ? Kind.CRASH : failure;
            throw new IutException(kind, what + " threw " + describe(e.getCause()));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            abandon(future);
            throw new IutException(Kind.INFRA, "interrupted while waiting for " + what);
        }
    }

    /** Gives up on a hung call: its thread and the instances it may be using are never touched again. */
    private void abandon(Future<?> future) {
        future.cancel(true);
        worker.shutdownNow();
        worker = newWorker();
        instances.clear();
        abandoned++;
    }

    private static ExecutorService newWorker() {
        return Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "fclcert-java-iut");
            t.setDaemon(true);
            return t;
        });
    }

    private static String describe(Throwable t) {
        return t.getClass().getSimpleName() + (t.getMessage() == null ? "" : ": " + t.getMessage());
    }
}
