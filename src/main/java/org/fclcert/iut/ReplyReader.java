package org.fclcert.iut;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * Reads a process's standard output on its own thread and hands over one line at a time. A line
 * longer than the limit is not kept: the reader reports it as too long at once (so the caller can
 * kill the process without waiting for the rest) and skips to the next newline.
 */
final class ReplyReader {
    /** What the reader saw on stdout. */
    sealed interface Event {}

    /** A line, with the {@link System#nanoTime} at which the read that completed it returned. */
    record Line(String text, long readAt) implements Event {}

    record TooLong(int limit) implements Event {}

    record EndOfStream() implements Event {}

    record WriteFailed(String reason) implements Event {}

    // a few lines at most: the protocol has one reply in flight, anything more is a fault anyway
    private final BlockingQueue<Event> events = new LinkedBlockingQueue<>(4);
    private final int maxLineBytes;
    private final ByteArrayOutputStream line = new ByteArrayOutputStream();
    private final Thread reader;
    private boolean skipping;
    /** When the chunk being scanned was read: a line is as old as the read that brought its end. */
    private long chunkReadAt;

    ReplyReader(InputStream stdout, int maxLineBytes, String threadName) {
        this.maxLineBytes = maxLineBytes;
        this.reader = new Thread(() -> read(stdout), threadName);
        reader.setDaemon(true);
        reader.start();
    }

    /** Frees the reader thread if it waits for room to hand over a line nobody will take any more. */
    void stop() {
        reader.interrupt();
    }

    /** The next event, or null when none came within the time. */
    Event next(long nanos) throws InterruptedException {
        return events.poll(nanos, TimeUnit.NANOSECONDS);
    }

    /** Lets the writer report a failed request into the same stream of events. */
    void writeFailed(String reason) {
        events.offer(new WriteFailed(reason));
    }

    private void read(InputStream in) {
        byte[] chunk = new byte[65536];
        try (in) {
            int n;
            while ((n = in.read(chunk)) >= 0) {
                chunkReadAt = System.nanoTime();
                scan(chunk, n);
            }
        } catch (IOException e) {
            // closed because the process was killed: report the end below
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        }
        try {
            // put, not offer: with lines still waiting to be taken, the end must not be lost (it tells a crash
            // from a hang); stop() frees this thread when nobody takes events any more
            events.put(new EndOfStream());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void scan(byte[] chunk, int n) throws InterruptedException {
        int start = 0;
        for (int k = 0; k < n; k++) {
            if (chunk[k] == '\n') {
                take(chunk, start, k - start);
                endLine();
                start = k + 1;
            }
        }
        take(chunk, start, n - start);
    }

    private void take(byte[] chunk, int from, int len) throws InterruptedException {
        if (skipping || len == 0) {
            return;
        }
        if (line.size() + len > maxLineBytes) {
            skipping = true;
            line.reset();
            events.put(new TooLong(maxLineBytes));
            return;
        }
        line.write(chunk, from, len);
    }

    private void endLine() throws InterruptedException {
        if (!skipping) {
            String text = line.toString(StandardCharsets.UTF_8);
            events.put(new Line(text.endsWith("\r") ? text.substring(0, text.length() - 1) : text, chunkReadAt));
        }
        skipping = false;
        line.reset();
    }
}
