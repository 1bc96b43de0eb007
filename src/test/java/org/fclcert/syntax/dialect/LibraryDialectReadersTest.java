package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.check.Analysis;
import org.fclcert.check.FeatureDetector;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Program;
import org.fclcert.model.ShapeKind;
import org.fclcert.syntax.ReadResult;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.api.Test;

/** The jFuzzyLogic and fuzzylite readers on sample programs written in each library's style. */
class LibraryDialectReadersTest {
    private final JFuzzyLogicReader jfl = new JFuzzyLogicReader();
    private final FuzzyliteReader fl = new FuzzyliteReader();

    static String resource(String path) throws IOException {
        try (InputStream in = LibraryDialectReadersTest.class.getResourceAsStream(path)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    /** feature-id@line:col of the Open Level uses, sorted as the detector sorts them. */
    private static List<String> openUses(Program program) {
        return new FeatureDetector().detect(program).uses().stream()
                .filter(u -> u.feature().id().startsWith("O-"))
                .map(u -> u.feature().id() + "@" + u.location().line() + ":" + u.location().column()).toList();
    }

    private static List<String> codes(List<Diagnostic> ds) {
        return ds.stream().map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column()).toList();
    }

    @Test
    void jfuzzylogicTipperReadsChecksAndListsItsOpenLevelConstructs() throws IOException {
        Analysis a = Analysis.analyze(jfl, "tipper.fcl", resource("jfuzzylogic/tipper.fcl"));
        assertEquals(List.of(), a.diagnostics());
        Program p = a.program().orElseThrow();
        FunctionBlock fb = p.functionBlocks().get(0);
        // gbell 2 4 5 is width 2, slope 4, centre 5: canonical (centre, width, slope)
        MembershipFunction.NamedShape bell = (MembershipFunction.NamedShape) fb.fuzzification("service").orElseThrow()
                .term("good").orElseThrow().function();
        assertEquals(ShapeKind.BELL, bell.kind());
        assertEquals(List.of(5.0, 2.0, 4.0), bell.parameters().stream().map(l -> l.value()).toList());
        // sigm 2 8 is gain 2, centre 8; cosine 10 25 is half-width 10, centre 25: support 15 to 35, width 20
        assertEquals(List.of(8.0, 2.0), ((MembershipFunction.NamedShape) fb.fuzzification("service").orElseThrow()
                .term("excellent").orElseThrow().function()).parameters().stream().map(l -> l.value()).toList());
        assertEquals(List.of(25.0, 20.0), ((MembershipFunction.NamedShape) fb.defuzzification("tip").orElseThrow()
                .term("generous").orElseThrow().function()).parameters().stream().map(l -> l.value()).toList());
        // jFuzzyLogic's input RANGE stands after the declaration in VAR_INPUT; the reader gives it to the FUZZIFY block
        assertEquals(List.of(0.0, 10.0), fb.fuzzification("service").orElseThrow().declaredRange()
                .map(r -> List.of(r.min().value(), r.max().value())).orElseThrow());
        assertTrue(fb.fuzzification("food").orElseThrow().declaredRange().isEmpty());
        assertEquals(AccumulationMethod.PROBOR, fb.ruleBlocks().get(0).accumulation().orElseThrow().value());
        assertEquals(DefuzzificationMethod.COG, fb.defuzzification("tip").orElseThrow().method().orElseThrow().value());
        assertEquals(List.of(
                "O-COMMENT-STYLE@1:1",
                "O-SHAPE-GAUSSIAN@16:5", "O-SHAPE-BELL@17:5", "O-SHAPE-SIGMOID@18:5",
                "O-DECLARATION-RANGE@7:5",
                "O-SHAPE-TRIANGLE@22:5", "O-SHAPE-TRAPEZOID@23:5",
                "O-SHAPE-TRIANGLE@28:5", "O-SHAPE-GAUSSIAN@29:5", "O-SHAPE-COSINE@30:5", "O-METHOD-COGF@31:14",
                "O-ACCU-PROBOR@38:5", "O-COMMENT-STYLE@39:5").stream().sorted(LibraryDialectReadersTest::byPlace).toList(),
                openUses(p));
    }

    private static int byPlace(String a, String b) {
        return Long.compare(place(a), place(b));
    }

    private static long place(String use) {
        Matcher m = Pattern.compile("@(\\d+):(\\d+)").matcher(use);
        assertTrue(m.find());
        return Long.parseLong(m.group(1)) * 1000 + Long.parseLong(m.group(2));
    }

    @Test
    void jfuzzylogicHabitsAreWarnedWhereItsMeaningDiffers() throws IOException {
        ReadResult r = jfl.read("habits.fcl", resource("jfuzzylogic/habits.fcl"));
        assertTrue(r.program().isPresent(), r.diagnostics().toString());
        // FUZZIFY humidity vs Humidity (W303, line 13), ACCU missing -> SUM (W304 at RULEBLOCK line 21),
        // METHOD MM present, DEFAULT missing -> NC (W304 at DEFUZZIFY line 16), OR: ASUM after AND: MIN (W301
        // at line 23), 'OR temp IS hot AND ...' (W302 at line 24 col 33, the operand after OR)
        assertEquals(List.of("FCL-W303@13:1", "FCL-W304@16:1", "FCL-W304@21:1", "FCL-W301@23:5",
                "FCL-W302@24:33"), codes(r.diagnostics()));
        Program p = r.program().get();
        FunctionBlock fb = p.functionBlocks().get(0);
        assertEquals(AccumulationMethod.SUM, fb.ruleBlocks().get(0).accumulation().orElseThrow().value());
        assertTrue(fb.defuzzification("fan").orElseThrow().defaultValue().orElseThrow() instanceof DefaultValue.NoChange);
        assertEquals(DefuzzificationMethod.MOM, fb.defuzzification("fan").orElseThrow().method().orElseThrow().value());
        List<String> uses = openUses(p);
        assertTrue(uses.contains("O-METHOD-MM@19:14"), uses.toString());
        assertTrue(uses.contains("O-MOM@19:5"), uses.toString());
        assertTrue(uses.contains("O-IMPLICIT-SETTING@21:1"), uses.toString());
        assertTrue(uses.contains("O-ACCU-SUM@21:1"), uses.toString());
        // the checks then report the unpaired AND/OR (FCL-C014) at the later declaration
        Analysis a = Analysis.analyze(jfl, "habits.fcl", resource("jfuzzylogic/habits.fcl"));
        assertTrue(codes(a.diagnostics()).contains("FCL-C014@23:5"), a.diagnostics().toString());
    }

    @Test
    void fuzzyliteObstacleReadsChecksAndListsItsOpenLevelConstructs() throws IOException {
        Analysis a = Analysis.analyze(fl, "obstacle.fcl", resource("fuzzylite/obstacle.fcl"));
        // W310: fuzzylite weighs the degree before ACT MIN, fclcert the activated set
        assertEquals(List.of("FCL-W305@29:10", "FCL-W310@47:43"), codes(a.diagnostics()));
        Program p = a.program().orElseThrow();
        FunctionBlock fb = p.functionBlocks().get(0);
        // ACCU in DEFUZZIFY moved to the rule block; RANGE -inf..inf of an input dropped
        assertEquals(AccumulationMethod.PROBOR, fb.ruleBlocks().get(0).accumulation().orElseThrow().value());
        assertTrue(fb.defuzzification("steer").orElseThrow().defaultValue().orElseThrow() instanceof DefaultValue.NoChange);
        assertEquals(DefuzzificationMethod.COGSS, fb.defuzzification("speed").orElseThrow().method().orElseThrow().value());
        assertEquals(List.of(
                "O-COMMENT-STYLE@1:1", "O-ENABLED@14:3", "O-INFINITE-RANGE@15:3", "O-INPUT-RANGE@15:3",
                "O-SHAPE-RAMP@16:3", "O-SHAPE-RAMP@17:3", "O-SHAPE-GAUSSIAN@18:3", "O-ENABLED@22:3",
                "O-SHAPE-BELL@24:3", "O-SHAPE-TRIANGLE@25:3", "O-ACCU-IN-DEFUZZIFY@27:3", "O-DEFAULT-NAN@28:14",
                "O-LOCK-PREVIOUS@29:10", "O-LOCK-RANGE@29:20", "O-COGSS@36:3", "O-ACCU-IN-DEFUZZIFY@37:3",
                "O-ACCU-PROBOR@27:3", "O-COMMENT-STYLE@45:3", "O-RULE-WITHOUT-SEMICOLON@46:3",
                "O-CONCLUSION-AND@46:52", "O-HEDGE-VERY@47:15", "O-RULE-WITHOUT-SEMICOLON@47:3",
                "O-HEDGE-SOMEWHAT@48:15", "O-HEDGE-EXTREMELY@48:46", "O-HEDGE-SELDOM@49:15", "O-HEDGE-ANY@49:45",
                "O-RULE-WITHOUT-SEMICOLON@49:3")
                .stream().sorted().toList(), openUses(p).stream().sorted().toList());
    }

    @Test
    void malformedDialectTextGetsLocatedErrorsAndNoProgram() {
        String head = "FUNCTION_BLOCK f\nVAR_INPUT\n  x: REAL;\nEND_VAR\nVAR_OUTPUT\n  y: REAL;\nEND_VAR\n"
                + "FUZZIFY x\n  TERM a := Triangle 0 1 2;\nEND_FUZZIFY\n"
                + "DEFUZZIFY y\n  RANGE := (0 .. 1);\n  TERM b := Triangle 0 0.5 1;\n  METHOD : COG;\n  ACCU : MAX;\n"
                + "  DEFAULT := 0;\nEND_DEFUZZIFY\nRULEBLOCK r\n  AND : MIN;\n";
        // fuzzylite drops upper-case IF silently; fclcert refuses it, at the IF
        assertErrors(fl, head + "  RULE 1 : IF x is a then y is b\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n", "FCL-S306@20:12");
        // a rule continued on the next line
        assertErrors(fl, head + "  RULE 1 : if x is a\n then y is b\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n", "FCL-S310@21:2");
        // (* *) comment in fuzzylite
        assertErrors(fl, "(* c *)\n" + head + "  RULE 1 : if x is a then y is b\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n",
                "FCL-S303@1:1");
        // an unknown shape, and Triangle with two parameters (C040 from the checks)
        assertErrors(fl, head.replace("Triangle 0 1 2", "Triangel 0 1 2")
                + "  RULE 1 : if x is a then y is b\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n", "FCL-S307@9:13");
        assertErrors(fl, head.replace("Triangle 0 1 2", "Triangle 0 1")
                + "  RULE 1 : if x is a then y is b\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n", "FCL-C040@9:3");
        assertErrors(fl, head.replace("Triangle 0 1 2", "Triangle 2 1 0")
                + "  RULE 1 : if x is a then y is b\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n", "FCL-C041@9:3");
        // jFuzzyLogic: VAR, initial values, '.5', commas between points, a bare variable
        String j = "FUNCTION_BLOCK f\nVAR_INPUT x : REAL := 1.0; END_VAR\nEND_FUNCTION_BLOCK\n";
        assertErrors(jfl, j, "FCL-S306@2:20");
        assertErrors(jfl, "FUNCTION_BLOCK f\nVAR\n v : REAL;\nEND_VAR\nEND_FUNCTION_BLOCK\n", "FCL-S306@2:1");
        assertErrors(jfl, "FUNCTION_BLOCK f\nVAR_INPUT x : REAL; END_VAR\nFUZZIFY x\n TERM a := (0, 1), (.5, 0);\n"
                + "END_FUZZIFY\nEND_FUNCTION_BLOCK\n", "FCL-S306@4:18", "FCL-S304@4:21");
        assertErrors(jfl, "FUNCTION_BLOCK f\nVAR_INPUT x : REAL; END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n"
                + "RULEBLOCK r\n RULE 1 : IF x THEN y IS b;\nEND_RULEBLOCK\nEND_FUNCTION_BLOCK\n", "FCL-S306@5:14");
        assertErrors(jfl, "FUNCTION_BLOCK f\n", "FCL-S305@2:1");
        // the strict reader rejects what only a dialect reads
        assertTrue(new StrictReader().read("s.fcl", head.replace("Triangle 0 1 2", "(0, 0) (1, 1)")
                .replace("Triangle 0 0.5 1", "(0, 0) (1, 1)").replace("ACCU : MAX;", "") .replace("AND : MIN;",
                        "AND : MIN;\n  ACCU : PROBOR;") + "  RULE 1 : IF x IS a THEN y IS b;\nEND_RULEBLOCK\n"
                + "END_FUNCTION_BLOCK\n").hasErrors());
    }

    private static void assertErrors(DialectReader reader, String text, String... expected) {
        Analysis a = Analysis.analyze(reader, "m.fcl", text);
        List<String> errors = a.diagnostics().stream().filter(Diagnostic::isError)
                .map(d -> d.code() + "@" + d.location().line() + ":" + d.location().column()).toList();
        assertEquals(List.of(expected), errors, a.diagnostics().toString());
        assertTrue(a.hasErrors());
        assertTrue(a.diagnostics().stream().allMatch(d -> d.toString().startsWith("m.fcl:")));
    }

    @Test
    void giveawaysFindTheTellingConstructsAndNothingInTheStandardExample() throws IOException {
        String valve = Files.readString(Path.of("examples/valve.fcl"));
        assertEquals(List.of(), jfl.giveaways(valve));
        assertEquals(List.of(), fl.giveaways(valve));
        List<String> j = jfl.giveaways(resource("jfuzzylogic/tipper.fcl")).stream()
                .map(g -> g.construct() + "@" + g.line()).toList();
        assertEquals(List.of("'/* */' comment@1", "RANGE in a VAR section@7", "shape 'gauss'@16", "shape 'gbell'@17", "shape 'sigm'@18",
                "shape 'trian'@22", "shape 'trape'@23", "shape 'trian'@28", "shape 'gauss'@29", "shape 'cosine'@30",
                "'COGF'@31", "'PROBOR'@38", "'//' comment@39"), j);
        List<String> f = fl.giveaways(resource("fuzzylite/obstacle.fcl")).stream()
                .map(g -> g.construct() + "@" + g.line()).toList();
        assertTrue(f.containsAll(List.of("'#' comment@1", "'ENABLED'@14", "'-inf'@15", "'inf'@15", "shape 'Ramp'@16",
                "shape 'Gaussian'@18", "'nan'@28", "'LOCK'@29", "METHOD COGSS@36", "ACCU inside DEFUZZIFY@27",
                "rule without ';'@46", "hedge 'very'@47", "hedge 'any'@49")), f.toString());
        // each library's sample gives little or nothing away for the other
        assertTrue(fl.giveaways(resource("jfuzzylogic/tipper.fcl")).isEmpty());
        // (fuzzylite's exporter writes '//' comments too, which count once for jFuzzyLogic: weight 1 against many)
        assertEquals(List.of("'//' comment"), jfl.giveaways(resource("fuzzylite/obstacle.fcl")).stream()
                .map(DialectReader.Giveaway::construct).toList());
        assertEquals(List.of(), fl.giveaways("\u0000(*\n#"), "never throws; '#' alone on the last line");
    }

    @Test
    void mutatedDialectTextNeverThrowsNorHangs() throws IOException {
        List<String> seeds = List.of(resource("jfuzzylogic/tipper.fcl"), resource("jfuzzylogic/habits.fcl"),
                resource("fuzzylite/obstacle.fcl"));
        Random random = new Random(7);
        String alphabet = "();:=,.#/*\n -+0123456789abcisnotveryIFTHENRULEEND_";
        long start = System.nanoTime();
        int programs = 0;
        for (String seed : seeds) {
            for (int n = 0; n < 300; n++) {
                StringBuilder text = new StringBuilder(seed);
                int edits = 1 + random.nextInt(6);
                for (int e = 0; e < edits && text.length() > 0; e++) {
                    int at = random.nextInt(text.length());
                    switch (random.nextInt(3)) {
                        case 0 -> text.deleteCharAt(at);
                        case 1 -> text.insert(at, alphabet.charAt(random.nextInt(alphabet.length())));
                        default -> text.setCharAt(at, alphabet.charAt(random.nextInt(alphabet.length())));
                    }
                }
                for (DialectReader reader : List.of(jfl, fl)) {
                    Analysis a = Analysis.analyze(reader, "mut.fcl", text.toString());
                    assertFalse(a.diagnostics().stream().anyMatch(
                            d -> d.diagnosticCode() == org.fclcert.syntax.SyntaxCode.INTERNAL_ERROR), a.diagnostics().toString());
                    assertTrue(a.program().isPresent() || a.hasErrors());
                    reader.giveaways(text.toString());
                    programs++;
                }
            }
        }
        assertEquals(1800, programs);
        assertTrue(System.nanoTime() - start < 60_000_000_000L, "mutation run took too long");
    }
}
