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

    public static Report run(ImplementationUnderTest iut, Path corpusDir) throws Exception {
        Corpus corpus = Corpus.load(corpusDir);
        List<RunCase> cases = RunCases.from(corpus.cases());
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
