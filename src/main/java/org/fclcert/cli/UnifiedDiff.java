package org.fclcert.cli;

import java.util.ArrayList;
import java.util.List;

/**
 * The unified diff of two texts, line by line ({@code diff -u}'s form: {@code ---}/{@code +++} headers, hunks
 * {@code @@ -a,b +c,d @@} with three lines of context), for {@code fmt --check}. The line matching is a longest
 * common subsequence; past {@link #MAX_CELLS} line pairs the whole text is one hunk (removed, then added).
 */
final class UnifiedDiff {
    private static final int CONTEXT = 3;
    private static final long MAX_CELLS = 25_000_000L;

    private UnifiedDiff() {
    }

    private record Edit(char kind, String line, int oldLine, int newLine) {
    }

    /** The diff, empty when the texts are equal. */
    static String of(String oldName, String oldText, String newName, String newText) {
        if (oldText.equals(newText)) {
            return "";
        }
        List<String> a = oldText.lines().toList();
        List<String> b = newText.lines().toList();
        List<Edit> edits = edits(a, b);
        StringBuilder out = new StringBuilder();
        out.append("--- ").append(oldName).append('\n').append("+++ ").append(newName).append('\n');
        int i = 0;
        while (i < edits.size()) {
            if (edits.get(i).kind == ' ') {
                i++;
                continue;
            }
            int start = Math.max(0, i - CONTEXT);
            int end = i;
            // extend while the next change is within 2 * CONTEXT unchanged lines
            while (true) {
                while (end < edits.size() && edits.get(end).kind != ' ') {
                    end++;
                }
                int next = end;
                while (next < edits.size() && edits.get(next).kind == ' ') {
                    next++;
                }
                if (next < edits.size() && next - end <= 2 * CONTEXT) {
                    end = next;
                } else {
                    end = Math.min(edits.size(), end + CONTEXT);
                    break;
                }
            }
            hunk(out, edits.subList(start, end), a.size(), b.size());
            i = end;
        }
        if (!oldText.isEmpty() && !oldText.endsWith("\n")) {
            out.append("\\ No newline at end of ").append(oldName).append('\n');
        }
        return out.toString();
    }

    private static void hunk(StringBuilder out, List<Edit> edits, int oldSize, int newSize) {
        int oldStart = 0;
        int newStart = 0;
        int oldCount = 0;
        int newCount = 0;
        for (Edit e : edits) {
            if (e.kind != '+') {
                if (oldCount++ == 0) {
                    oldStart = e.oldLine;
                }
            }
            if (e.kind != '-') {
                if (newCount++ == 0) {
                    newStart = e.newLine;
                }
            }
        }
        if (oldCount == 0) {
            oldStart = edits.get(0).oldLine - 1;   // diff -u names the line before an insertion
        }
        if (newCount == 0) {
            newStart = edits.get(0).newLine - 1;
        }
        out.append("@@ -").append(range(oldStart, oldCount)).append(" +").append(range(newStart, newCount))
                .append(" @@\n");
        for (Edit e : edits) {
            out.append(e.kind).append(e.line).append('\n');
        }
    }

    private static String range(int start, int count) {
        return count == 1 ? Integer.toString(start) : start + "," + count;
    }

    /** The edit script: ' ' kept, '-' only in the old text, '+' only in the new; line numbers 1-based. */
    private static List<Edit> edits(List<String> a, List<String> b) {
        int n = a.size();
        int m = b.size();
        List<Edit> out = new ArrayList<>();
        // common head and tail are kept without the table
        int head = 0;
        while (head < n && head < m && a.get(head).equals(b.get(head))) {
            head++;
        }
        int tail = 0;
        while (tail < n - head && tail < m - head && a.get(n - 1 - tail).equals(b.get(m - 1 - tail))) {
            tail++;
        }
        for (int k = 0; k < head; k++) {
            out.add(new Edit(' ', a.get(k), k + 1, k + 1));
        }
        int an = n - head - tail;
        int bm = m - head - tail;
        if ((long) an * bm > MAX_CELLS) {
            for (int k = 0; k < an; k++) {
                out.add(new Edit('-', a.get(head + k), head + k + 1, head + 1));
            }
            for (int k = 0; k < bm; k++) {
                out.add(new Edit('+', b.get(head + k), head + an + 1, head + k + 1));
            }
        } else {
            int[][] lcs = new int[an + 1][bm + 1];
            for (int x = an - 1; x >= 0; x--) {
                for (int y = bm - 1; y >= 0; y--) {
                    lcs[x][y] = a.get(head + x).equals(b.get(head + y)) ? lcs[x + 1][y + 1] + 1
                            : Math.max(lcs[x + 1][y], lcs[x][y + 1]);
                }
            }
            int x = 0;
            int y = 0;
            while (x < an || y < bm) {
                if (x < an && y < bm && a.get(head + x).equals(b.get(head + y))) {
                    out.add(new Edit(' ', a.get(head + x), head + x + 1, head + y + 1));
                    x++;
                    y++;
                } else if (x < an && (y == bm || lcs[x + 1][y] >= lcs[x][y + 1])) {
                    out.add(new Edit('-', a.get(head + x), head + x + 1, head + y + 1));
                    x++;
                } else {
                    out.add(new Edit('+', b.get(head + y), head + x + 1, head + y + 1));
                    y++;
                }
            }
        }
        for (int k = tail; k > 0; k--) {
            out.add(new Edit(' ', a.get(n - k), n - k + 1, m - k + 1));
        }
        return out;
    }
}
