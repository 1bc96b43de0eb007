package org.fclcert.iut;

import java.util.List;
import java.util.Map;
import java.util.Optional;

/** A separate process speaking JSON lines. Work in progress. */
final class ProcessIut implements ImplementationUnderTest {
    ProcessIut(String spec, List<String> command, IutOptions options) {}

    @Override
    public IutInfo hello() throws IutException {
        throw notYet();
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        throw notYet();
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        throw notYet();
    }

    @Override
    public void reset() throws IutException {
        throw notYet();
    }

    @Override
    public Optional<String> export() throws IutException {
        throw notYet();
    }

    @Override
    public void close() {}

    private static IutException notYet() {
        return new IutException(IutException.Kind.INFRA, "process: IUTs are not available yet");
    }
}
