package org.fclcert.harness;

import java.io.IOException;

/** Receives the run header, then each case result as soon as the case has finished. */
public interface ResultSink {
    void header(RunHeader header) throws IOException;

    void accept(CaseResult result) throws IOException;
}
