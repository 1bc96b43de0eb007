package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Expected words are what {@code sh -c 'printf "[%s]" COMMAND'} prints for each command. */
class CommandLineSplitterTest {

    private static List<String> split(String command) throws IutException {
        return CommandLineSplitter.split(command);
    }

    @Test
    void blanksSeparateWordsAndRunsOfBlanksCountOnce() throws IutException {
        assertEquals(List.of("python3", "iut.py", "--fast"), split("  python3\t iut.py   --fast \n"));
    }

    @Test
    void singleQuotesKeepEverythingLiterally() throws IutException {
        assertEquals(List.of("run", "a b", "$HOME", "back\\slash", "\"x\""), split("run 'a b' '$HOME' 'back\\slash' '\"x\"'"));
    }

    @Test
    void doubleQuotesKeepBlanksAndSingleQuotes() throws IutException {
        assertEquals(List.of("say", "it's here", "tab\there"), split("say \"it's here\" \"tab\there\""));
    }

    @Test
    void backslashInDoubleQuotesEscapesOnlyDollarBacktickQuoteAndBackslash() throws IutException {
        // sh: "a\"b" -> a"b ; "c\\d" -> c\d ; "e\$f" -> e$f ; "g\nh" keeps the backslash
        assertEquals(List.of("a\"b", "c\\d", "e$f", "g\\nh"), split("\"a\\\"b\" \"c\\\\d\" \"e\\$f\" \"g\\nh\""));
    }

    @Test
    void backslashOutsideQuotesMakesTheNextCharacterLiteral() throws IutException {
        assertEquals(List.of("my iut", "'", "a\"b", "x\\"), split("my\\ iut \\' a\\\"b x\\\\"));
    }

    @Test
    void backslashNewlineJoinsLines() throws IutException {
        assertEquals(List.of("ab", "c"), split("a\\\nb c"));
    }

    @Test
    void adjacentQuotedAndUnquotedPartsFormOneWord() throws IutException {
        assertEquals(List.of("--name=my iut", "ab"), split("--name='my iut' \"a\"'b'"));
    }

    @Test
    void emptyQuotesMakeAnEmptyWord() throws IutException {
        assertEquals(List.of("cmd", "", "x"), split("cmd '' x"));
        assertEquals(List.of("cmd", ""), split("cmd \"\""));
    }

    @Test
    void shellSyntaxIsNotInterpreted() throws IutException {
        assertEquals(List.of("a", "|", "b", ">out", "*.py", "~", "$X"), split("a | b >out *.py ~ $X"));
    }

    @Test
    void unterminatedQuotesTrailingBackslashAndEmptyCommandsAreInfraErrors() {
        for (String bad : List.of("a 'b", "a \"b", "a \"b\\\"", "a\\", "", "   ", "''x'")) {
            IutException e = assertThrows(IutException.class, () -> split(bad), bad);
            assertEquals(IutException.Kind.INFRA, e.kind(), bad);
        }
    }
}
