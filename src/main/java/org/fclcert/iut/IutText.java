package org.fclcert.iut;

import java.nio.charset.StandardCharsets;

/**
 * What fclcert keeps of any text an implementation gives it (name, version, claims, messages, error
 * output, output names), applied once where the text enters ({@link IutInfo}, {@link LoadOutcome.Rejected},
 * {@link IutException}, the protocol reader). A lone UTF-16 surrogate (valid in a JSON string, not
 * encodable as UTF-8) becomes U+FFFD, so results and reports can always be written; anything longer than
 * {@link #MAX_KEPT_BYTES} UTF-8 bytes is cut at a character boundary and marked, so memory and report size
 * are bounded by what is kept, not by what the implementation sends.
 */
public final class IutText {
    /** The most of one implementation string that is kept (UTF-8 bytes, before the truncation marker). */
    public static final int MAX_KEPT_BYTES = 4096;

    private static final int MARKER_BYTES = 48;
    private static final java.util.regex.Pattern MARKED = java.util.regex.Pattern.compile("… \\(truncated, \\d+ bytes\\)$");

    private IutText() {}

    /** The text as kept: surrogates repaired, cut to {@link #MAX_KEPT_BYTES} with a marker saying how long it was. */
    public static String kept(String text) {
        if (text == null) {
            return null;
        }
        String whole = wellFormed(text);
        if (whole.length() * 3L <= MAX_KEPT_BYTES) {
            return whole;   // cannot be over the cap: a char is at most 3 UTF-8 bytes (a pair is 4 for 2)
        }
        int total = whole.getBytes(StandardCharsets.UTF_8).length;
        if (total <= MAX_KEPT_BYTES || (total <= MAX_KEPT_BYTES + MARKER_BYTES && MARKED.matcher(whole).find())) {
            return whole;   // within the cap, or kept already (passing through twice changes nothing)
        }
        int bytes = 0;
        int end = 0;
        while (end < whole.length()) {
            int cp = whole.codePointAt(end);
            int size = cp < 0x80 ? 1 : cp < 0x800 ? 2 : cp < 0x10000 ? 3 : 4;
            if (bytes + size > MAX_KEPT_BYTES) {
                break;
            }
            bytes += size;
            end += Character.charCount(cp);
        }
        return whole.substring(0, end) + "… (truncated, " + total + " bytes)";
    }

    /** The text with every lone surrogate replaced by U+FFFD (no cap: for program text such as an export). */
    public static String wellFormed(String text) {
        if (text == null) {
            return null;
        }
        StringBuilder out = null;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            boolean lone;
            if (Character.isHighSurrogate(c)) {
                lone = i + 1 >= text.length() || !Character.isLowSurrogate(text.charAt(i + 1));
                if (!lone) {
                    if (out != null) {
                        out.append(c).append(text.charAt(i + 1));
                    }
                    i++;
                    continue;
                }
            } else {
                lone = Character.isLowSurrogate(c);
            }
            if (lone && out == null) {
                out = new StringBuilder(text.length()).append(text, 0, i);
            }
            if (out != null) {
                out.append(lone ? '\uFFFD' : c);
            }
        }
        return out == null ? text : out.toString();
    }
}
