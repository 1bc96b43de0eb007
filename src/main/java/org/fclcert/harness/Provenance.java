package org.fclcert.harness;

import com.fasterxml.jackson.annotation.JsonInclude;
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
import java.util.stream.Stream;
import org.fclcert.iut.CommandLineSplitter;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.model.Toolkit;

/**
 * Where a run's results come from, as fclcert measured it (in the run header, and so in every report): the run
 * seed; this fclcert (version, git commit, the sha256 of its jar); the corpus (its digest and whether it is the
 * built-in one); the machine (OS, JVM); and the implementation — for {@code process:} the executable the command
 * resolves to and the sha256 of every file the command names, for {@code java:} the sha256 of every class path
 * entry, for the built-in adapters the library's jar or binary — beside the name and version it gives itself,
 * which are its claim, not a measurement.
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record Provenance(String seed, ToolkitBuild toolkit, CorpusIdentity corpus, String os, String jvm,
        IutIdentity iut) {

    /** fclcert itself: its version, the commit it was built from ("unknown" outside a checkout), its jar. */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record ToolkitBuild(String version, String commit, String jar, String jarSha256) {
    }

    /**
     * The corpus: {@code builtIn} when it is the corpus built into this fclcert; {@code description} how the
     * headline names it; {@code missingBasic} and {@code missingExtension} the built-in Basic and Extension Level
     * cases a custom corpus does not hold unchanged (its Basic verdict, or its Table 9 verdicts, are then not
     * determined).
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record CorpusIdentity(String sha256, boolean builtIn, String description, List<String> missingBasic,
            List<String> missingExtension) {
        public CorpusIdentity {
            missingBasic = missingBasic == null ? List.of() : List.copyOf(missingBasic);
            missingExtension = missingExtension == null ? List.of() : List.copyOf(missingExtension);
        }

        public CorpusIdentity(String sha256, boolean builtIn, String description, List<String> missingBasic) {
            this(sha256, builtIn, description, missingBasic, List.of());
        }
    }

    /** One file that identifies the implementation, and its sha256 (or why there is none). */
    public record FileHash(String path, String sha256) {
    }

    /**
     * The implementation: {@code claimedName}/{@code claimedVersion} as it introduced itself (a claim);
     * {@code kind} of spec; {@code executable} what a {@code process:} command resolves to; {@code files} the
     * hashes fclcert measured.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record IutIdentity(String claimedName, String claimedVersion, String kind, String executable,
            List<FileHash> files) {
        public IutIdentity {
            files = files == null ? List.of() : List.copyOf(files);
        }
    }

    /** The provenance of a run about to start. */
    public static Provenance of(long seed, IutInfo info, String spec, List<Path> classpath, CorpusIdentity corpus) {
        return new Provenance(RunSeed.text(seed), thisToolkit(), corpus,
                System.getProperty("os.name") + " " + System.getProperty("os.version") + " ("
                        + System.getProperty("os.arch") + ")",
                System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version", 
                        System.getProperty("java.version")) + " (" + System.getProperty("java.vendor") + ")",
                identify(info, spec, classpath));
    }

    static ToolkitBuild thisToolkit() {
        Optional<Path> code = codeSource(Provenance.class);
        String jar = code.map(Path::toString).orElse("unknown");
        String hash = code.filter(Files::isRegularFile).map(Provenance::sha256).orElse(
                code.isPresent() ? "not a jar (classes directory)" : "unknown");
        return new ToolkitBuild(Toolkit.version(), code.flatMap(Provenance::gitCommit).orElse("unknown"), jar, hash);
    }

    static IutIdentity identify(IutInfo info, String spec, List<Path> classpath) {
        String s = spec.strip();
        List<FileHash> files = new ArrayList<>();
        String executable = null;
        String kind;
        if (s.equals("reference")) {
            kind = "reference (fclcert's own evaluator, in this fclcert)";
        } else if (s.startsWith("java:")) {
            kind = "java";
            if (classpath == null || classpath.isEmpty()) {
                codeSource(Provenance.class).ifPresent(p -> files.add(hash(p)));
            } else {
                classpath.forEach(p -> files.add(hash(p)));
            }
        } else if (s.startsWith("process:")) {
            kind = "process";
            try {
                List<String> command = CommandLineSplitter.split(s.substring("process:".length()));
                if (!command.isEmpty()) {
                    Optional<Path> exe = onPath(command.get(0));
                    executable = exe.map(Path::toString).orElse(command.get(0) + " (not found)");
                    exe.ifPresent(p -> files.add(hash(p)));
                    for (String arg : command.subList(1, command.size())) {
                        Path p = Path.of(arg).toAbsolutePath();
                        if (arg.length() < 4096 && Files.isRegularFile(p)) {
                            files.add(hash(p));
                        }
                    }
                }
            } catch (IutException | RuntimeException e) {
                executable = "(the command cannot be split: " + e.getMessage() + ")";
            }
        } else {
            kind = "built-in adapter " + s.replaceFirst(":.*", "");
            int colon = s.indexOf(':');
            if (colon > 0) {
                Path p = Path.of(s.substring(colon + 1)).toAbsolutePath();
                if (Files.exists(p)) {
                    files.add(hash(p));
                }
            } else if (s.equals("fuzzylite")) {
                onPath("fuzzylite").ifPresent(p -> files.add(hash(p)));
            } else {
                library("com.fuzzylite.Engine").ifPresent(p -> files.add(hash(p)));
            }
        }
        return new IutIdentity(info.name(), info.version(), kind, executable, files);
    }

    private static Optional<Path> library(String className) {
        try {
            return codeSource(Class.forName(className, false, Provenance.class.getClassLoader()));
        } catch (ClassNotFoundException | LinkageError e) {
            return Optional.empty();
        }
    }

    private static Optional<Path> codeSource(Class<?> c) {
        try {
            var src = c.getProtectionDomain().getCodeSource();
            return src == null ? Optional.empty() : Optional.of(Path.of(src.getLocation().toURI()));
        } catch (Exception e) {
            return Optional.empty();
        }
    }

    /** The file a command's first word runs: itself when it has a '/', else the first match on PATH; resolved. */
    static Optional<Path> onPath(String name) {
        try {
            if (name.contains("/")) {
                Path p = Path.of(name);
                return Files.isRegularFile(p) ? Optional.of(p.toRealPath()) : Optional.empty();
            }
            for (String dir : System.getenv().getOrDefault("PATH", "").split(java.io.File.pathSeparator)) {
                Path p = Path.of(dir.isEmpty() ? "." : dir, name);
                if (Files.isRegularFile(p) && Files.isExecutable(p)) {
                    return Optional.of(p.toRealPath());
                }
            }
        } catch (IOException | RuntimeException e) {
            return Optional.empty();
        }
        return Optional.empty();
    }

    /** A file's sha256, a directory's digest over its files (relative path, zero byte, bytes; in path order). */
    static FileHash hash(Path p) {
        Path real;
        try {
            real = p.toRealPath();
        } catch (IOException e) {
            return new FileHash(p.toString(), "missing");
        }
        if (Files.isRegularFile(real)) {
            return new FileHash(real.toString(), sha256(real));
        }
        if (Files.isDirectory(real)) {
            try (Stream<Path> walk = Files.walk(real)) {
                MessageDigest d = MessageDigest.getInstance("SHA-256");
                for (Path f : walk.filter(Files::isRegularFile).sorted().toList()) {
                    d.update(real.relativize(f).toString().replace('\\', '/').getBytes(StandardCharsets.UTF_8));
                    d.update((byte) 0);
                    d.update(Files.readAllBytes(f));
                }
                return new FileHash(real + "/", "directory " + HexFormat.of().formatHex(d.digest()));
            } catch (IOException | NoSuchAlgorithmException | RuntimeException e) {
                return new FileHash(real + "/", "unreadable: " + e.getMessage());
            }
        }
        return new FileHash(real.toString(), "not a file");
    }

    /** The sha256 of a file, in hex ("unreadable: …" when it cannot be read). */
    public static String sha256(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            MessageDigest d = MessageDigest.getInstance("SHA-256");
            byte[] buffer = new byte[1 << 16];
            for (int n; (n = in.read(buffer)) > 0;) {
                d.update(buffer, 0, n);
            }
            return HexFormat.of().formatHex(d.digest());
        } catch (IOException | NoSuchAlgorithmException e) {
            return "unreadable: " + e.getMessage();
        }
    }

    /** The commit of the git checkout {@code code} lies in (HEAD, following one symbolic ref), if any. */
    static Optional<String> gitCommit(Path code) {
        try {
            for (Path dir = code.toAbsolutePath(); dir != null; dir = dir.getParent()) {
                Path git = dir.resolve(".git");
                if (Files.isRegularFile(git)) {   // a worktree: "gitdir: PATH"
                    String line = Files.readString(git).strip();
                    if (!line.startsWith("gitdir:")) {
                        return Optional.empty();
                    }
                    git = dir.resolve(line.substring("gitdir:".length()).strip());
                }
                if (Files.isDirectory(git)) {
                    return headOf(git);
                }
            }
        } catch (IOException | RuntimeException e) {
            return Optional.empty();
        }
        return Optional.empty();
    }

    private static Optional<String> headOf(Path git) throws IOException {
        String head = Files.readString(git.resolve("HEAD")).strip();
        if (!head.startsWith("ref:")) {
            return Optional.of(head);
        }
        String ref = head.substring(4).strip();
        Path common = git;
        Path commondir = git.resolve("commondir");
        if (Files.isRegularFile(commondir)) {
            common = git.resolve(Files.readString(commondir).strip()).normalize();
        }
        for (Path base : List.of(git, common)) {
            Path loose = base.resolve(ref);
            if (Files.isRegularFile(loose)) {
                return Optional.of(Files.readString(loose).strip());
            }
        }
        Path packed = common.resolve("packed-refs");
        if (Files.isRegularFile(packed)) {
            for (String line : Files.readAllLines(packed)) {
                if (line.endsWith(" " + ref)) {
                    return Optional.of(line.substring(0, line.indexOf(' ')));
                }
            }
        }
        return Optional.empty();
    }
}
