package org.fclcert.harness;

/** Progress of a run, for the command line's progress line (the runner itself never prints). */
public interface RunListener {
    RunListener NONE = new RunListener() {
    };

    default void caseStarted(RunCase c, int index, int total) {
    }

    default void caseFinished(CaseResult result, int index, int total) {
    }
}
