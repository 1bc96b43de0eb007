package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.Program;
import org.fclcert.model.SourceLocation;
import org.fclcert.syntax.ReadResult;

/**
 * The shared core of the readers of fuzzylite's two engine formats, FLL ({@link FllReader}) and MATLAB's FIS
 * ({@link FisReader}). Both describe a fuzzylite engine, which fuzzylite's FCL describes too: each line of the
 * file is restated as the fuzzylite FCL statement that means the same (on the same line, so every diagnostic
 * keeps its line), and that text is read by the fuzzylite dialect's reader ({@link FuzzyliteDialect}), the one place
 * that says what a fuzzylite construct means in the model. What is only FCL's way of writing a thing (its
 * comments, rule semicolons, where ACCU stands, block names) is the restatement's, not the file's, so those Open
 * Level features are left out. Every place keeps its line; the reader's diagnostics are put at the line's first
 * written column. The model's places (and so the checks' diagnostics) are put in the file too ({@link #place}): a
 * place in a line's own restatement at the line's first written column plus its offset in the restatement, never past
 * the line's end; a place in text the restatement adds (the END_… closing the section before, the declarations of
 * the variables) at the first written column of the line it stands for. So a place is always on its line of the file,
 * not at a column of the longer restated line.
 */
final class EngineText {
    /** Features of FCL's spelling, never of the engine file: the restatement writes them, the file does not. */
    private static final Set<Feature> SPELLING = Set.of(Feature.O_COMMENT_STYLE, Feature.O_RULE_WITHOUT_SEMICOLON,
            Feature.O_UNNAMED_BLOCK, Feature.O_BLOCK_NAME_VERBATIM, Feature.O_ACCU_IN_DEFUZZIFY, Feature.O_ENABLED,
            Feature.O_CONCLUSION_AND, Feature.O_INFINITE_RANGE, Feature.O_INPUT_RANGE);

    private static final LibraryDialect FUZZYLITE = new FuzzyliteDialect();

    private final String source;
    private final List<String> lines;
    private final String[] fcl;
    private final List<Diagnostic> errors = new ArrayList<>();
    private final List<Diagnostic> warnings = new ArrayList<>();
    private String end = "";
    private String pending = "";
    /** Added text waiting for the next line put ({@link #beforeNext}), with the lines of the file it stands for. */
    private final List<Piece> pendingPieces = new ArrayList<>();
    /** Per restated line, its pieces in order: where each starts and ends in the line, and what it stands for. */
    private final List<List<Piece>> pieces;

    /**
     * A stretch of a restated line: {@code from} to {@code to} (0-based, exclusive); {@code own} when it restates the
     * line itself, else added text standing for line {@code target} (0-based).
     */
    private record Piece(int from, int to, boolean own, int target) {
    }

