package org.fclcert.cli;

import java.io.PrintStream;

/**
 * SIGINT, SIGTERM and SIGHUP in the moments before a command has its own handling (the run's shutdown hook of
 * {@code certify}, {@code probe} and {@code fuzz}): without a hook of the JVM's, such a signal ended fclcert silently with exit
 * code 143 and nothing written (issue 27). {@link #install} is the first thing {@link Main#main} does; from then on
 * a signal ends fclcert with a message saying how far it had come. A command that registers its own hook calls
 * {@link #handledByCommand()}, after which this one stays silent. (The JVM's own start, before {@code main}, has no
 * Java code to answer a signal.)
 */
final class EarlySignals {
    private static boolean installed;
    private static volatile boolean commandStarted;
    private static volatile boolean handled;
    private static volatile boolean finished;

    private EarlySignals() {}

    /** Registers the hook once per JVM; it writes to {@code err}. */
    static synchronized void install(PrintStream err) {
        if (installed) {
            return;
        }
        installed = true;
        Runtime.getRuntime().addShutdownHook(new Thread(() -> interrupted(err), "fclcert-early-signal"));
    }

    /** picocli has parsed the command line and is running the command. */
    static void commandStarted() {
        commandStarted = true;
    }

    /** The command answers signals with a hook of its own from now on. */
    static void handledByCommand() {
        handled = true;
    }

    /** fclcert is ending normally ({@code System.exit} runs the hooks too): nothing to say. */
    static void finished() {
        finished = true;
    }

    private static void interrupted(PrintStream err) {
        if (finished || handled) {
            return;
        }
        err.println();
        err.println("fclcert: " + org.fclcert.iut.StopSignal.INTERRUPTED + (commandStarted
                ? " before the command finished; it wrote no outputs of a run (certify, probe and fuzz runs handle a"
                        + " signal themselves once started)"
                : " before the run started; nothing was written"));
        err.flush();
    }
}
