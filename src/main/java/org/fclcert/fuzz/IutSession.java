package org.fclcert.fuzz;

import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;

/**
 * One job's implementation under test, reopened after it crashed, hung or replied garbage, so that the run
 * goes on. Not thread-safe: one job, one session.
 */
public final class IutSession implements AutoCloseable {
    /** Opens a fresh session of the implementation (one per job). */
    @FunctionalInterface
    public interface Factory {
        ImplementationUnderTest open() throws IutException;
    }

    private final Factory factory;
    private ImplementationUnderTest iut;
    private int restarts;

    IutSession(Factory factory) throws IutException {
        this.factory = factory;
        this.iut = factory.open();
    }

    ImplementationUnderTest iut() {
        return iut;
    }

    /** Closes the implementation and opens it again. */
    void restart() throws IutException {
        iut.close();
        restarts++;
        iut = factory.open();
    }

    int restarts() {
        return restarts;
    }

    @Override
    public void close() {
        iut.close();
    }
}
