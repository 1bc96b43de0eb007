package org.fclcert.syntax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.lang.reflect.RecordComponent;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import java.util.stream.Stream;
import org.antlr.v4.runtime.Token;
import org.fclcert.fuzz.FuzzSettings;
import org.fclcert.fuzz.ProgramGenerator;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Program;
import org.fclcert.model.SourceLocation;
import org.fclcert.write.CanonicalWriter;
import org.junit.jupiter.api.Test;

/**
 * The strict reader's fast path ({@link DirectParser}) against the full pipeline (pre-scan, ANTLR, model
 * builder), which defines what a text means: on every text, the reader with the fast path gives exactly what
 * the reader without it gives (the program with every location, the diagnostics, the repaired program), and
 * where the fast path reads a text, the full pipeline has no diagnostic for it. Texts: every FCL file of the
 * project, programs of the fuzz generator, and token-level mutations of both (a token dropped, doubled,
 * swapped with the next, or replaced by or preceded by one of the spellings that decide the reader's paths).
 */
class DirectParserTest {
    /** Three kinds of options without a token filter: the standard, the corpus's Open Level, the draft's forms. */
    private static final List<ReaderOptions> OPTIONS = List.of(ReaderOptions.STRICT, ReaderOptions.OPEN_LEVEL,
            new ReaderOptions(EnumSet.of(DefuzzificationMethod.MOM), true, true, ReaderOptions.TokenFilter.NONE));

    /** Spellings a mutation puts in: keywords, soft keywords, drafts, malformed names and numbers, comments. */
    private static final List<String> SPELLINGS = List.of("FUNCTION_BLOCK", "END_FUNCTION_BLOCK", "VAR_INPUT",
            "VAR_OUTPUT", "VAR", "END_VAR", "FUZZIFY", "END_FUZZIFY", "DEFUZZIFY", "END_DEFUZZIFY", "RULEBLOCK",
            "END_RULEBLOCK", "OPTIONS", "END_OPTIONS", "OPTION", "END_OPTION", "TERM", "RANGE", "METHOD", "DEFAULT",
            "NC", "CoG", "CoGS", "MoM", "LM", "AND", "OR", "NOT", "ACT", "ACCU", "MIN", "MAX", "PROD", "BSUM", "NSUM",
            "PROBOR", "RULE", "IF", "THEN", "IS", "WITH", "REAL", "INT", "BOOL", ":=", ":", ";", ",", "(", ")", "..",
            "=", "1", "+1", "-2", "0.5", "1_0", "1__0", "01", "1.", ".5", "1E5", "1.0E5", "1e400", "16#FF", "2#12",
            "x", "y_", "a__b", "_", "RULE1", "r1", "(* c *)", "(* (* *)", "(*", "#", "'", "\u00e9");

    private final List<String> failures = new ArrayList<>();
    private int read;
    private int readDirectly;

    @Test
    void sameResultOnEveryFclFileOfTheProjectAndItsMutations() throws IOException {
        List<String> texts = projectTexts();
        assertTrue(texts.size() > 150, texts.size() + " files");
        Random random = new Random(20261202);
        for (String text : texts) {
            compareOnAllOptions(text);
            for (int k = 0; k < 12; k++) {
                compareOnAllOptions(mutated(text, random));
            }
        }
        assertNoFailures();
        // the project's programs are written as 5.4 writes them: the fast path must really take them
        int clean = 0;
        for (String text : texts) {
            if (new StrictReader(ReaderOptions.OPEN_LEVEL, false).read("t.fcl", text).diagnostics().isEmpty()) {
                clean++;
                assertTrue(directly(text, ReaderOptions.OPEN_LEVEL), text);
            }
        }
        assertTrue(clean > 200, clean + " files without a diagnostic");
    }

    @Test
    void sameResultOnGeneratedProgramsAndTheirMutations() {
        Random random = new Random(7);
        int clean = 0;    // generated programs without an error
        CanonicalWriter writer = new CanonicalWriter();
        for (ConformanceLevel level : List.of(ConformanceLevel.BASIC, ConformanceLevel.EXTENSION,
                ConformanceLevel.OPEN)) {
            ProgramGenerator generator = new ProgramGenerator(new FuzzSettings(level, java.util.Set.of()));
            for (long seed = 0; seed < 150; seed++) {
                String text = writer.write(generator.generate(seed));
                if (!new StrictReader(ReaderOptions.OPEN_LEVEL, false).read("g.fcl", text).hasErrors()) {
                    clean++;
                    assertTrue(directly(text, ReaderOptions.OPEN_LEVEL), text);
                }
                compareOnAllOptions(text);
                for (int k = 0; k < 8; k++) {
                    compareOnAllOptions(mutated(text, random));
                }
            }
        }
        assertNoFailures();
        // the canonical writer writes 5.4's form (and WITH after the last of several subconclusions, which the
        // direct parser warns of as the pipeline does): every generated program is read directly
        assertEquals(450, clean);
    }

