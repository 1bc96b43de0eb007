package org.fclcert.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ThreadLocalRandom;
import java.util.stream.Stream;

/**
 * The one way fclcert launches code it did not write: every process implementation and every library bridge
 * asks {@link #processBuilder(List)} for its process, so each new adapter gets the same isolation by using it.
 *
 * <p>With the sandbox on and bubblewrap working, the command runs in fresh PID, network, IPC, UTS and mount
 * namespaces (and a user namespace where fclcert is not root): no network but a loopback of its own; the system
 * ({@code /usr}, {@code /etc} and the top-level links into {@code /usr}) read-only; a private, empty {@code /tmp},
 * home and working directory, each a size-capped tmpfs that ends with the sandbox; fclcert's home, the checkout,
 * the corpus and the output directory absent; the environment cleared but for {@code PATH}, the locale and the
 * time zone; the whole process tree killed when the launch ends (PID namespace, die with parent). The files the
 * command names and the installation they come from are bound read-only at their own paths ({@link Binds}).
 * As root, the command runs as a fresh unprivileged uid without capabilities (root is exempt from the process
 * limit, and a uid of its own per launch keeps launches from counting against each other).
 *
 * <p>Where bubblewrap is missing or cannot make namespaces, or the sandbox is switched off, the command runs
 * as a plain process and {@link #isolation()} says so, for the terminal and every report.
 */
public final class Sandbox {
    static final String INSTALL_HINT = "install bubblewrap (Debian/Ubuntu: apt-get install bubblewrap;"
            + " Fedora: dnf install bubblewrap) or pass --no-sandbox to run without isolation";
    /** First uid of the range a root launch picks its unprivileged uid from (far above any account). */
    private static final int UID_BASE = 1_500_000_000;
    private static final int UID_SPAN = 100_000_000;
    private static final List<String> ENVIRONMENT = List.of("PATH", "LANG", "LC_ALL", "LC_CTYPE", "TZ", "PYENV_VERSION");
    static final String HOME = "/tmp/home";

    private final SandboxSettings settings;
    private final Engine engine;
    /** The unprivileged uid a root launch runs as, one per sandbox (so per implementation session). */
    private final int uid = UID_BASE + ThreadLocalRandom.current().nextInt(UID_SPAN);

    private Sandbox(SandboxSettings settings, Engine engine) {
        this.settings = settings;
        this.engine = engine;
    }

    /**
     * Makes a directory of fclcert's own writable for the sandboxed command (as root the command runs as another
     * uid, so the directory is given to it; otherwise nothing is needed).
     */
    public void grantWrite(Path dir) throws IOException {
        if (active() && engine.root()) {
            Files.setAttribute(dir, "unix:uid", uid);
            Files.setAttribute(dir, "unix:gid", uid);
        }
    }

    /** A sandbox of these settings; finds and tries bubblewrap once per JVM when the settings enable it. */
    public static Sandbox of(SandboxSettings settings) {
        return new Sandbox(settings, settings.enabled() ? Engine.probe() : null);
    }

    public SandboxSettings settings() {
        return settings;
    }

    public Limits limits() {
        return settings.limits();
    }

    /** Whether launches are really sandboxed. */
    public boolean active() {
        return engine != null && engine.works();
    }

    /** What the certificate records. */
    public Isolation isolation() {
        if (!settings.enabled()) {
            return new Isolation(Isolation.Kind.DISABLED, "none: --no-sandbox was given, so the implementation"
                    + " ran as a plain process of the user, with the user's files, network and environment");
        }
        if (!engine.works()) {
            return new Isolation(Isolation.Kind.UNAVAILABLE, "none: " + engine.problem() + "; the implementation ran"
                    + " as a plain process of the user; " + INSTALL_HINT);
        }
        return new Isolation(Isolation.Kind.SANDBOX, "bubblewrap " + engine.version() + " sandbox: own PID, network,"
                + " IPC and mount namespaces" + (engine.root() ? ", an unprivileged uid without capabilities"
                : ", an own user namespace") + "; the system read-only; private /tmp, home and working directory;"
                + " no access to the user's home, the checkout, the corpus or the output directory; limits: "
                + settings.limits().describe());
    }

    /**
     * A process builder for a long-lived {@code command} (a session answering many requests): inside the sandbox
     * when it is active, else the command itself. Its CPU time is counted per request by its driver.
     */
    public ProcessBuilder processBuilder(List<String> command) throws IOException {
        return new ProcessBuilder(command(command, List.of(), false));
    }

    /**
     * A process builder for a launch that answers one request and ends (the fuzzylite command line): the CPU
     * limit per request is its RLIMIT_CPU, and {@code writable} directories (fclcert's own fresh exchange
     * directory for the launch's files) are bound read-write.
     */
    public ProcessBuilder oneRequest(List<String> command, List<Path> writable) throws IOException {
        return new ProcessBuilder(command(command, writable, true));
    }

