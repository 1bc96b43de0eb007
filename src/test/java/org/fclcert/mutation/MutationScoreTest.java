package org.fclcert.mutation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The score printed after PIT: counted by hand on a small report. */
class MutationScoreTest {
    @TempDir
    Path dir;

    private static String mutation(String status, String cls, String method, int line, String mutator, String desc) {
        return "<mutation detected='" + !status.equals("SURVIVED") + "' status='" + status + "' numberOfTestsRun='1'>"
                + "<sourceFile>Thing.java</sourceFile><mutatedClass>org.x." + cls + "</mutatedClass>"
                + "<mutatedMethod>" + method + "</mutatedMethod><methodDescription>()V</methodDescription>"
                + "<lineNumber>" + line + "</lineNumber>"
                + "<mutator>org.pitest.mutationtest.engine.gregor.mutators." + mutator + "</mutator>"
                + "<indexes><index>1</index></indexes><blocks><block>1</block></blocks><killingTest/>"
                + "<description>" + desc + "</description></mutation>\n";
    }

    private Path sources() throws IOException {
        Path src = dir.resolve("src");
        Files.createDirectories(src.resolve("org/x"));
        Files.writeString(src.resolve("org/x/Thing.java"), String.join("\n",
                "package org.x;",                       // 1
                "class Thing {",                        // 2
                "  int f(int a) {",                     // 3
                "    if (a > 0) {",                     // 4
                "      return   a + 1;",                // 5
                "    }",                                // 6
                "    return a - 1;",                    // 7
                "  }",                                  // 8
                "}"));
        return src;
    }

    private Path report(String... mutations) throws IOException {
        Path xml = dir.resolve("mutations.xml");
        Files.writeString(xml, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<mutations partial=\"true\">\n"
                + String.join("", mutations) + "</mutations>\n");
        return xml;
    }

    private Path argued(String... rows) throws IOException {
        Path tsv = dir.resolve("equivalent-mutants.tsv");
        Files.writeString(tsv, "# class\tmethod\tmutator\tdescription\tsource\tcategory\tnote\n"
                + String.join("\n", rows) + "\n");
        return tsv;
    }

    @Test
    void equivalentRowsLeaveTheDenominatorAndUnarguedSurvivorsStayInIt() throws IOException {
        Path xml = report(
                mutation("KILLED", "Thing", "f", 4, "ConditionalsBoundaryMutator", "changed conditional boundary"),
                mutation("TIMED_OUT", "Thing", "f", 5, "MathMutator", "Replaced integer addition with subtraction"),
                mutation("SURVIVED", "Thing", "f", 4, "RemoveConditionalMutator_ORDER_ELSE",
                        "removed conditional - replaced comparison check with false"),
                mutation("SURVIVED", "Thing", "f", 7, "MathMutator", "Replaced integer subtraction with addition"),
                mutation("SURVIVED", "Thing", "f", 5, "PrimitiveReturnsMutator", "replaced int return with 0"),
                mutation("NO_COVERAGE", "Thing", "f", 7, "PrimitiveReturnsMutator", "replaced int return with 0"),
                mutation("NO_COVERAGE", "Other", "g", 1, "VoidMethodCallMutator", "removed call"));
        // line 4's survivor argued E1 (its text with other spacing matches); line 7's known U; line 5's not listed;
        // a row whose line text no longer matches the source (stale) matches nothing
        Path tsv = argued(
                "Thing\tf\tRemoveConditionalMutator_ORDER_ELSE\tremoved conditional - replaced comparison check with"
                        + " false\tif   (a > 0) {\tE1\tzero-width",
                "Thing\tf\tMathMutator\tReplaced integer subtraction with addition\treturn a - 1;\tU",
                "Thing\tf\tMathMutator\tReplaced integer addition with subtraction\treturn a + 2;\tE9");
        MutationScore.Score s = MutationScore.score(MutationScore.readMutations(xml), MutationScore.readArgued(tsv),
                sources());
        // 7 mutants, 5 reached, 2 detected (killed, timed out), 1 equivalent: 2 of 4 non-equivalent = 50 %
        assertEquals("{mutants=7, reached=5, detected=2, equivalent=1, notArgued=2, withoutRow=1, stale=1}",
                MutationScore.summary(s));
        assertEquals(50.0, s.percent(), 1e-12);
        assertEquals(1, s.unlisted().size());
        assertTrue(s.unlisted().get(0).startsWith("Thing:5 f PrimitiveReturnsMutator"), s.unlisted().get(0));
        assertEquals(java.util.List.of("Other (1)"), s.unreachedClasses());
        assertEquals("{E1=1, U=1}", s.byCategory().toString());
    }

