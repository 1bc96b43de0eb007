package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.fclcert.corpus.Corpus;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class ReferenceExportCheckTest {
    static RunCase defaultValue;

    @BeforeAll
    static void load() throws Exception {
        defaultValue = RunCases.from(Corpus.load(Path.of("src/test/resources/corpus-mini")).byId("B-DEFAULT-VALUE-001")
                .orElseThrow());
    }

    private static ExportCheck.Verdict check(String text) {
        return new ReferenceExportCheck().check(text, defaultValue);
    }

    @Test
    void theSameProgramInAnotherLayoutPasses() {
        String relaidOut = defaultValue.program().strip().replace("\n", "\n  ").replace("DEFAULT := 42", "DEFAULT:=42.0");
        ExportCheck.Verdict v = check(relaidOut);
        assertEquals(ExportStatus.PASSED, v.status(), v.message());
    }

    @Test
    void textThatDoesNotReadBackFails() {
        ExportCheck.Verdict v = check(defaultValue.program().replace("END_RULEBLOCK", ""));
        assertEquals(ExportStatus.FAILED, v.status());
        assertTrue(v.message().startsWith("the exported FCL does not read back: B-DEFAULT-VALUE-001 (exported):"),
                v.message());
    }

    @Test
    void aProgramThatEvaluatesDifferentlyFails() {
        // an export that lost the DEFAULT value: no rule fires at x = 9, and 0 is not the 42 of the original
        ExportCheck.Verdict v = check(defaultValue.program().replace("DEFAULT := 42", "DEFAULT := 0"));
        assertEquals(ExportStatus.FAILED, v.status());
        assertEquals("the exported FCL evaluates differently: step 2: y = 0.0 where 42.0 is expected", v.message());
    }
}