    /**
     * {@code command} as it is launched: wrapped in bubblewrap with the limits when the sandbox is active, else
     * unchanged.
     *
     * @throws IOException when the program the command names cannot be found
     */
    public List<String> command(List<String> command) throws IOException {
        return command(command, List.of(), false);
    }

    private List<String> command(List<String> command, List<Path> writable, boolean oneRequest) throws IOException {
        if (command.isEmpty()) {
            throw new IOException("empty command");
        }
        if (!active()) {
            return List.copyOf(command);
        }
        Path cwd = Path.of("").toAbsolutePath().normalize();
        Path program = Binds.program(command.get(0), cwd, System.getenv("PATH"))
                .orElseThrow(() -> new IOException("cannot find the program '" + command.get(0) + "'"));
        List<String> target = new ArrayList<>(command);
        target.set(0, program.toString());
        return wrap(target, Binds.forCommand(program, command.subList(1, command.size()), cwd, home(), settings),
                writable, oneRequest);
    }

    private List<String> wrap(List<String> target, Binds binds, List<Path> writable, boolean oneRequest) {
        // a little above the file size limit, so a single big file meets that limit (SIGXFSZ, named) first
        long size = settings.limits().fileSizeBytes() + (64L << 20);
        List<String> a = new ArrayList<>(List.of(engine.bwrap().toString()));
        if (!engine.root()) {
            a.add("--unshare-user");
            if (engine.disablesUserns()) {
                a.add("--disable-userns");   // bubblewrap 0.8 and later: no nested user namespace either
            }
        }
        a.addAll(List.of("--unshare-pid", "--unshare-net", "--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try",
                "--die-with-parent", "--new-session", "--hostname", "fclcert-sandbox"));
        binds.system().forEach(s -> a.addAll(s));
        a.addAll(List.of("--proc", "/proc", "--dev", "/dev"));
        a.addAll(tmpfs("/tmp", size));
        a.addAll(List.of("--perms", "0777", "--dir", HOME));
        home().filter(h -> !h.toString().equals("/")).ifPresent(h -> a.addAll(List.of("--tmpfs", h.toString())));
        String workdir = binds.workingDirectory().toString();
        if (!workdir.startsWith("/tmp/")) {
            a.addAll(tmpfs(workdir, size));
        } else {
            a.addAll(List.of("--perms", "1777", "--dir", workdir));
        }
        // directories bubblewrap makes on the way to a bind are private to root: make them traversable first
        java.util.Set<Path> made = new java.util.HashSet<>(List.of(Path.of("/"), Path.of("/tmp"), Path.of(HOME),
                Path.of(workdir)));
        home().ifPresent(made::add);
        List<Path> bound = new ArrayList<>();
        binds.system().stream().filter(s -> s.get(0).equals("--ro-bind")).forEach(s -> bound.add(Path.of(s.get(2))));
        for (Path p : binds.readOnly()) {
            a.addAll(mountPoint(p, made, bound));
            a.addAll(List.of("--ro-bind", p.toString(), p.toString()));
        }
        for (Path p : writable) {
            a.addAll(mountPoint(p, made, bound));
            a.addAll(List.of("--bind", p.toString(), p.toString()));
        }
        for (Path p : binds.masked()) {
            a.addAll(List.of("--tmpfs", p.toString()));
        }
        a.addAll(List.of("--chdir", workdir, "--clearenv", "--setenv", "HOME", HOME, "--setenv", "TMPDIR", "/tmp"));
        Map<String, String> env = System.getenv();
        for (String name : ENVIRONMENT) {
            if (env.containsKey(name)) {
                a.addAll(List.of("--setenv", name, env.get(name)));
            }
        }
        if (engine.root()) {
            // setpriv needs these to leave root; it drops them (and the bounding set) before the command runs
            a.addAll(List.of("--cap-add", "CAP_SETUID", "--cap-add", "CAP_SETGID", "--cap-add", "CAP_SETPCAP"));
        }
        a.add("--");
        Limits limits = settings.limits();
        a.addAll(List.of(engine.prlimit().toString(), "--data=" + limits.memoryBytes(),
                "--nproc=" + limits.processes(), "--fsize=" + limits.fileSizeBytes(), "--core=0"));
        if (oneRequest) {
            a.add("--cpu=" + Math.max(1, (limits.cpuPerRequest().toMillis() + 999) / 1000));
        }
        a.add("--");
        if (engine.root()) {
            a.addAll(List.of(engine.setpriv().toString(), "--reuid=" + uid, "--regid=" + uid, "--clear-groups",
                    "--inh-caps=-all", "--bounding-set=-all", "--"));
        }
        a.addAll(target);
        return a;
    }

    /** {@code --dir} for each directory above {@code p} that the sandbox does not have yet (made readable to all). */
    private static List<String> mountPoint(Path p, java.util.Set<Path> made, List<Path> bound) {
        List<String> a = new ArrayList<>();
        for (int n = 1; n < p.getNameCount(); n++) {
            Path above = p.getRoot().resolve(p.subpath(0, n));
            if (bound.stream().anyMatch(above::startsWith)) {
                return a;
            }
            if (made.add(above)) {
                a.addAll(List.of("--perms", "0755", "--dir", above.toString()));
            }
        }
        bound.add(p);
        return a;
    }