    @Test
    void aRowCountsOnceForIdenticalMutantsOnOneLine() throws IOException {
        Path xml = report(
                mutation("SURVIVED", "Thing", "f", 4, "ConditionalsBoundaryMutator", "changed conditional boundary"),
                mutation("SURVIVED", "Thing", "f", 4, "ConditionalsBoundaryMutator", "changed conditional boundary"),
                mutation("KILLED", "Thing", "f", 7, "MathMutator", "Replaced integer subtraction with addition"));
        Path tsv = argued("Thing\tf\tConditionalsBoundaryMutator\tchanged conditional boundary\tif (a > 0) {\tE1b");
        MutationScore.Score s = MutationScore.score(MutationScore.readMutations(xml), MutationScore.readArgued(tsv),
                sources());
        assertEquals("{mutants=3, reached=3, detected=1, equivalent=1, notArgued=1, withoutRow=1, stale=0}",
                MutationScore.summary(s));
    }

    @Test
    void theRunFailsBelowTheBarAndPrintsTheScore() throws IOException {
        Path xml = report(
                mutation("KILLED", "Thing", "f", 4, "ConditionalsBoundaryMutator", "changed conditional boundary"),
                mutation("SURVIVED", "Thing", "f", 7, "MathMutator", "Replaced integer subtraction with addition"));
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        int status = MutationScore.run(xml, argued(), sources(), new PrintStream(bytes, true, StandardCharsets.UTF_8));
        String text = bytes.toString(StandardCharsets.UTF_8);
        assertEquals(1, status, text);
        assertTrue(text.contains("MUTATION SCORE: 1 of 2 reached non-equivalent mutants killed by the corpus alone:"
                + " 50.0 %"), text);
        assertTrue(text.contains("Thing:7 f MathMutator (Replaced integer subtraction with addition): return a - 1;"),
                text);

        Path tsv = argued("Thing\tf\tMathMutator\tReplaced integer subtraction with addition\treturn a - 1;\tE7");
        bytes.reset();
        assertEquals(0, MutationScore.run(xml, tsv, sources(), new PrintStream(bytes, true, StandardCharsets.UTF_8)));
        assertTrue(bytes.toString(StandardCharsets.UTF_8).contains("1 of 1 reached non-equivalent mutants killed"));
    }

    @Test
    void aKilledRowThatSurvivesAgainIsNotArgued() throws IOException {
        Path xml = report(
                mutation("SURVIVED", "Thing", "f", 7, "MathMutator", "Replaced integer subtraction with addition"),
                mutation("SURVIVED", "Thing", "f", 4, "ConditionalsBoundaryMutator", "changed conditional boundary"));
        Path tsv = argued("Thing\tf\tMathMutator\tReplaced integer subtraction with addition\treturn a - 1;\tK",
                "Thing\tf\tConditionalsBoundaryMutator\tchanged conditional boundary\tif (a > 0) {\tX4");
        MutationScore.Score s = MutationScore.score(MutationScore.readMutations(xml), MutationScore.readArgued(tsv),
                sources());
        assertEquals("{mutants=2, reached=2, detected=0, equivalent=1, notArgued=1, withoutRow=0, stale=0}",
                MutationScore.summary(s));
        assertEquals("{K=1, X4=1}", s.byCategory().toString());
    }

    @Test
    void aMalformedRowIsLocated() throws IOException {
        Path tsv = dir.resolve("bad.tsv");
        Files.writeString(tsv, "# header\nThing\tf\tMathMutator\n");
        IOException e = assertThrows(IOException.class, () -> MutationScore.readArgued(tsv));
        assertTrue(e.getMessage().contains("bad.tsv:2:"), e.getMessage());
    }
}
