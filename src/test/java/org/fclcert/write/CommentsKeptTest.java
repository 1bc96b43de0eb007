package org.fclcert.write;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.regex.Pattern;
import org.fclcert.model.Program;
import org.fclcert.syntax.ReadResult;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/** The canonical layout keeps a program's comments: each where it stood, its text unchanged. */
class CommentsKeptTest {
    /** Comments found in a text by a pattern of their own (IEC 61131-3: '(*' to the first '*)'), not by the reader. */
    private static final Pattern COMMENT = Pattern.compile("\\(\\*.*?\\*\\)", Pattern.DOTALL);

    private final CanonicalWriter writer = new CanonicalWriter();

    static String commentedHeater() {
        try (InputStream in = CommentsKeptTest.class.getResourceAsStream("/fmt/commented-heater.fcl")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    static List<String> comments(String text) {
        return COMMENT.matcher(text).results().map(m -> m.group()).toList();
    }

    private static Program read(String name, String text) {
        ReadResult r = new StrictReader().read(name, text);
        assertTrue(r.program().isPresent(), () -> r.diagnostics().toString());
        return r.program().get();
    }

    @Test
    void everyCommentSurvivesUnchangedAndInOrder() {
        String source = commentedHeater();
        String written = writer.write(read("heater.fcl", source));
        List<String> before = comments(source);
        assertEquals(43, before.size());   // grep -o '(\*' of the file: 42 outside OPTIONS, 1 inside
        assertEquals(before, comments(written), written);
        assertTrue(written.contains("    temp : REAL; (* °C, 0 .. 120 *)\n"), written);
        assertTrue(written.contains("(* Drying-room heater, PLC 3, written for fclcert's comment tests.\n"
                + "   Units: temperatures in °C, differences in K, power in %. *)\n(* a second comment"), written);
    }

    @Test
    void theTextReadsBackToTheSameProgramAndIsAFixedPoint() {
        String source = commentedHeater();
        Program first = read("heater.fcl", source);
        String written = writer.write(first);
        Program again = read("heater.fcl", written);
        assertEquals(first, again);
        assertEquals(first.comments().size(), again.comments().size());
        assertEquals(written, writer.write(again));
    }

    @Test
    void theDirectParserAndTheFullPipelineGiveTheSameComments() {
        // the direct path declines OPTION/END_OPTION (a warning it leaves to the full pipeline), so the second text
        // is read by ANTLR and the model builder
        String source = commentedHeater();
        String viaAntlr = source.replace("OPTIONS\n", "OPTION\n").replace("END_OPTIONS", "END_OPTION");
        Program direct = read("h.fcl", source);
        Program full = read("h.fcl", viaAntlr);
        assertEquals(direct.comments().stream().map(c -> c.text() + c.line() + c.item() + c.trailing()).toList(),
                full.comments().stream().map(c -> c.text() + c.line() + c.item() + c.trailing()).toList());
    }

    /** The places of the layout, each written out by hand from CanonicalWriter's rules. */
    @Test
    void eachCommentStandsOnTheLineItBelongsTo() {
        String source = """
                (*head*) FUNCTION_BLOCK f (*fb*)
                VAR_INPUT (*in*) x : REAL; (*x*) END_VAR (*end in*)
                VAR_OUTPUT y : REAL; (*y*)
                  (*before end*)
                END_VAR
                FUZZIFY x TERM a := (0, 0) (1, 1); END_FUZZIFY
                DEFUZZIFY y
                  TERM one := 1;
                  (*method*) METHOD : CoGS;
                  DEFAULT := 0; (*default*)
                  RANGE := (0 .. 1); (*range, moved with it*)
                END_DEFUZZIFY
                RULEBLOCK r ACCU : MAX; RULE 1 : IF x IS a
                  (*inside rule 1*) THEN y IS one; END_RULEBLOCK
                END_FUNCTION_BLOCK (*fb end*) (*tail*)
                (*eof*)
                """;
        String expected = """
                (*head*)
                FUNCTION_BLOCK f (*fb*)
                VAR_INPUT (*in*)
                    x : REAL; (*x*)
                END_VAR (*end in*)

                VAR_OUTPUT
                    y : REAL; (*y*)
                    (*before end*)
                END_VAR

                FUZZIFY x
                    TERM a := (0, 0) (1, 1);
                END_FUZZIFY

                DEFUZZIFY y
                    RANGE (0 .. 1); (*range, moved with it*)
                    TERM one := 1;
                    (*method*)
                    METHOD : CoGS;
                    DEFAULT := 0; (*default*)
                END_DEFUZZIFY

                RULEBLOCK r
                    ACCU : MAX;
                    RULE 1 : IF x IS a THEN y IS one; (*inside rule 1*)
                END_RULEBLOCK
                END_FUNCTION_BLOCK (*fb end*) (*tail*)
                (*eof*)
                """;
        assertEquals(expected, writer.write(read("f.fcl", source)));
    }

    @Test
    void aProgramWithoutCommentsIsWrittenAsBefore() {
        String source = commentedHeater();
        Program program = read("heater.fcl", source).withComments(List.of());
        String written = writer.write(program);
        assertEquals(List.of("(* the vendor's, kept verbatim *)"), comments(written));   // OPTIONS content only
        assertFalse(written.contains("°C"));
        assertEquals(program, read("heater.fcl", written));
    }
}
