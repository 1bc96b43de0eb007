package org.fclcert.iut;

import java.util.Map;
import java.util.Optional;

/** A Java class implementing the vendor SPI. Work in progress. */
final class JavaIut implements ImplementationUnderTest {
    static JavaIut open(String spec, String className, IutOptions options) throws IutException {
        throw notYet();
    }

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
        return new IutException(IutException.Kind.INFRA, "java: IUTs is not available yet");
    }
}