    /** A restatement of {@code text}, whose lines start empty. */
    EngineText(String source, String text) {
        this.source = source == null ? "<input>" : source;
        this.lines = (text == null ? "" : text).lines().toList();
        this.fcl = new String[lines.size()];
        java.util.Arrays.fill(fcl, "");
        this.pieces = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            pieces.add(new ArrayList<>());
        }
    }

    /** The file's lines (0-based here, 1-based in diagnostics). */
    List<String> lines() {
        return lines;
    }

    /** Appends FCL text to line {@code index} (0-based), the restatement of that line. */
    void put(int index, String text) {
        put(index, "", text);
    }

    /**
     * Appends to line {@code index} (0-based) FCL text the restatement adds there ({@code added}, such as the END_…
     * of the section before), then the restatement of the line itself.
     */
    void put(int index, String added, String text) {
        if (!pending.isEmpty()) {
            for (Piece p : pendingPieces) {
                append(index, pending.substring(p.from(), p.to()), false, p.target() < 0 ? index : p.target());
            }
            pending = "";
            pendingPieces.clear();
        }
        if (!added.isBlank()) {
            append(index, added.strip(), false, index);
        }
        append(index, text, true, index);
    }

    private void append(int index, String text, boolean own, int target) {
        int from = fcl[index].isEmpty() ? 0 : fcl[index].length() + 1;
        fcl[index] = fcl[index].isEmpty() ? text : fcl[index] + " " + text;
        pieces.get(index).add(new Piece(from, fcl[index].length(), own, target));
    }

    /** FCL text that goes before the next text put on a line (a statement that must not share its line). */
    void beforeNext(String text) {
        beforeNext(text, -1);
    }

    /** The same, standing for line {@code target} (0-based; -1: for the line it is put on). */
    void beforeNext(String text, int target) {
        int from = pending.isEmpty() ? 0 : pending.length() + 1;
        pending = pending.isEmpty() ? text : pending + " " + text;
        pendingPieces.add(new Piece(from, pending.length(), false, target));
    }

    /** FCL text after the last line (the closing keywords). */
    void end(String text) {
        String all = pending.isEmpty() ? text : pending + " " + text;
        pending = "";
        pendingPieces.clear();
        end = end.isEmpty() ? all : end + " " + all;
    }

    /** A warning on line {@code index} (0-based): where a library reads the line otherwise than fclcert. */
    void warn(int index, DialectCode code, String message) {
        warnings.add(Diagnostic.warning(at(index + 1), code, message));
    }

    /** An error of the file's own syntax on line {@code index} (0-based), at its first written column. */
    void error(int index, DialectCode code, String message) {
        errors.add(Diagnostic.error(at(index + 1), code, message));
    }

    boolean failed() {
        return !errors.isEmpty();
    }

    /**
     * Where a place of the restatement (1-based line and column) is in the file: see the class comment. The text after
     * the last line (the closing keywords) stands for the last line.
     */
    SourceLocation place(int line, int column) {
        if (line < 1 || line > lines.size()) {
            return at(Math.max(1, Math.min(line, lines.size())));
        }
        SourceLocation start = at(line);
        for (Piece p : pieces.get(line - 1)) {
            if (column - 1 >= p.from() && column - 1 < p.to()) {
                if (!p.own()) {
                    return at(p.target() + 1);
                }
                int last = Math.max(start.column(), lines.get(line - 1).stripTrailing().length());
                return SourceLocation.of(source, line, Math.min(last, start.column() + column - 1 - p.from()));
            }
        }
        return start;
    }

    private SourceLocation at(int line) {
        String text = line >= 1 && line <= lines.size() ? lines.get(line - 1) : "";
        int column = 1;
        while (column <= text.length() && Character.isWhitespace(text.charAt(column - 1))) {
            column++;
        }
        return SourceLocation.of(source, line, column > text.length() ? 1 : column);
    }

    /** The restated text (for tests and the curious). */
    String fcl() {
        StringBuilder s = new StringBuilder();
        for (String line : fcl) {
            s.append(line).append('\n');
        }
        return s.append(end).append('\n').toString();
    }

    /** The program: the file's own errors if it has any, else the fuzzylite reading of the restatement. */
    ReadResult read() {
        if (!errors.isEmpty()) {
            List<Diagnostic> sorted = new ArrayList<>(errors);
            sorted.addAll(warnings);
            sorted.sort(Comparator.comparing(Diagnostic::location));
            return new ReadResult(Optional.empty(), sorted);
        }
        ReadResult r = DialectParser.read(source, fcl(), FUZZYLITE, this::place);
        List<Diagnostic> located = new ArrayList<>(r.diagnostics().stream()
                .map(d -> new Diagnostic(at(Math.min(d.location().line(), lines.size())), d.severity(),
                        d.diagnosticCode(), d.message())).toList());
        located.addAll(warnings);
        located.sort(Comparator.comparing(Diagnostic::location));
        return new ReadResult(r.program().map(this::ownFeatures), located);
    }

    private Program ownFeatures(Program p) {
        // kept where the model has them: the checks match a tolerated construct to its feature by place
        List<FeatureUse> own = p.dialectFeatures().stream().filter(f -> !SPELLING.contains(f.feature())).toList();
        return new Program(p.sourceName(), p.functionBlocks(), own);
    }

    /** A file read by restating it ({@code restate}); a bug of the reader is a located FCL-S999, never an exception. */
    static ReadResult read(String source, String text, String reader,
            java.util.function.BiFunction<String, String, EngineText> restate) {
        try {
            return restate.apply(source, text).read();
        } catch (RuntimeException | StackOverflowError e) {
            return new ReadResult(Optional.empty(), List.of(DialectParser.internalError(
                    source == null ? "<input>" : source, reader, e)));
        }
    }

    /** {@code RANGE := (lo .. hi);} on line {@code index} from two written numbers, else a located FCL-S305. */
    void range(int index, String[] written, String expected) {
        Optional<String> lo = written.length == 2 ? number(written[0]) : Optional.empty();
        Optional<String> hi = written.length == 2 ? number(written[1]) : Optional.empty();
        if (lo.isEmpty() || hi.isEmpty()) {
            error(index, DialectCode.SYNTAX, "expected '" + expected + "' (two numbers), found '"
                    + String.join(" ", written) + "'");
        } else {
            put(index, "RANGE := (" + lo.get() + " .. " + hi.get() + ");");
        }
    }

    /** A name as an FCL identifier: each run of other characters as '_', a leading digit prefixed. */
    static String identifier(String name, String fallback) {
        String s = name.strip().replaceAll("[^A-Za-z0-9_]+", "_");
        if (s.isEmpty() || s.equals("_")) {
            return fallback;
        }
        return Character.isDigit(s.charAt(0)) ? "_" + s : s;
    }

    /** A number as FCL writes it; empty when the text is none. */
    static Optional<String> number(String text) {
        String t = text.strip();
        if (t.equalsIgnoreCase("nan") || t.equalsIgnoreCase("inf") || t.equalsIgnoreCase("-inf")
                || t.equalsIgnoreCase("+inf")) {
            return Optional.of(t.toLowerCase(java.util.Locale.ROOT).replace("+", ""));
        }
        try {
            double v = Double.parseDouble(t);
            if (Double.isNaN(v) || Double.isInfinite(v) || t.endsWith("d") || t.endsWith("f") || t.endsWith("D")
                    || t.endsWith("F")) {
                return Optional.empty();
            }
            return Optional.of(t.startsWith("+") ? t.substring(1) : t.startsWith(".") ? "0" + t
                    : t.startsWith("-.") ? "-0" + t.substring(1) : t);
        } catch (NumberFormatException e) {
            return Optional.empty();
        }
    }
}
