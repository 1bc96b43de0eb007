package org.fclcert.orchestration;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.Comparator;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;
import java.util.stream.Stream;
import org.fclcert.orchestration.Certification.CannotCertify;

/**
 * One run's hold on its output directory: a lock that a second run into the same directory finds at once (it
 * refuses, naming the first and its pid), and a private sibling directory the run writes into, whose files are
 * moved into place when the run ends. A run killed outright leaves the directory as it was (and its partial
 * results in the sibling); nothing another process does to the directory during the run mixes into its outputs.
 *
 * <p>The lock is {@code .<name>.lock} next to the directory (the directory itself is replaced file by file, so
 * it cannot hold its own lock); it is an OS file lock, released by the kernel when the process ends, so a killed
 * run never leaves a stale lock. The file stays, holding the last holder's pid.
 */
public final class OutputDirectory implements AutoCloseable {
    private final Path dir;
    private final Path staging;
    private final FileChannel lockFile;
    private final FileLock lock;

    private OutputDirectory(Path dir, Path staging, FileChannel lockFile, FileLock lock) {
        this.dir = dir;
        this.staging = staging;
        this.lockFile = lockFile;
        this.lock = lock;
    }

    /** Locks {@code dir} for this run and makes the private sibling it writes into. */
    static OutputDirectory claim(Path dir) throws CannotCertify {
        Lock lock;
        try {
            lock = lock(dir);
        } catch (InUse e) {
            throw new CannotCertify(e.getMessage());
        }
        Path target = dir.toAbsolutePath().normalize();
        try {
            Path staging = target.getParent().resolve("." + target.getFileName() + ".partial-"
                    + ProcessHandle.current().pid() + "-" + Long.toHexString(ThreadLocalRandom.current().nextLong() >>> 1));
            Files.createDirectory(staging);   // fails on anything already there, a planted link included
            return new OutputDirectory(dir, staging, lock.channel, lock.lock);   // named as given, e.g. in "Reports: …"
        } catch (IOException e) {
            lock.close();
            throw new CannotCertify("cannot lock the output directory " + target + ": " + e.getMessage());
        }
    }

    /**
     * Locks {@code dir} for one run of a command that writes into it ({@code certify}, {@code probe --out},
     * {@code fuzz --out}): {@code .<name>.lock} beside it, held until {@link Lock#close()} or the process ends.
     *
     * @throws InUse when another run holds it (the message names that run's pid and start), or it cannot be made
     */
    public static Lock lock(Path dir) throws InUse {
        Path target = dir.toAbsolutePath().normalize();
        Path parent = target.getParent();
        if (parent == null || target.getFileName() == null) {
            throw new InUse("the output directory cannot be the file system's root");
        }
        String name = target.getFileName().toString();
        FileChannel channel = null;
        try {
            Files.createDirectories(parent);
            Path lockPath = parent.resolve("." + name + ".lock");
            channel = FileChannel.open(lockPath, StandardOpenOption.CREATE, StandardOpenOption.READ,
                    StandardOpenOption.WRITE, LinkOption.NOFOLLOW_LINKS);
            FileLock lock;
            try {
                lock = channel.tryLock();
            } catch (OverlappingFileLockException e) {
                lock = null;   // this very JVM holds it: another run of the same process
            }
            if (lock == null) {
                String holder = holder(channel);
                channel.close();
                throw new InUse("the output directory " + target + " is in use by another fclcert run ("
                        + holder + "); wait for it to end or give another --out");
            }
            String me = "pid " + ProcessHandle.current().pid() + ", started " + Instant.now();
            channel.truncate(0);
            channel.write(ByteBuffer.wrap((me + "\n").getBytes(StandardCharsets.UTF_8)), 0);
            channel.force(false);
            return new Lock(channel, lock);
        } catch (IOException e) {
            close(channel);
            throw new InUse("cannot lock the output directory " + target + ": " + e.getMessage());
        }
    }

    /** A run's hold on an output directory; released by {@link #close()} (or by the kernel when the process ends). */
    public static final class Lock implements AutoCloseable {
        private final FileChannel channel;
        private final FileLock lock;

        private Lock(FileChannel channel, FileLock lock) {
            this.channel = channel;
            this.lock = lock;
        }

