package org.fclcert.iut;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * Drains a process's standard error on its own thread and keeps only the last bytes, so a noisy IUT
 * never blocks on a full pipe and never fills fclcert's memory.
 */
final class StderrTail {
    private final byte[] ring;
    private final Thread drainer;
    private long written;

    StderrTail(InputStream stderr, int capacity, String threadName) {
        this.ring = new byte[capacity];
        this.drainer = new Thread(() -> drain(stderr), threadName);
        drainer.setDaemon(true);
        drainer.start();
    }

    private void drain(InputStream in) {
        byte[] chunk = new byte[8192];
        try (in) {
            int n;
            while ((n = in.read(chunk)) >= 0) {
                append(chunk, n);
            }
        } catch (IOException e) {
            // the pipe closed under us because the process was killed: nothing more to keep
        }
    }

    private synchronized void append(byte[] chunk, int n) {
        if (ring.length == 0) {
            return;
        }
        for (int k = Math.max(0, n - ring.length); k < n; k++) {
            ring[(int) ((written + k) % ring.length)] = chunk[k];
        }
        written += n;
    }

    /** Waits (at most {@code millis}) until the process's stderr has been read to its end. */
    void awaitEnd(long millis) {
        try {
            drainer.join(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The kept end of the stream, decoded as UTF-8 (a character cut at the start shows as U+FFFD). */
    synchronized String text() {
        int size = (int) Math.min(written, ring.length);
        byte[] out = new byte[size];
        long start = written - size;
        for (int k = 0; k < size; k++) {
            out[k] = ring[(int) ((start + k) % ring.length)];
        }
        return new String(out, StandardCharsets.UTF_8);
    }
}
