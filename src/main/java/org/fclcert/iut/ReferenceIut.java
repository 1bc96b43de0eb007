package org.fclcert.iut;

import java.util.Map;
import java.util.Optional;

/** fclcert's own evaluator as an implementation under test (in process). Work in progress. */
final class ReferenceIut implements ImplementationUnderTest {
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
        return new IutException(IutException.Kind.INFRA, "the reference IUT is not available yet");
    }
}
