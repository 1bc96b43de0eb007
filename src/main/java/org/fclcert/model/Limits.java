package org.fclcert.model;

/**
 * Documented implementation limits of fclcert, shared by the reader and the checks so that both
 * agree. Table 11 lets each system state its own limits; the standard sets none. These are
 * fclcert's, far above anything a controller needs and well below what would exhaust the stack.
 */
public final class Limits {
    /**
     * Deepest nesting of parentheses in one rule condition: {@code (a)} has depth 1, {@code ((a))}
     * depth 2. The strict reader rejects deeper nesting with FCL-S008 before parsing (so the
     * recursive parser never sees it); check FCL-C026 uses the same number for programs built by
     * other readers.
     */
    public static final int MAX_NESTING_DEPTH = 1_000;

    /**
     * Errors a reader reports for one file (the strict reader, each dialect reader): the rest are summarised in one
     * last error ("too many errors"), so that one early mistake cannot bury the user in follow-up messages and the
     * diagnostics kept stay small on any input. Check findings are not capped: each names one offending place of a
     * program that has read without error.
     */
    public static final int MAX_ERRORS_PER_FILE = 25;

    /** Warnings of one code the strict reader reports for one file before it summarises the rest in one. */
    public static final int MAX_WARNINGS_PER_CODE = 25;

    /**
     * Largest file fclcert reads, in bytes (128 MiB): a program, a CSV table, a corpus case, a results file, a
     * report. Only regular files are read (not devices, FIFOs or directories), so {@code /dev/zero} or a pipe
     * that never ends gets a plain error instead of exhausting memory or hanging. {@link #readFile} enforces it.
     */
    public static final long MAX_SOURCE_BYTES = 128L * 1024 * 1024;

    private Limits() {
    }

    /** A file fclcert does not read: {@link #getMessage()} is the reason, a phrase ("it is a directory"). */
    public static final class Unreadable extends java.io.IOException {
        private static final long serialVersionUID = 1L;

        Unreadable(String reason) {
            super(reason);
        }
    }

    /**
     * The bytes of a regular file of at most {@link #MAX_SOURCE_BYTES}, also when it grows while it is read. A
     * directory, a device, a FIFO or a larger file is {@link Unreadable}, found before the file is opened
     * (opening a FIFO blocks, and {@code /dev/zero} never ends); other I/O failures pass through.
     */
    public static byte[] readFile(java.nio.file.Path p) throws java.io.IOException {
        if (java.nio.file.Files.isDirectory(p)) {
            throw new Unreadable("it is a directory");
        }
        if (java.nio.file.Files.exists(p) && !java.nio.file.Files.isRegularFile(p)) {
            throw new Unreadable("not a regular file (a device, pipe or socket); fclcert reads only files");
        }
        if (java.nio.file.Files.size(p) > MAX_SOURCE_BYTES) {
            throw tooLarge();
        }
        try (java.io.InputStream in = java.nio.file.Files.newInputStream(p)) {
            byte[] bytes = in.readNBytes((int) MAX_SOURCE_BYTES + 1);
            if (bytes.length > MAX_SOURCE_BYTES) {
                throw tooLarge();
            }
            return bytes;
        }
    }

    private static Unreadable tooLarge() {
        return new Unreadable("larger than fclcert's limit of " + MAX_SOURCE_BYTES / (1024 * 1024)
                + " MiB (org.fclcert.model.Limits.MAX_SOURCE_BYTES)");
    }
}
