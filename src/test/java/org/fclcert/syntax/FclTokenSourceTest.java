package org.fclcert.syntax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.junit.jupiter.api.Test;

/**
 * The hand-written lexer ({@link FclTokenSource}) against the one ANTLR generates from Fcl.g4
 * ({@link FclLexer}), the grammar's own definition of the tokens: every field of every token (type,
 * channel, start, stop, line, column, text) equal, on every FCL file of the project, on each code point
 * alone and between letters, on every string of up to three characters over the characters that decide
 * tokens, and on random text built from them.
 */
class FclTokenSourceTest {
    /** The characters at which the lexer's decisions turn (and some it must pass over unchanged). */
    private static final String ALPHABET = "aEe_zR0159.+-#(*):=;,/ \t\r\n\u000B\f\u00e9\u017f\u212a\u0130Kk";

    @Test
    void sameTokensOnEveryFclFileOfTheProject() throws IOException {
        List<Path> files = new ArrayList<>();
        for (String dir : new String[] {"conformance", "examples", "src/test/resources"}) {
            try (Stream<Path> s = Files.walk(Path.of(dir))) {
                s.filter(p -> p.toString().endsWith(".fcl")).forEach(files::add);
            }
        }
        assertTrue(files.size() > 150, files.size() + " files");
        for (Path f : files) {
            String text = new String(Files.readAllBytes(f), java.nio.charset.StandardCharsets.UTF_8);
            same(text, f.toString());
        }
    }

    @Test
    void theCompactTableGivesBackEveryTokenItWasGiven() throws IOException {
        List<String> texts = new ArrayList<>();
        try (Stream<Path> s = Files.walk(Path.of("conformance"))) {
            for (Path f : s.filter(p -> p.toString().endsWith(".fcl")).toList()) {
                texts.add(Files.readString(f));
            }
        }
        texts.add("");
        texts.add("\n\n  x");
        texts.add("a\uD83D\uDE00b (* \n *) c\n\n\n d");      // code points beyond the BMP shift the indices
        for (String text : texts) {
            FclTokenSource lexer = new FclTokenSource(text, "t");
            TokenTable table = new TokenTable();
            List<Token> given = new ArrayList<>();
            Token t;
            do {
                t = lexer.nextToken();
                if (t.getChannel() == Token.DEFAULT_CHANNEL) {
                    table.add(t);
                    given.add(t);
                }
            } while (t.getType() != Token.EOF);
            assertEquals(given.size(), table.size());
            for (int i = 0; i < given.size(); i++) {
                Token w = given.get(i);
                Token g = table.token(i);
                String at = "token " + i + " of " + text.length() + " characters";
                assertEquals(w.getType(), g.getType(), at);
                assertEquals(w.getStartIndex(), g.getStartIndex(), at);
                assertEquals(w.getStopIndex(), g.getStopIndex(), at);
                assertEquals(w.getLine(), g.getLine(), at);
                assertEquals(w.getCharPositionInLine(), g.getCharPositionInLine(), at);
                assertEquals(w.getText(), g.getText(), at);
                assertEquals(i, g.getTokenIndex(), at);
                if (w.getType() == FclLexer.IDENT) {
                    assertTrue(w.getText() == g.getText(), at + ": an identifier keeps its shared spelling");
                }
            }
        }
    }

    @Test
    void sameTokenForEveryCodePointAloneAndBetweenLetters() {
        StringBuilder all = new StringBuilder();
        for (int cp = 0; cp <= Character.MAX_CODE_POINT; cp++) {
            if (cp >= 0xD800 && cp <= 0xDFFF && cp % 64 != 0) {
                continue;       // lone surrogates: a sample of them
            }
            String c = new String(Character.toChars(cp));
            if (cp < 0x3000 || cp % 97 == 0) {
                same(c, "U+" + Integer.toHexString(cp));
                same("a" + c + "b1", "U+" + Integer.toHexString(cp) + " in a word");
            }
            all.append(c).append(cp % 7 == 0 ? "\n" : " ");
        }
        same(all.toString(), "all code points");
    }

    @Test
    void sameTokensOnEveryShortString() {
        int n = ALPHABET.length();
        for (int a = 0; a < n; a++) {
            for (int b = 0; b < n; b++) {
                for (int c = 0; c < n; c++) {
                    String s = "" + ALPHABET.charAt(a) + ALPHABET.charAt(b) + ALPHABET.charAt(c);
                    same(s, "'" + s + "'");
                    same("1" + s, "'1" + s + "'");
                    same("x" + s + "9", "'x" + s + "9'");
                }
            }
        }
    }

    @Test
    void sameTokensOnRandomText() {
        Random rnd = new Random(61131);
        String[] pieces = {"END_VAR", "CoGS", "cog", "RULE1", "16#FF", "1.5E-3", "1E5", ".5", "5.", "1__0", "a__b",
            "x_", "_", "_1", "(*", "*)", "(* c *)", "\r\n", "\uD83D\uDE00", "\uD83D", "..", ":=", "IS", "NOT", "+.5",
            "-0.0e+0_1", "1_.5", "12_3#F", "1#_", "VAR_INPUTX"};
        for (int k = 0; k < 20_000; k++) {
            StringBuilder s = new StringBuilder();
            int len = 1 + rnd.nextInt(12);
            for (int i = 0; i < len; i++) {
                s.append(rnd.nextInt(3) == 0 ? pieces[rnd.nextInt(pieces.length)]
                        : String.valueOf(ALPHABET.charAt(rnd.nextInt(ALPHABET.length()))));
            }
            same(s.toString(), "'" + s + "'");
        }
    }

    private static void same(String text, String what) {
        TokenSource want = new FclLexer(CharStreams.fromString(text, "t"));
        ((FclLexer) want).removeErrorListeners();
        FclTokenSource got = new FclTokenSource(text, "t");
        for (int i = 0; ; i++) {
            Token w = want.nextToken();
            Token g = got.nextToken();
            String at = what + ", token " + i;
            assertEquals(FclLexer.VOCABULARY.getSymbolicName(w.getType()), FclLexer.VOCABULARY.getSymbolicName(g.getType()),
                    at + " type");
            assertEquals(w.getChannel(), g.getChannel(), at + " channel");
            assertEquals(w.getStartIndex(), g.getStartIndex(), at + " start");
            assertEquals(w.getStopIndex(), g.getStopIndex(), at + " stop");
            assertEquals(w.getLine(), g.getLine(), at + " line");
            assertEquals(w.getCharPositionInLine(), g.getCharPositionInLine(), at + " column");
            assertEquals(w.getText(), g.getText(), at + " text");
            if (w.getType() == Token.EOF) {
                break;
            }
        }
    }
}
