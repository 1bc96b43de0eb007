package org.fclcert.sandbox;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

/**
 * What a sandboxed command sees of the host's files, worked out from the command itself.
 *
 * <ul>
 *   <li>The system: {@code /usr}, {@code /etc} and the top-level directories or links {@code /bin}, {@code /sbin},
 *       {@code /lib*}, read-only.</li>
 *   <li>The program's installation: the directory above {@code bin} for a program in a {@code bin} directory
 *       ({@code /opt/jdk/bin/java} → {@code /opt/jdk}), else its directory; for a program under the home
 *       directory in a hidden directory there, that whole directory ({@code ~/.pyenv}, {@code ~/.sdkman},
 *       {@code ~/.nvm}: interpreters found through shims). The same for the program's real path.</li>
 *   <li>Every argument (or part of a class path, or value after {@code =}) that names an existing file: its
 *       directory (a script's modules lie next to it); one that names a directory: that directory.</li>
 *   <li>Never a protected directory — the root, the home directory, the working directory, an ancestor of any of
 *       them or of a hidden path: there only the named file itself is bound.</li>
 *   <li>The shared libraries a native program links against outside the system (an rpath into a build directory),
 *       as {@code ldd} lists them: their directory (only the file where the directory is protected).</li>
 *   <li>Files the user binds with {@code --sandbox-bind}.</li>
 * </ul>
 *
 * @param system           bubblewrap arguments for the system parts, one list per part
 * @param workingDirectory where the command starts: the host's working directory path (a private, empty tmpfs
 *                         there, so relative paths in the command resolve to the same bound files), or a
 *                         directory under the private {@code /tmp} where that path cannot be covered
 * @param readOnly         files and directories bound read-only at their own paths, parents before children
 * @param masked           hidden directories that lie inside a bound part, covered with an empty tmpfs
 */
record Binds(List<List<String>> system, Path workingDirectory, List<Path> readOnly, List<Path> masked) {
    private static final List<String> SYSTEM_DIRS = List.of("/usr", "/etc", "/bin", "/sbin", "/lib", "/lib32",
            "/lib64", "/libx32");

    static Binds forCommand(Path program, List<String> arguments, Path cwd, Optional<Path> home,
            SandboxSettings settings) {
        List<List<String>> system = new ArrayList<>();
        List<Path> systemRoots = new ArrayList<>();
        for (String dir : SYSTEM_DIRS) {
            Path p = Path.of(dir);
            if (Files.isSymbolicLink(p)) {
                try {
                    system.add(List.of("--symlink", Files.readSymbolicLink(p).toString(), dir));
                } catch (IOException e) {
                    // unreadable link: leave the name out
                }
            } else if (Files.isDirectory(p)) {
                system.add(List.of("--ro-bind", dir, dir));
                systemRoots.add(p);
            }
        }
        Set<Path> protectedDirs = new TreeSet<>();
        protectedDirs.add(Path.of("/"));
        List<Path> guarded = new ArrayList<>(List.of(cwd));
        home.ifPresent(guarded::add);
        settings.hidden().forEach(h -> guarded.add(h.toAbsolutePath().normalize()));
        for (Path g : guarded) {
            for (Path p = g; p != null; p = p.getParent()) {
                protectedDirs.add(p);
            }
        }
        Set<Path> binds = new TreeSet<>();
        for (Path p : List.of(program, real(program))) {
            Path install = installation(p, home);
            binds.add(protectedDirs.contains(install) ? p : install);
        }
        for (String argument : arguments) {
            for (String part : parts(argument)) {
                existing(part, cwd).ifPresent(p -> {
                    if (Files.isDirectory(p)) {
                        if (!protectedDirs.contains(p)) {
                            binds.add(p);
                        }
                    } else {
                        Path dir = p.getParent();
                        binds.add(dir == null || protectedDirs.contains(dir) ? p : dir);
                    }
                    Path realPath = real(p);
                    if (!realPath.equals(p) && !protectedDirs.contains(realPath)) {
                        binds.add(realPath);
                    }
                });
            }
        }
        for (Path library : sharedLibraries(real(program))) {
            // a library outside the system (an rpath into a build directory): its directory, or the file alone
            if (systemRoots.stream().noneMatch(library::startsWith)) {
                Path dir = library.getParent();
                binds.add(dir == null || protectedDirs.contains(dir) ? library : dir);
            }
        }
        for (Path extra : settings.readOnly()) {
            Path p = extra.toAbsolutePath().normalize();
            if (Files.exists(p)) {
                binds.add(p);
            }
        }
        List<Path> readOnly = new ArrayList<>();
        for (Path p : binds) {   // sorted, so a parent comes before its children: keep only the outermost
            boolean covered = systemRoots.stream().anyMatch(p::startsWith)
                    || readOnly.stream().anyMatch(q -> p.startsWith(q));
            if (!covered) {
                readOnly.add(p);
            }
        }
        List<Path> masked = new ArrayList<>();
        for (Path h : settings.hidden()) {
            Path p = h.toAbsolutePath().normalize();
            boolean inside = systemRoots.stream().anyMatch(p::startsWith) || readOnly.stream().anyMatch(p::startsWith);
            if (inside && Files.isDirectory(p)) {
                masked.add(p);
            }
        }
        boolean coverable = cwd.getParent() != null && systemRoots.stream().noneMatch(cwd::startsWith)
                && readOnly.stream().noneMatch(cwd::startsWith);
        Path workingDirectory = coverable ? cwd : Path.of("/tmp/work");
        return new Binds(List.copyOf(system), workingDirectory, List.copyOf(readOnly), List.copyOf(masked));
    }

