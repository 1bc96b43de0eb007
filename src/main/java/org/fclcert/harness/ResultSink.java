package org.fclcert.harness;

import org.fclcert.probe.DataCheckEntry;
import java.io.IOException;
import java.util.List;

/** Receives the run header, then each case result as soon as the case has finished. */
public interface ResultSink {
    void header(RunHeader header) throws IOException;

    void accept(CaseResult result) throws IOException;

    /** The Table 11 data check list as measured by the probes (at most once per run). */
    default void dataCheckList(List<DataCheckEntry> entries) throws IOException {
    }
}
