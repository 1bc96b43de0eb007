package org.fclcert.lsp;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ScheduledFuture;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;

/**
 * The open documents: for each its current text and version, the {@link Snapshot} of that version once made, and
 * the one diagnostics run waiting for the debounce. Nothing else is kept, so the state is bounded by the open
 * documents whatever the number of edits: an edit replaces the text and drops the old snapshot, a close forgets
 * the document. Thread-safe (one lock).
 */
final class Documents {
    private static final class Open {
        /** The text with its line starts, kept from one version to the next (an edit moves them). */
        SourceText source;
        int version;
        Snapshot snapshot;
        /** auto's choice, while it is known to hold for the text (edits that cannot change it keep it). */
        Optional<DialectReaders.Detection> detection = Optional.empty();
        ScheduledFuture<?> pending;
        String shownNote;

        Open(String text, int version) {
            this.source = new SourceText(text);
            this.version = version;
        }
    }

    private final Map<String, Open> open = new HashMap<>();
    private Optional<Dialect> dialect = Optional.empty();

    synchronized void open(String uri, String text, int version) {
        Open old = open.put(uri, new Open(text == null ? "" : text, version));
        cancel(old);
    }

    /** Applies changes in order (whole text, or a range in the protocol's positions); false for a document not open. */
    synchronized boolean change(String uri, int version, List<TextDocumentContentChangeEvent> changes) {
        Open d = open.get(uri);
        if (d == null) {
            return false;
        }
        SourceText src = d.source;
        Optional<DialectReaders.Detection> detection = d.detection;
        for (TextDocumentContentChangeEvent c : changes) {
            String inserted = c.getText() == null ? "" : c.getText();
            if (c.getRange() == null) {
                src = new SourceText(inserted);
                detection = Optional.empty();
            } else {
                int from = src.offset(c.getRange().getStart());
                int to = Math.max(from, src.offset(c.getRange().getEnd()));
                String before = src.text();
                detection = detection.filter(k -> DialectReaders.kept(k, before, from, to, inserted));
                src = src.edited(from, to, inserted);
            }
        }
        d.source = src;
        d.detection = detection;
        d.version = version;
        d.snapshot = null;
        return true;
    }

    synchronized void close(String uri) {
        cancel(open.remove(uri));
    }

    /** The snapshot of a document's current version, read now if it is not yet. */
    Optional<Snapshot> snapshot(String uri) {
        Open d;
        SourceText text;
        int version;
        Optional<Dialect> in;
        Optional<DialectReaders.Detection> known;
        synchronized (this) {
            d = open.get(uri);
            if (d == null) {
                return Optional.empty();
            }
            if (d.snapshot != null) {
                return Optional.of(d.snapshot);
            }
            text = d.source;
            version = d.version;
            in = dialect;
            known = d.detection;
        }
        // read outside the lock: edits keep arriving while a large text is checked
        Snapshot s = Snapshot.read(uri, version, text, in, known);
        synchronized (this) {
            if (open.get(uri) == d && d.version == version && d.source == text && dialect.equals(in)) {
                d.snapshot = s;
                d.detection = s.detection();
            }
        }
        return Optional.of(s);
    }

    /** True when the snapshot is of the document's current version and dialect. */
    synchronized boolean current(Snapshot s) {
        Open d = open.get(s.uri());
        return d != null && d.version == s.version() && (d.snapshot == s || d.snapshot == null);
    }

    /** Records the run that will publish diagnostics, cancelling the one waiting before. */
    synchronized void pending(String uri, ScheduledFuture<?> run) {
        Open d = open.get(uri);
        if (d == null) {
            run.cancel(false);
            return;
        }
        cancel(d);
        d.pending = run;
    }

    /** True the first time a document is read with this dialect note (so it is shown once, not on every edit). */
    synchronized boolean newNote(String uri, String note) {
        Open d = open.get(uri);
        if (d == null || note.equals(d.shownNote)) {
            return false;
        }
        d.shownNote = note;
        return true;
    }

    synchronized void dialect(Optional<Dialect> dialect) {
        this.dialect = dialect;
        open.values().forEach(d -> {
            d.snapshot = null;
            d.detection = Optional.empty();
        });
    }

    synchronized Optional<Dialect> dialect() {
        return dialect;
    }

    synchronized List<String> uris() {
        return new ArrayList<>(open.keySet());
    }

    /** How many documents are open (the state the server keeps grows with this number only). */
    synchronized int size() {
        return open.size();
    }

    /** How many diagnostics runs wait (at most one per open document). */
    synchronized int waiting() {
        return (int) open.values().stream().filter(d -> d.pending != null && !d.pending.isDone()).count();
    }

    private static void cancel(Open d) {
        if (d != null && d.pending != null) {
            d.pending.cancel(false);
        }
    }
}
