package org.fclcert.orchestration;

import java.util.List;
import java.util.stream.Collectors;
import org.fclcert.corpus.Corpus;
import org.fclcert.corpus.CorpusIdentity;
import org.fclcert.corpus.CorpusProblem;
import org.fclcert.harness.Provenance;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Toolkit;

/**
 * The corpus of a run before anything runs: which corpus it is (the built-in one, or a custom one, and then which
 * built-in Basic and Extension Level cases it lacks), and, for a custom corpus, that the exact reference reproduces every
 * case's expected values and errors — a case it does not reproduce is refused, named, before any implementation
 * is started.
 */
final class CorpusCheck {
    private CorpusCheck() {
    }

    static Provenance.CorpusIdentity identify(Corpus corpus) throws Certification.CannotCertify {
        Corpus builtIn = CorpusIdentity.builtIn();
        if (CorpusIdentity.isBuiltIn(corpus, builtIn)) {
            return new Provenance.CorpusIdentity(corpus.sha256(), true, "the fclcert conformance corpus "
                    + Toolkit.version() + " (" + corpus.cases().size() + " cases)", List.of());
        }
        List<CorpusProblem> refused = CorpusIdentity.unreproduced(corpus);
        if (!refused.isEmpty()) {
            throw new Certification.CannotCertify("the custom corpus " + corpus.directory() + " is refused: the exact"
                    + " reference does not reproduce what " + refused.size() + " of its case(s) expect, so no"
                    + " implementation can be judged by them:\n" + refused.stream().limit(20).map(CorpusProblem::toString)
                    .collect(Collectors.joining("\n")) + (refused.size() > 20 ? "\n…" : ""));
        }
        return new Provenance.CorpusIdentity(corpus.sha256(), false, "a custom corpus (" + corpus.cases().size()
                + " cases), not the fclcert conformance corpus",
                CorpusIdentity.missingBuiltIn(corpus, builtIn, ConformanceLevel.BASIC),
                CorpusIdentity.missingBuiltIn(corpus, builtIn, ConformanceLevel.EXTENSION));
    }
}