    @Test
    void theValveIsReadDirectlyWithEveryLocation() {
        String text = FclTestPrograms.text("figure7_valve.fcl");
        Optional<Program> direct = DirectParser.program("valve.fcl", text, ReaderOptions.STRICT,
                new ReaderDiagnostics("valve.fcl"));
        assertTrue(direct.isPresent());
        ReadResult full = new StrictReader(ReaderOptions.STRICT, false).read("valve.fcl", text);
        assertTrue(full.diagnostics().isEmpty(), full.diagnostics().toString());
        assertNull(difference(full.program().orElseThrow(), direct.get(), "program"));
        // the first rule's subcondition 'temp IS cold' where the text writes it, by hand
        var rule = direct.get().functionBlocks().get(0).ruleBlocks().get(0).rules().get(0);
        var at = ((org.fclcert.model.Condition.And) rule.condition()).operands().get(0);
        assertTrue(text.split("\n", -1)[at.location().line() - 1].substring(at.location().column() - 1)
                .startsWith("temp IS cold"), at.location().toString());
    }

    /** Each thing the full pipeline has a word for makes the fast path decline; the text is otherwise read directly. */
    @Test
    void declinesWhereverTheFullPipelineWouldSaySomething() {
        String base = """
                FUNCTION_BLOCK f
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM low := (0, 1) (10, 0); TERM high := (0, 0) (10, 1); END_FUZZIFY
                DEFUZZIFY y RANGE (0 .. 10); TERM a := 2; TERM b := 8; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r AND : MIN; ACT : MIN; ACCU : MAX;
                RULE 1 : IF x IS low THEN y IS a;
                RULE 2 : IF NOT (x IS high) THEN y IS b WITH 0.5;
                END_RULEBLOCK
                OPTIONS anything (* even this *) END_OPTIONS
                END_FUNCTION_BLOCK
                """;
        assertTrue(directly(base, ReaderOptions.STRICT));
        String[][] changes = {
                {"TERM low", "TERM max"},                       // a keyword as a name
                {"END_DEFUZZIFY", "END_FUZZIFY"},               // the draft's end
                {"OPTIONS anything", "OPTION anything"},        // 5.4's spelling
                {"RULE 1 :", "RULE r1 :"},                      // a rule named by an identifier
                {"RULE 1 :", "RULE 01 :"},                      // not the number's plain form
                {"RANGE (0 .. 10); TERM a := 2;", "TERM a := 2; RANGE (0 .. 10);"}, // RANGE out of order, not last
                {"METHOD : CoGS; DEFAULT := 0;", "DEFAULT := 0; METHOD : CoGS;"}, // out of order
                {"ACT : MIN;", "ACT : MIN; ACT : PROD;"},       // a setting twice
                {"AND : MIN;", "AND : PROBOR;"},                // not a standard algorithm
                {"(* even this *)", "(* (* nested *)"},         // '(*' inside a comment
                {"(10, 0)", "(1__0, 0)"},                       // a malformed number
                {"x IS low", "x = low"},                        // Annex D's '='
        };
        for (String[] change : changes) {
            String text = base.replace(change[0], change[1]);
            assertFalse(text.equals(base), change[0]);
            assertTrue(!directly(text, ReaderOptions.STRICT), change[1]);
            compareOnAllOptions(text);
        }
        assertNoFailures();
    }

