package org.fclcert.harness;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fclcert.iut.ImplementationUnderTest;

/**
 * Runs a case with evidence no earlier run could have produced: its fresh vectors ({@link FreshVectors}) after
 * its own, its text disguised ({@link Disguise}), both drawn from the run seed, and the implementation's replies
 * kept in the result ({@link CaseResult#replies}). The case passes only when the corpus vectors and the fresh ones
 * pass. {@link Rejudge} prepares a case the same way to judge its evidence again.
 */
public final class FreshEvidence {
    private FreshEvidence() {
    }

    /** A case as this run sends it: {@code plain} the corpus case with its fresh vectors, and its disguise. */
    record Prepared(RunCase corpus, RunCase plain, Disguise disguise) {
        RunCase sent() {
            return disguise.apply(plain);
        }

        int fresh() {
            return plain.vectors().size() - corpus.vectors().size();
        }

        /** The result with what the run did to the case said in a note. */
        CaseResult noted(CaseResult r, long seed) {
            List<String> notes = new ArrayList<>(r.verdict().notes());
            String vectors = fresh() == 0 ? "no fresh vectors" : "steps " + (corpus.vectors().size() + 1) + "–"
                    + plain.vectors().size() + " are fresh vectors drawn for this run";
            Optional<String> exempt = Disguise.exemption(corpus);
            notes.add("run seed " + RunSeed.text(seed) + ": " + vectors + (exempt.isPresent()
                    ? "; the program was sent undisguised (" + exempt.get() + ")" : "; the program was sent disguised ("
                    + disguise.renamed() + " names renamed, " + disguise.lineShift() + " line(s) put in front"
                    + (disguise.reordered() ? ", declarations, blocks, terms and rules reordered" : "")
                    + (corpus.expectReject() ? ", the error's line following its token" : "")
                    + disguise.twin().map(t -> "; its accepted twin (the defect repaired) was sent " + (t.first() ? "before"
                            : "after") + " it").orElse("")
                    + ")"));
            return new CaseResult(r.plan(), new CaseResult.Verdict(r.status(), r.message(), notes,
                    r.verdict().rejection()), r.evidence(), r.export(), r.setup(), r.presented(), r.replies());
        }
    }

    static Prepared prepare(RunCase c, long seed) {
        RunCase plain = FreshVectors.withFresh(c, seed);
        return new Prepared(c, plain, Disguise.draw(plain, RunSeed.forCase(seed, c.id(), "disguise")));
    }

    static CaseRunner.Ran run(CaseRunner runner, ImplementationUnderTest iut, RunCase c, long seed) {
        Prepared p = prepare(c, seed);
        DisguisedIut wire = new DisguisedIut(iut, p.disguise());
        CaseRunner.Ran ran = runner.run(wire, p.sent(), iut, p.plain(), p.disguise().twin(), p.disguise());
        return new CaseRunner.Ran(p.noted(ran.result(), seed).withReplies(wire.exchanges()), ran.gaveUp());
    }
}
