package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Program;
import org.fclcert.model.Severity;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.FfllReader;
import org.fclcert.write.DialectWriters;
import org.fclcert.write.Written;
import org.junit.jupiter.api.Test;

/**
 * fclcert's FFLL writer and reader against the real FFLL 2.2.1: every positive corpus case the writer says FFLL's
 * layout expresses loads in FFLL, neither refused nor crashing it (before issue 28 every one of them was refused or
 * crashed FFLL at load); and FFLL's own writer's output (export, {@code FuzzyModelBase::save_to_fcl_file}) of every
 * one of them reads back in fclcert's FFLL reader without an error (where FFLL's writer itself does not crash: it
 * does on some programs its reader loaded, e.g. B-COGS-002, a fault of FFLL's export only).
 */
class FfllWrittenCorpusTest {
    @Test
    void everyCaseTheLayoutExpressesLoadsInFfllAndItsExportReadsBack() throws Exception {
        Ffll.assumeLibrary();
        List<String> failures = new ArrayList<>();
        int written = 0;
        int exports = 0;
        List<String> exportCrashes = new ArrayList<>();
        try (ImplementationUnderTest iut = Iuts.open("ffll", IutOptions.defaults().withTimeout(Duration.ofSeconds(5)))) {
            for (CorpusCase c : Corpus.load(Path.of("conformance")).cases()) {
                if (c.expectReject() || c.inDialect()) {   // the writers' subject is standard FCL
                    continue;
                }
                Program p = Analysis.analyze(StrictReader.openLevel(), c.id(), c.programText()).program().orElseThrow();
                Written w = DialectWriters.writer(Dialect.FFLL).write(p);
                if (!w.exact()) {
                    continue;
                }
                written++;
                try {
                    LoadOutcome outcome = iut.load(w.text());
                    if (!(outcome instanceof LoadOutcome.Loaded)) {
                        failures.add(c.id() + ": " + outcome + "\n" + w.text());
                        continue;
                    }
                    String exported;
                    try {
                        exported = iut.export().orElseThrow();
                    } catch (IutException e) {
                        // FFLL's own writer (save_to_fcl_file) crashes on some programs its reader loaded
                        exportCrashes.add(c.id());
                        continue;
                    }
                    exports++;
                    Analysis back = Analysis.analyze(new FfllReader(), c.id() + "-export.fcl", exported);
                    List<Diagnostic> errors = back.diagnostics().stream()
                            .filter(d -> d.severity() == Severity.ERROR).toList();
                    if (back.program().isEmpty() || !errors.isEmpty()) {
                        failures.add(c.id() + ": FFLL's export does not read back: " + errors + "\n" + exported);
                    }
                } catch (IutException e) {
                    failures.add(c.id() + ": " + e + "\n" + w.text());
                }
            }
            assertEquals(exportCrashes.size(), iut.health().crashes(), "FFLL crashed loading a written case: " + failures);
        }
        // measured: 53 of the 125 positive cases are expressible (CorpusRoundTripTest)
        assertTrue(written >= 53, "written exactly: " + written);
        assertTrue(exports > written / 2, exports + " exports read back; FFLL's writer crashed on " + exportCrashes);
        assertTrue(failures.isEmpty(), failures.size() + " failures:\n" + String.join("\n\n",
                failures.subList(0, Math.min(5, failures.size()))));
    }
}