    private static List<String> tmpfs(String path, long size) {
        return List.of("--perms", "1777", "--size", Long.toString(size), "--tmpfs", path);
    }

    private static java.util.Optional<Path> home() {
        String home = System.getProperty("user.home");
        if (home == null || home.isBlank()) {
            return java.util.Optional.empty();
        }
        Path p = Path.of(home).toAbsolutePath().normalize();
        return Files.isDirectory(p) ? java.util.Optional.of(p) : java.util.Optional.empty();
    }

    /**
     * CPU time used so far by a launched process and every process of its tree that is alive (user and system
     * time of all their threads); what the per-request CPU limit is measured on.
     */
    public static Duration cpuTime(ProcessHandle root) {
        return Stream.concat(Stream.of(root), root.descendants())
                .map(p -> p.info().totalCpuDuration().orElse(Duration.ZERO))
                .reduce(Duration.ZERO, Duration::plus);
    }

    /** The message for a launch that ended on a signal a limit sends, or empty (exit codes 128 + signal). */
    public java.util.Optional<String> limitHit(long exitCode) {
        if (!active()) {
            return java.util.Optional.empty();
        }
        if (exitCode == 128 + 25) {
            return java.util.Optional.of("it was stopped by the sandbox's file size limit of "
                    + Limits.bytes(settings.limits().fileSizeBytes()) + " (SIGXFSZ)");
        }
        if (exitCode == 128 + 24) {
            return java.util.Optional.of("it was stopped by the sandbox's CPU time limit of "
                    + settings.limits().cpuPerRequest().toSeconds() + " s per request (SIGXCPU)");
        }
        return java.util.Optional.empty();
    }

    /** Where the engine's programs are, found once per JVM. */
    record Engine(Path bwrap, Path prlimit, Path setpriv, boolean root, String version, boolean disablesUserns,
            String problem) {
        private static Engine probed;

        boolean works() {
            return problem == null;
        }

        static synchronized Engine probe() {
            if (probed == null) {
                probed = find();
            }
            return probed;
        }

        private static Engine find() {
            String path = System.getenv("PATH");
            Path cwd = Path.of("").toAbsolutePath();
            java.util.Optional<Path> bwrap = Binds.program("bwrap", cwd, path);
            java.util.Optional<Path> prlimit = Binds.program("prlimit", cwd, path);
            java.util.Optional<Path> setpriv = Binds.program("setpriv", cwd, path);
            boolean root = isRoot();
            if (bwrap.isEmpty()) {
                return broken(root, "bubblewrap (bwrap) is not installed");
            }
            if (prlimit.isEmpty() || (root && setpriv.isEmpty())) {
                return broken(root, "prlimit or setpriv (util-linux) is not installed");
            }
            String version = run(List.of(bwrap.get().toString(), "--version")).strip().replace("bubblewrap ", "");
            boolean disables = run(List.of(bwrap.get().toString(), "--help")).contains("--disable-userns");
            Engine engine = new Engine(bwrap.get(), prlimit.get(), setpriv.orElse(null), root, version, disables, null);
            Path truth = Path.of("/bin/true");
            try {
                Sandbox trial = new Sandbox(SandboxSettings.defaults(), engine);
                Process p = new ProcessBuilder(trial.command(List.of(truth.toString()))).redirectErrorStream(true)
                        .start();
                p.getOutputStream().close();
                String said = new String(p.getInputStream().readNBytes(4096)).strip();
                if (!p.waitFor(20, java.util.concurrent.TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                    return broken(root, "bubblewrap did not start a sandbox within 20 s");
                }
                if (p.exitValue() != 0) {
                    return broken(root, "bubblewrap cannot make a sandbox here (" + said + "; are user namespaces"
                            + " disabled?)");
                }
            } catch (IOException e) {
                return broken(root, "bubblewrap could not be started (" + e.getMessage() + ")");
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return broken(root, "interrupted while trying bubblewrap");
            }
            return engine;
        }

        private static Engine broken(boolean root, String problem) {
            return new Engine(null, null, null, root, "", false, problem);
        }

        private static String run(List<String> command) {
            try {
                Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
                p.getOutputStream().close();
                String out = new String(p.getInputStream().readNBytes(4096));
                p.waitFor(10, java.util.concurrent.TimeUnit.SECONDS);
                return out;
            } catch (IOException e) {
                return "";
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return "";
            }
        }

        /** Whether fclcert runs as root (the real uid from /proc, Linux being the only home of bubblewrap). */
        private static boolean isRoot() {
            try {
                for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                    if (line.startsWith("Uid:")) {
                        return line.substring(4).strip().split("\\s+")[0].equals("0");
                    }
                }
            } catch (IOException | InvalidPathException | ArrayIndexOutOfBoundsException e) {
                // not Linux: bubblewrap will not be found either
            }
            return "root".equals(System.getProperty("user.name"));
        }
    }
}