    private static final java.util.regex.Pattern LIBRARY = java.util.regex.Pattern.compile(
            "^\\s*(?:\\S+\\s+=>\\s+)?(/\\S+)\\s+\\(0x[0-9a-f]+\\)\\s*$");

    /**
     * The shared libraries a native program links against, as {@code ldd} resolves them (their real paths); empty
     * for a script or where {@code ldd} is missing or fails. glibc's {@code ldd} lists them through the system's
     * dynamic loader in its tracing mode, which maps the libraries without running the program or their code.
     */
    static List<Path> sharedLibraries(Path program) {
        if (!isElf(program)) {
            return List.of();
        }
        Optional<Path> ldd = program("ldd", Path.of("/"), System.getenv("PATH"));
        if (ldd.isEmpty()) {
            return List.of();
        }
        List<Path> libraries = new ArrayList<>();
        try {
            Process p = new ProcessBuilder(ldd.get().toString(), program.toString()).redirectErrorStream(true).start();
            p.getOutputStream().close();
            String out = new String(p.getInputStream().readNBytes(1 << 20), java.nio.charset.StandardCharsets.UTF_8);
            if (!p.waitFor(10, java.util.concurrent.TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return List.of();
            }
            for (String line : out.split("\n")) {
                java.util.regex.Matcher m = LIBRARY.matcher(line);
                if (m.matches()) {
                    libraries.add(real(Path.of(m.group(1)).normalize()));
                }
            }
        } catch (IOException | InvalidPathException e) {
            return List.of();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return List.of();
        }
        return libraries;
    }

    private static boolean isElf(Path file) {
        try (java.io.InputStream in = Files.newInputStream(file)) {
            byte[] magic = in.readNBytes(4);
            return magic.length == 4 && magic[0] == 0x7f && magic[1] == 'E' && magic[2] == 'L' && magic[3] == 'F';
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /** The program's absolute path: as given when it has a slash, else the first match on {@code PATH}. */
    static Optional<Path> program(String name, Path cwd, String path) {
        try {
            if (name.contains("/")) {
                Path p = cwd.resolve(name).normalize();
                return Files.isExecutable(p) && !Files.isDirectory(p) ? Optional.of(p) : Optional.empty();
            }
            for (String dir : (path == null ? "" : path).split(File.pathSeparator)) {
                if (dir.isEmpty()) {
                    continue;
                }
                Path p = cwd.resolve(dir).resolve(name).normalize();
                if (Files.isExecutable(p) && !Files.isDirectory(p)) {
                    return Optional.of(p);
                }
            }
        } catch (InvalidPathException e) {
            // not a name a file can have
        }
        return Optional.empty();
    }

    /** Where a program comes from: see the class comment. */
    static Path installation(Path program, Optional<Path> home) {
        if (home.isPresent() && program.startsWith(home.get()) && program.getNameCount() > home.get().getNameCount() + 1) {
            Path first = home.get().resolve(program.getName(home.get().getNameCount()));
            if (first.getFileName().toString().startsWith(".")) {
                return first;
            }
        }
        Path dir = program.getParent();
        if (dir != null && dir.getFileName() != null && dir.getFileName().toString().equals("bin")
                && dir.getParent() != null) {
            return dir.getParent();
        }
        return dir == null ? program : dir;
    }

    /** The pieces of an argument that may name files: itself, the parts of a class path, the value after '='. */
    private static List<String> parts(String argument) {
        List<String> parts = new ArrayList<>(List.of(argument));
        int eq = argument.indexOf('=');
        String value = eq >= 0 ? argument.substring(eq + 1) : argument;
        if (eq >= 0) {
            parts.add(value);
        }
        if (value.contains(File.pathSeparator)) {
            parts.addAll(List.of(value.split(File.pathSeparator)));
        }
        return parts;
    }

    private static Optional<Path> existing(String name, Path cwd) {
        if (name.isEmpty() || name.length() > 4096) {
            return Optional.empty();
        }
        try {
            Path p = cwd.resolve(name).normalize();
            return Files.exists(p) ? Optional.of(p) : Optional.empty();
        } catch (InvalidPathException e) {
            return Optional.empty();
        }
    }

    private static Path real(Path p) {
        try {
            return p.toRealPath();
        } catch (IOException e) {
            return p;
        }
    }
}
