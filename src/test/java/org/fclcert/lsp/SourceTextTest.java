package org.fclcert.lsp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The server moves a document's line starts on an edit ({@link SourceText#edited}) instead of counting them again. */
class SourceTextTest {
    /** Texts and edits of line breaks ("\n", "\r\n"), letters and digits, at random places, against a fresh count. */
    @Test
    void anEditedTextHasTheLineStartsOfTheNewText() {
        Random random = new Random(31);
        String[] pieces = {"\n", "\r\n", "a", "RULE 1 : IF x IS y THEN z IS w;", "0.5", "", "\n\n", " "};
        for (int round = 0; round < 2_000; round++) {
            StringBuilder b = new StringBuilder();
            for (int k = random.nextInt(12); k > 0; k--) {
                b.append(pieces[random.nextInt(pieces.length)]);
            }
            SourceText src = new SourceText(b.toString());
            for (int edit = 0; edit < 5; edit++) {
                String text = src.text();
                int from = random.nextInt(text.length() + 1);
                int to = from + random.nextInt(text.length() - from + 1);
                String inserted = pieces[random.nextInt(pieces.length)] + pieces[random.nextInt(pieces.length)];
                SourceText edited = src.edited(from, to, inserted);
                String expected = text.substring(0, from) + inserted + text.substring(to);
                SourceText fresh = new SourceText(expected);
                assertEquals(expected, edited.text());
                assertArrayEquals(fresh.lineStarts(), edited.lineStarts(),
                        () -> "'" + text + "' with " + from + ".." + to + " replaced by '" + inserted + "'");
                src = edited;
            }
        }
    }

    /** By hand: "ab\ncd\n" with "b\nc" replaced by "X" is "aXd\n", one line break left, so line starts 0 and 4. */
    @Test
    void aJoinOfTwoLinesDropsTheirBreak() {
        SourceText edited = new SourceText("ab\ncd\n").edited(1, 4, "X");
        assertEquals("aXd\n", edited.text());
        assertArrayEquals(new int[] {0, 4}, edited.lineStarts());
    }
}
