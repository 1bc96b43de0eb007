package org.fclcert.harness;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import org.fclcert.corpus.Corpus;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutInfo;
import org.fclcert.report.Report;
import org.fclcert.report.ReportBuilder;

/** Runs a whole corpus against an implementation in process and builds the report (what certify does). */
public final class Certify {
    private Certify() {
    }

    /** A corpus loaded once and turned into runner cases, for running many implementations on it. */
    public record Prepared(Path dir, String sha256, List<RunCase> cases) {
        public static Prepared load(Path dir) throws Exception {
            Corpus corpus = Corpus.load(dir);
            return new Prepared(dir, corpus.sha256(), RunCases.from(corpus.cases()));
        }
    }

    public static Report run(ImplementationUnderTest iut, Path corpusDir) throws Exception {
        return run(iut, Prepared.load(corpusDir));
    }

    public static Report run(ImplementationUnderTest iut, Prepared corpus) throws Exception {
        Path corpusDir = corpus.dir();
        List<RunCase> cases = corpus.cases();
        IutInfo info = iut.hello();
        RunHeader header = RunHeaders.of(info, info.command(), null, corpusDir.toString(), corpus.sha256(), cases,
                cases, List.of(List.of(), List.of(), List.of()));
        List<CaseResult> results = new Runner(RunListener.NONE).run(iut, header, cases, new ResultSink() {
            @Override
            public void header(RunHeader h) {
            }

            @Override
            public void accept(CaseResult result) throws IOException {
            }
        });
        return ReportBuilder.build(header, results, List.of(), List.of(), Instant.now());
    }
}