    /**
     * Where the fast path declines at a rule whose ';' is missing before the next RULE or END_RULEBLOCK, it says
     * the text surely has a syntax error, and the reader skips ANTLR's SLL pass: on every project text with each
     * rule's ';' (up to 20 a text) dropped in turn, the full pipeline (which tries SLL first) indeed has an error,
     * and the reader with the skip gives exactly what it gives. Drops elsewhere are not marked.
     */
    @Test
    void aRuleWithoutItsSemicolonSkipsTheSllPassWithTheSameResult() throws IOException {
        int marked = 0;
        for (String text : projectTexts()) {
            List<Token> tokens = new ArrayList<>();
            FclTokenSource lexer = new FclTokenSource(text, "m");
            for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
                tokens.add(t);
            }
            int dropped = 0;
            for (int i = 0; i + 1 < tokens.size() && dropped < 20; i++) {
                if (tokens.get(i).getType() != FclLexer.SEMI) {
                    continue;
                }
                String without = text.substring(0, tokens.get(i).getStartIndex())
                        + text.substring(tokens.get(i).getStopIndex() + 1);
                boolean ruleEnd = tokens.get(i + 1).getType() == FclLexer.RULE
                        || tokens.get(i + 1).getType() == FclLexer.END_RULEBLOCK;
                for (ReaderOptions options : OPTIONS) {
                    DirectParser.Read read = DirectParser.read("t.fcl", without, options,
                            new ReaderDiagnostics("t.fcl"));
                    if (read.surelyInvalid()) {
                        marked++;
                        assertTrue(read.declined());
                        assertTrue(new StrictReader(options, false).read("t.fcl", without).hasErrors(), without);
                    }
                }
                if (ruleEnd) {
                    dropped++;
                    compareOnAllOptions(without);
                }
            }
        }
        assertNoFailures();
        assertTrue(marked > 1000, marked + " texts marked as surely invalid");
    }

    /** The rule without its ';' in a small text: marked, and the diagnostics the full pipeline gives. */
    @Test
    void aMissingSemicolonIsReportedAsWithoutTheSkip() {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y : REAL; END_VAR
                FUZZIFY x TERM low := (0, 1) (10, 0); END_FUZZIFY
                DEFUZZIFY y TERM a := 2; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r ACCU : MAX;
                RULE 1 : IF x IS low THEN y IS a
                RULE 2 : IF x IS low THEN y IS a;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        assertTrue(DirectParser.read("t.fcl", text, ReaderOptions.STRICT, new ReaderDiagnostics("t.fcl"))
                .surelyInvalid());
        // the one error, a malformed conclusion (FCL-S027, 5.2.4; the rule had its condition and THEN): line 7,
        // column 33, just after the 'a' that ends the rule, where its ';' was due
        ReadResult read = new StrictReader(ReaderOptions.STRICT, true).read("t.fcl", text);
        assertEquals(List.of("7:33 ERROR FCL-S027"), read.diagnostics().stream()
                .map(d -> d.location().line() + ":" + d.location().column() + " " + d.severity() + " "
                        + d.diagnosticCode().code()).toList());
        assertTrue(read.repaired().isPresent());
        assertEquals(2, read.repaired().get().functionBlocks().get(0).ruleBlocks().get(0).rules().size());
        compareOnAllOptions(text);
        assertNoFailures();
    }

    /** The three draft forms common in real files are read directly, with the full pipeline's warnings. */
    @Test
    void readsTheCommonDraftFormsWithTheSameWarnings() {
        String text = """
                FUNCTION_BLOCK f
                VAR_INPUT x : REAL; END_VAR
                VAR_OUTPUT y, z : REAL; END_VAR
                FUZZIFY x TERM low := (0, 1) (10, 0); END_FUZZIFY
                DEFUZZIFY y TERM a := 2; METHOD : CoGS; DEFAULT := 0; RANGE := (0 .. 10); END_DEFUZZIFY
                DEFUZZIFY z TERM a := 2; METHOD : CoGS; DEFAULT := 0; END_DEFUZZIFY
                RULEBLOCK r ACCU : MAX;
                RULE 1 : IF x IS low THEN y IS a, z IS a WITH 0.5;
                END_RULEBLOCK
                END_FUNCTION_BLOCK
                """;
        assertTrue(directly(text, ReaderOptions.STRICT));
        ReadResult read = new StrictReader(ReaderOptions.STRICT, true).read("t.fcl", text);
        assertEquals(List.of("5:55 FCL-W101", "5:61 FCL-W103", "8:42 FCL-W105"), read.diagnostics().stream()
                .map(d -> d.location().line() + ":" + d.location().column() + " " + d.diagnosticCode().code())
                .toList());
        compareOnAllOptions(text);
        assertNoFailures();
    }

    // ---------------------------------------------------------------- comparing

    private void compareOnAllOptions(String text) {
        for (ReaderOptions options : OPTIONS) {
            ReadResult full = new StrictReader(options, false).read("t.fcl", text);
            ReadResult withDirect = new StrictReader(options, true).read("t.fcl", text);
            String diff = difference(full, withDirect, "result");
            read++;
            boolean direct = directly(text, options);
            if (direct) {
                readDirectly++;
                if (full.hasErrors()) {
                    diff = "read directly, but the full pipeline says " + full.diagnostics();
                }
            }
            if (diff != null && failures.size() < 10) {
                failures.add(diff + "\n--- text ---\n" + text);
            }
        }
    }

    /** Whether the fast path reads the text (rather than declining it). */
    private static boolean directly(String text, ReaderOptions options) {
        return DirectParser.program("t.fcl", text, options, new ReaderDiagnostics("t.fcl")).isPresent();
    }

    private void assertNoFailures() {
        if (!failures.isEmpty()) {
            fail(failures.size() + " difference(s), the first:\n" + String.join("\n\n", failures.subList(0, 1)));
        }
    }

    /**
     * Where two values differ, field by field through records, lists and optionals, with locations compared
     * by place ({@link SourceLocation#equals} holds for any two); null when they are the same.
     */
    static String difference(Object a, Object b, String path) {
        if (a == null || b == null) {
            return a == b ? null : path + ": " + a + " / " + b;
        }
        if (a.getClass() != b.getClass()) {
            return path + ": " + a.getClass().getSimpleName() + " / " + b.getClass().getSimpleName();
        }
        if (a instanceof SourceLocation x) {
            return x.sameAs((SourceLocation) b) ? null : path + ": " + x + " / " + b;
        }
        if (a instanceof Optional<?> x) {
            Optional<?> y = (Optional<?>) b;
            if (x.isPresent() != y.isPresent()) {
                return path + ": " + x + " / " + y;
            }
            return x.isPresent() ? difference(x.get(), y.get(), path) : null;
        }
        if (a instanceof List<?> x) {
            List<?> y = (List<?>) b;
            if (x.size() != y.size()) {
                return path + ": " + x.size() + " / " + y.size() + " elements";
            }
            for (int i = 0; i < x.size(); i++) {
                String d = difference(x.get(i), y.get(i), path + "[" + i + "]");
                if (d != null) {
                    return d;
                }
            }
            return null;
        }
        if (a.getClass().isRecord()) {
            for (RecordComponent c : a.getClass().getRecordComponents()) {
                try {
                    String d = difference(c.getAccessor().invoke(a), c.getAccessor().invoke(b),
                            path + "." + c.getName());
                    if (d != null) {
                        return d;
                    }
                } catch (ReflectiveOperationException e) {
                    throw new AssertionError(e);
                }
            }
            return null;
        }
        return a.equals(b) ? null : path + ": " + a + " / " + b;
    }

    // ---------------------------------------------------------------- texts

    private static List<String> projectTexts() throws IOException {
        List<String> texts = new ArrayList<>();
        for (String dir : new String[] {"conformance", "examples", "src/test/resources", "src/it"}) {
            try (Stream<Path> s = Files.walk(Path.of(dir))) {
                for (Path f : s.filter(p -> p.toString().endsWith(".fcl")).sorted().toList()) {
                    texts.add(new String(Files.readAllBytes(f), StandardCharsets.UTF_8));
                }
            }
        }
        return texts;
    }

    /** The text with one token changed, the rest of the text (layout, comments) as it was. */
    private static String mutated(String text, Random random) {
        List<Token> tokens = new ArrayList<>();
        FclTokenSource lexer = new FclTokenSource(text, "m");
        for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
            tokens.add(t);
        }
        if (tokens.isEmpty() || text.codePointCount(0, text.length()) != text.length()) {
            return text + " " + SPELLINGS.get(random.nextInt(SPELLINGS.size()));
        }
        int i = random.nextInt(tokens.size());
        Token t = tokens.get(i);
        String before = text.substring(0, t.getStartIndex());
        String token = t.getText();
        String after = text.substring(t.getStopIndex() + 1);
        String spelling = SPELLINGS.get(random.nextInt(SPELLINGS.size()));
        return switch (random.nextInt(5)) {
            case 0 -> before + after;
            case 1 -> before + token + " " + token + after;
            case 2 -> before + spelling + after;
            case 3 -> before + spelling + " " + token + after;
            default -> {
                if (i + 1 == tokens.size()) {
                    yield before + after;
                }
                Token u = tokens.get(i + 1);   // swapped with the next token, the space between kept
                yield before + u.getText() + text.substring(t.getStopIndex() + 1, u.getStartIndex()) + token
                        + text.substring(u.getStopIndex() + 1);
            }
        };
    }
}
