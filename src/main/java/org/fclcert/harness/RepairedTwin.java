package org.fclcert.harness;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.eval.Evaluator;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;

/**
 * The accepted twin of a negative case: its program with the defect repaired by the smallest edit at the error's
 * line that the reference accepts — the line deleted, one token deleted, one token replaced by a token of the
 * program, or one inserted (tried in that order, the error's line first, then the line before it, for an error
 * found only at the token after the missing one). The twin must read without error, load on the reference and
 * use no feature above the case's level, so that a correct implementation of that level must load it: a
 * rejection of the case means something only when the twin is loaded (an implementation that rejects what it
 * does not recognise rejects both). Deterministic (the search does not depend on the run); the run disguises the
 * twin as it disguises the case.
 */
final class RepairedTwin {
    private static final Pattern TOKEN = Pattern.compile("\\(\\*.*?(?:\\*\\)|\\z)|[A-Za-z_][A-Za-z0-9_]*"
            + "|[0-9][0-9A-Za-z_.#]*(?:[eE][-+]?[0-9]+)?|:=|\\.\\.|\\S", Pattern.DOTALL);
    private static final int MAX_TRIES = 300;
    /** Statements a defect may have left out (closing keywords, the required items of 5.2's blocks). */
    private static final List<String> MISSING = List.of("END_VAR", "END_FUZZIFY", "END_DEFUZZIFY", "END_RULEBLOCK",
            "METHOD : COG;", "METHOD : COGS;", "DEFAULT := 0;", "ACCU : MAX;", "AND : MIN;", "END_FUNCTION_BLOCK");
    /** A name no corpus program uses, for a name declared twice (the disguise renames it as any other). */
    static final String NEW_NAME = "twin_name";
    private static final Map<String, Optional<String>> MEMO = new ConcurrentHashMap<>();

    private RepairedTwin() {
    }

    /** The repaired program of negative case {@code c}; empty when no small edit repairs it. */
    static Optional<String> of(RunCase c) {
        if (!c.expectReject()) {
            return Optional.empty();
        }
        int line = c.expectedError().orElseThrow().line();
        return MEMO.computeIfAbsent(c.level().word() + "\0" + line + "\0" + c.program(),
                k -> search(c.program(), line, c.level()));
    }

    private record Tok(int start, int end, String text) {
    }

    private static Optional<String> search(String program, int errorLine, ConformanceLevel level) {
        List<Tok> all = tokens(program);
        int[] lineStarts = lineStarts(program);
        // the tokens near the error (its line and the two around it) and a few that often go missing: a repair is
        // local, and a small vocabulary keeps the search cheap (at most MAX_TRIES readings per line)
        Set<String> vocabulary = new LinkedHashSet<>(List.of(";", ":=", ":", "0", "1"));
        int near = Math.max(0, lineStarts[Math.max(0, Math.min(lineStarts.length, errorLine - 1) - 1)]);
        int far = errorLine + 1 < lineStarts.length ? lineStarts[errorLine + 1] : program.length();
        all.stream().filter(t -> t.start() >= near && t.start() < far).forEach(t -> vocabulary.add(t.text()));
        for (int line : new int[] {errorLine, errorLine - 1}) {
            if (line < 1 || line > lineStarts.length) {
                continue;
            }
            int from = lineStarts[line - 1];
            int to = line < lineStarts.length ? lineStarts[line] : program.length();
            List<Tok> onLine = all.stream().filter(t -> t.start() >= from && t.start() < to).toList();
            int tries = 0;
            for (String candidate : edits(program, from, to, onLine, vocabulary)) {
                if (tries++ == MAX_TRIES) {
                    break;
                }
                if (accepted(candidate, level)) {
                    return Optional.of(candidate);
                }
            }
        }
        return Optional.empty();
    }

    /**
     * The edits in the order tried: the line deleted, swapped with the next (an order the grammar fixes), a missing
     * closing keyword or required item put before it, one token deleted, replaced (also by a new name, for a name
     * declared twice), or one inserted.
     */
    private static Iterable<String> edits(String p, int from, int to, List<Tok> onLine, Set<String> vocabulary) {
        List<String> out = new ArrayList<>();
        out.add(p.substring(0, from) + "\n".repeat(p.substring(from, to).endsWith("\n") ? 1 : 0) + p.substring(to));
        int next = p.indexOf('\n', to);
        if (to < p.length() && next > 0 && p.substring(from, to).endsWith("\n")) {
            out.add(p.substring(0, from) + p.substring(to, next + 1) + p.substring(from, to) + p.substring(next + 1));
        }
        if (from > 0) {
            int before = p.lastIndexOf('\n', from - 2) + 1;
            out.add(p.substring(0, before) + p.substring(from, to) + (p.substring(from, to).endsWith("\n") ? "" : "\n")
                    + p.substring(before, from) + p.substring(to));
        }
        for (String item : MISSING) {
            out.add(p.substring(0, from) + item + "\n" + p.substring(from));
        }
        vocabulary = new LinkedHashSet<>(vocabulary);
        vocabulary.add(NEW_NAME);
        for (Tok t : onLine) {
            out.add(p.substring(0, t.start()) + p.substring(t.end()));
        }
        for (Tok t : onLine) {
            for (String v : vocabulary) {
                if (!v.equals(t.text())) {
                    out.add(p.substring(0, t.start()) + v + p.substring(t.end()));
                }
            }
        }
        for (Tok t : onLine) {
            for (String v : vocabulary) {
                out.add(p.substring(0, t.start()) + v + " " + p.substring(t.start()));
            }
        }
        return out;
    }

    private static boolean accepted(String text, ConformanceLevel level) {
        try {
            Analysis a = Analysis.analyze(StrictReader.openLevel(), "twin", text);
            if (a.hasErrors() || a.program().isEmpty()) {
                return false;
            }
            Program p = a.program().get();
            Evaluator.load(p);
            return new FeatureDetector().detect(p).level().ordinal() <= level.ordinal();
        } catch (RuntimeException | StackOverflowError e) {
            return false;
        }
    }

    private static List<Tok> tokens(String text) {
        List<Tok> out = new ArrayList<>();
        Matcher m = TOKEN.matcher(text);
        while (m.find()) {
            if (!m.group().startsWith("(*")) {
                out.add(new Tok(m.start(), m.end(), m.group()));
            }
        }
        return out;
    }

    private static int[] lineStarts(String text) {
        List<Integer> starts = new ArrayList<>();
        starts.add(0);
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                starts.add(i + 1);
            }
        }
        return starts.stream().mapToInt(Integer::intValue).toArray();
    }
}
