package org.fclcert.cli;

/**
 * Text from an implementation under test (its name, version, claims, messages, error output) as it may
 * reach a terminal: every control character is shown visibly instead of acting ({@code \e} for ESC,
 * {@code \r}, {@code \n}, {@code \t}, {@code \a} for BEL, {@code \0}, {@code \x7f}, {@code \u009b}), so an
 * implementation cannot move the cursor, erase "FAILED", set the window title (OSC) or forge lines. Bidirectional
 * overrides are shown the same way, since they reorder what the reader sees.
 */
final class TerminalText {
    private TerminalText() {}

    static String visible(String text) {
        if (text == null) {
            return "";
        }
        StringBuilder out = null;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            String shown = shown(c);
            if (shown != null && out == null) {
                out = new StringBuilder(text.length() + 16).append(text, 0, i);
            }
            if (out != null) {
                if (shown != null) {
                    out.append(shown);
                } else {
                    out.append(c);
                }
            }
        }
        return out == null ? text : out.toString();
    }

    /** Multi-line text (an error output's tail): each line shown visibly, the line breaks kept. */
    static String visibleLines(String text) {
        if (text == null) {
            return "";
        }
        return String.join("\n", text.lines().map(TerminalText::visible).toList());
    }

    private static String shown(char c) {
        switch (c) {
            case 0x1b: return "\\e";
            case '\r': return "\\r";
            case '\n': return "\\n";
            case '\t': return "\\t";
            case 0x07: return "\\a";
            case 0x00: return "\\0";
            case 0x08: return "\\b";
            default:
                break;
        }
        if (c < 0x20 || c == 0x7f) {
            return String.format("\\x%02x", (int) c);
        }
        if ((c >= 0x80 && c <= 0x9f) || (c >= 0x202a && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069)
                || c == 0x200e || c == 0x200f || c == 0x061c) {
            return String.format("\\u%04x", (int) c);
        }
        return null;
    }
}
