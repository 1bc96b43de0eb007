package org.fclcert.model;

import java.util.Collection;
import java.util.Locale;
import java.util.Optional;

/** FCL names are not case-sensitive (IEC 61131-3, B.1.1): {@code Temp} and {@code TEMP} are one name. */
public final class Names {
    private Names() {
    }

    /** How many names a message about a block's inputs lists ({@link #listed(java.util.List)}). */
    public static final int LISTED = 20;

    /** {@link #listed(java.util.List, int)} with {@link #LISTED}: the inputs a message names. */
    public static String listed(java.util.List<String> names) {
        return listed(names, LISTED);
    }

    /**
     * At most {@code max} of the names, joined by ", ", then how many more ("a, b and 3 more"): a message that names a
     * block's inputs stays one readable line for a block of 100 000 of them.
     */
    public static String listed(java.util.List<String> names, int max) {
        return names.size() <= max ? String.join(", ", names)
                : String.join(", ", names.subList(0, max)) + " and " + (names.size() - max) + " more";
    }

    /** The key under which a name is looked up: upper case, locale-independent. */
    public static String key(String name) {
        return name.toUpperCase(Locale.ROOT);
    }

    public static boolean same(String a, String b) {
        return a.equalsIgnoreCase(b);
    }

    /**
     * The name among {@code candidates} a misspelt {@code name} most likely meant, for "did you mean"
     * hints: the one at the smallest edit distance (insertions, deletions, substitutions and swaps of
     * two neighbouring letters, case ignored), if that distance is small for the name's length (1 for
     * up to 4 letters, 2 up to 8, 3 beyond) and no other candidate is as close.
     */
    public static Optional<String> closest(String name, Collection<String> candidates) {
        String k = key(name);
        int limit = k.length() <= 4 ? 1 : k.length() <= 8 ? 2 : 3;
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        boolean tie = false;
        for (String c : candidates) {
            int d = distance(k, key(c));
            if (d == 0) {
                return Optional.empty();    // not misspelt: the name exists
            }
            if (d < bestDistance) {
                best = c;
                bestDistance = d;
                tie = false;
            } else if (d == bestDistance && !same(c, best)) {
                tie = true;
            }
        }
        return best != null && bestDistance <= limit && !tie && bestDistance < k.length()
                ? Optional.of(best) : Optional.empty();
    }

    /** Optimal string alignment distance (Damerau-Levenshtein without repeated edits of one substring). */
    static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= b.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }
}
