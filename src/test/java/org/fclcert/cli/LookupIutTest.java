package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import java.util.List;
import org.fclcert.corpus.Corpus;
import org.fclcert.harness.CaseResult;
import org.fclcert.harness.CaseStatus;
import org.fclcert.harness.ResultSink;
import org.fclcert.harness.RunCase;
import org.fclcert.harness.RunCases;
import org.fclcert.harness.RunHeader;
import org.fclcert.harness.RunListener;
import org.fclcert.harness.Runner;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 26: an "implementation" that computes nothing and replays the corpus's answers (src/test/resources/iut/
 * lookup.py: it finds ./conformance, matches the program it is sent by its structure, names and layout ignored,
 * and answers as the corpus says) must not be certified.
 */
class LookupIutTest {
    static final String LOOKUP = "process:python3 src/test/resources/iut/lookup.py";

    @TempDir
    Path dir;

    @Test
    void withoutFreshEvidenceTheLookupPassesEveryCaseItIsShown() throws Exception {
        // the control: the adversary is real — sent the corpus text and vectors, it passes
        List<RunCase> cases = RunCases.from(Corpus.load(Path.of("conformance")).cases()).stream()
                .filter(c -> c.id().startsWith("B-")).limit(30).toList();
        ResultSink none = new ResultSink() {
            @Override
            public void header(RunHeader header) {
            }

            @Override
            public void accept(CaseResult result) {
            }
        };
        // the sandbox would hide the corpus from it: off, so that what stops the lookup is the fresh evidence alone
        try (ImplementationUnderTest lookup = Iuts.open(LOOKUP, IutOptions.defaults()
                .withSandbox(org.fclcert.sandbox.SandboxSettings.none()))) {
            List<CaseResult> results = new Runner(RunListener.NONE).run(lookup, null, cases, none);
            assertEquals(List.of(), results.stream().filter(r -> r.status() != CaseStatus.PASSED)
                    .map(r -> r.id() + ": " + r.message()).toList());
        }
    }

    @Test
    void withFreshVectorsAndADisguiseTheLookupIsNotConformant() throws Exception {
        // --no-sandbox: the lookup must see the corpus, so that only the fresh vectors and the disguise stop it
        Cli c = Cli.run("certify", "--iut", LOOKUP, "--no-sandbox", "--no-probe", "--seed", "2026", "--out", dir.toString());
        assertEquals(0, c.exitCode(), c.err());
        assertTrue(c.out().contains("Basic Level: not conformant"), c.out());
        JsonNode report = new ObjectMapper().readTree(dir.resolve("report.json").toFile());
        int positive = 0;
        int failed = 0;
        int negative = 0;
        int negativeFailed = 0;
        for (JsonNode k : report.path("cases")) {
            if (k.path("id").asText().startsWith("N-")) {
                // reordered, the case no longer matches; rejecting what it does not know, the lookup rejects the
                // accepted twin too (RepairedTwin), and a rejection counts only when the twin was loaded
                negative++;
                if (!k.path("status").asText().equals("passed")) {
                    negativeFailed++;
                }
                continue;
            }
            positive++;
            if (!k.path("status").asText().equals("passed")) {
                failed++;
            }
        }
        long corpusPositive = org.fclcert.corpus.Corpus.load(java.nio.file.Path.of("conformance")).cases().stream()
                .filter(k -> !k.expectReject()).count();
        assertEquals(corpusPositive, positive);
        assertTrue(failed > corpusPositive * 4 / 5, "only " + failed + " of " + positive + " positive cases failed the lookup");
        assertTrue(negativeFailed > negative / 2, "only " + negativeFailed + " of " + negative + " negative cases failed"
                + " the lookup");
        assertEquals("2026", report.path("origin").path("provenance").path("seed").asText());
        // the executable and the script it runs are identified by their hashes; the name it gives is a claim
        JsonNode iut = report.path("origin").path("provenance").path("iut");
        assertEquals("lookup", iut.path("claimedName").asText());
        assertTrue(iut.path("executable").asText().contains("python3"), iut.toString());
        assertTrue(iut.path("files").toString().contains("lookup.py"), iut.toString());
        assertTrue(iut.path("files").get(1).path("sha256").asText().matches("[0-9a-f]{64}"), iut.toString());
        // and the run, reports and evidence are consistent
        Cli verify = Cli.run("report", "--verify", dir.toString());
        assertEquals(0, verify.exitCode(), verify.err());
    }
}
