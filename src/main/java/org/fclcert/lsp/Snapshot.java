package org.fclcert.lsp;

import java.net.URI;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.fclcert.check.Analysis;
import org.fclcert.model.Program;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.ReadResult;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;

/**
 * One version of a document, read and checked once: exactly what {@code fclcert check} finds in the same text
 * with the same dialect, the program to navigate (the repaired one after a one-token slip) and, built on first
 * use, the {@link Outline} of its tokens. Immutable once made.
 */
final class Snapshot {
    private final String uri;
    private final int version;
    private final SourceText source;
    private final String sourceName;
    private final Dialect dialect;
    private final String dialectNote;
    private final Analysis analysis;
    private final Optional<Program> program;
    private final Optional<DialectReaders.Detection> detection;
    private volatile Outline outline;

    private Snapshot(String uri, int version, SourceText source, String sourceName, Dialect dialect, String dialectNote,
            Analysis analysis, Optional<Program> program, Optional<DialectReaders.Detection> detection) {
        this.uri = uri;
        this.version = version;
        this.source = source;
        this.sourceName = sourceName;
        this.dialect = dialect;
        this.dialectNote = dialectNote;
        this.analysis = analysis;
        this.program = program;
        this.detection = detection;
    }

    /**
     * Reads and checks a text: in {@code dialect}, or, when empty, in the dialect {@code --dialect auto} picks; that
     * choice is {@code known} when it is known to hold for this text ({@link DialectReaders#kept}), else detected.
     */
    static Snapshot read(String uri, int version, String text, Optional<Dialect> dialect,
            Optional<DialectReaders.Detection> known) {
        return read(uri, version, new SourceText(text), dialect, known);
    }

    /** The same of a text whose line starts are known. */
    static Snapshot read(String uri, int version, SourceText source, Optional<Dialect> dialect,
            Optional<DialectReaders.Detection> known) {
        String text = source.text();
        String name = sourceName(uri);
        FclReader reader;
        Dialect read;
        String note;
        DialectReaders.Detection detection = null;
        if (dialect.isPresent()) {
            read = dialect.get();
            reader = DialectReaders.reader(read);
            note = "read as " + read.displayName() + " (setting fclcert.dialect)";
        } else {
            detection = known.orElseGet(() -> DialectReaders.detect(text));
            DialectReaders.Choice choice = detection.choice();
            read = choice.dialect();
            reader = choice.reader();
            note = choice.explanation() + " (dialect auto)";
        }
        ReadResult result = reader.read(name, text);
        Analysis analysis = Analysis.of(result);
        return new Snapshot(uri, version, source, name, read, note, analysis,
                result.program().or(result::repaired), Optional.ofNullable(detection));
    }

    /** How {@code auto} chose the dialect of this text; empty when the dialect was set. */
    Optional<DialectReaders.Detection> detection() {
        return detection;
    }

    /** The name check would print for the document: its file path, or the URI when it is no file. */
    static String sourceName(String uri) {
        try {
            URI u = new URI(uri);
            if ("file".equalsIgnoreCase(u.getScheme())) {
                return Path.of(u).toString();
            }
        } catch (Exception e) {
            // not a file URI: the URI itself names the document
        }
        return uri;
    }

    String uri() {
        return uri;
    }

    int version() {
        return version;
    }

    SourceText source() {
        return source;
    }

    String text() {
        return source.text();
    }

    String sourceName() {
        return sourceName;
    }

    Dialect dialect() {
        return dialect;
    }

    /** One line saying which dialect the text was read in and why. */
    String dialectNote() {
        return dialectNote;
    }

    /** What {@code fclcert check} reports for the text. */
    Analysis analysis() {
        return analysis;
    }

    List<org.fclcert.model.Diagnostic> diagnostics() {
        return analysis.diagnostics();
    }

    /** The program read, or repaired after one-token slips; empty when the text cannot be read. */
    Optional<Program> program() {
        return program;
    }

    Outline outline() {
        Outline o = outline;
        if (o == null) {
            o = Outline.of(source.text());
            outline = o;
        }
        return o;
    }
}