        @Override
        public void close() {
            release(lock, channel);
        }
    }

    /** The output directory is held by another run, or its lock cannot be made; the message says which. */
    public static final class InUse extends Exception {
        private static final long serialVersionUID = 1L;

        InUse(String message) {
            super(message);
        }
    }

    private static String holder(FileChannel channel) {
        try {
            ByteBuffer bytes = ByteBuffer.allocate(200);
            channel.read(bytes, 0);
            String text = new String(bytes.array(), 0, bytes.position(), StandardCharsets.UTF_8).strip();
            return text.isEmpty() ? "its pid not yet written" : text.replaceAll("\\p{Cntrl}", "?");
        } catch (IOException e) {
            return "its lock file cannot be read: " + e.getMessage();
        }
    }

    /** Where this run writes its outputs until {@link #publish}. */
    Path staging() {
        return staging;
    }

    /** The directory the outputs end up in, as the run was given it. */
    Path target() {
        return dir;
    }

    /**
     * Moves every file written into place (each file replaced atomically; the reports and transcripts of the run
     * before are removed first, so none of them stays beside this run's), and removes the private sibling.
     */
    void publish(java.util.List<String> replacedNames, String transcripts) throws IOException {
        Files.createDirectories(dir);
        for (String old : replacedNames) {
            Files.deleteIfExists(dir.resolve(old));
        }
        Path oldTranscripts = dir.resolve(transcripts);
        if (Files.isDirectory(oldTranscripts, LinkOption.NOFOLLOW_LINKS)) {
            try (DirectoryStream<Path> files = Files.newDirectoryStream(oldTranscripts, "*.requests.jsonl")) {
                for (Path f : files) {
                    Files.deleteIfExists(f);
                }
            }
        }
        try (Stream<Path> written = Files.walk(staging)) {
            for (Path from : written.sorted().toList()) {
                Path to = dir.resolve(staging.relativize(from).toString());
                if (Files.isDirectory(from, LinkOption.NOFOLLOW_LINKS)) {
                    Files.createDirectories(to);
                } else {
                    Files.move(from, to, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
                }
            }
        }
        delete(staging);
    }

    /** Releases the lock (the private sibling of a run that never published stays, with its partial results). */
    @Override
    public void close() {
        release(lock, lockFile);
    }

    private static void release(FileLock lock, FileChannel channel) {
        try {
            lock.release();
        } catch (IOException e) {
            // closing the channel releases it as well
        }
        close(channel);
    }

    private static void close(FileChannel channel) {
        if (channel != null) {
            try {
                channel.close();
            } catch (IOException e) {
                // nothing more to release
            }
        }
    }

    private static void delete(Path dir) throws IOException {
        if (!Files.exists(dir, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }

    /**
     * A directory of the system's temporary directory private to this user ({@code fclcert-reports-<user>}, mode
     * 700), for the runs of selected cases; never one that is a link or that another user owns or can write —
     * then a fresh private directory of the temporary directory instead.
     */
    static Path privateScratch(Path tmp, String user) throws IOException {
        Set<PosixFilePermission> ownerOnly = PosixFilePermissions.fromString("rwx------");
        Path p = tmp.resolve("fclcert-reports-" + user.replaceAll("[^A-Za-z0-9._-]", "_"));
        try {
            Files.createDirectory(p, PosixFilePermissions.asFileAttribute(ownerOnly));
            return p;
        } catch (java.nio.file.FileAlreadyExistsException e) {
            // there already: used only when it is a real directory of this user, closed to everyone else
        } catch (UnsupportedOperationException e) {
            return Files.createDirectories(p);   // not a POSIX file system: no other users' links to fear
        }
        boolean safe;
        try {
            var attrs = Files.readAttributes(p, java.nio.file.attribute.PosixFileAttributes.class,
                    LinkOption.NOFOLLOW_LINKS);
            safe = attrs.isDirectory() && !attrs.isSymbolicLink()
                    && attrs.owner().getName().equals(user) && attrs.permissions().equals(ownerOnly);
        } catch (IOException | UnsupportedOperationException e) {
            safe = false;
        }
        return safe ? p : Files.createTempDirectory(tmp, "fclcert-reports-");
    }
}
