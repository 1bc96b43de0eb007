package org.fclcert.iut;

import java.util.List;

/**
 * Opens an implementation under test from its spec: {@code reference}, {@code java:CLASS}, {@code process:COMMAND},
 * or a built-in adapter: fuzzylite 6.0 ({@code fuzzylite} or {@code fuzzylite:PATH}), jfuzzylite 6.0.1
 * ({@code jfuzzylite} or {@code jfuzzylite:JAR}) and jFuzzyLogic ({@code jfuzzylogic:JAR}).
 */
public final class Iuts {
    private Iuts() {}

    /**
     * Opens a session. Nothing is started eagerly beyond what is needed to check the spec: a process
     * IUT is started on its first request.
     *
     * @throws IutException of kind {@link IutException.Kind#INFRA} when the spec is malformed, the class
     *     cannot be loaded, or the command is empty
     */
    public static ImplementationUnderTest open(String spec, IutOptions options) throws IutException {
        if (spec == null || spec.isBlank()) {
            throw new IutException(IutException.Kind.INFRA, "no implementation under test given");
        }
        spec = spec.strip();
        if (spec.equals("reference")) {
            return new ReferenceIut();
        }
        if (spec.startsWith("java:")) {
            return JavaIut.open(spec, spec.substring("java:".length()).strip(), options);
        }
        if (spec.equals(FuzzyliteIut.SPEC) || spec.startsWith(FuzzyliteIut.SPEC + ":")) {
            return FuzzyliteIut.open(spec, options);
        }
        if (spec.equals(JfuzzyliteImplementation.SPEC) || spec.startsWith(JfuzzyliteImplementation.SPEC + ":")) {
            return JfuzzyliteImplementation.open(spec, options);
        }
        if (spec.equals(JFuzzyLogicIut.SPEC) || spec.startsWith(JFuzzyLogicIut.SPEC + ":")) {
            return JFuzzyLogicIut.open(spec, options);
        }
        if (spec.startsWith("process:")) {
            List<String> command = CommandLineSplitter.split(spec.substring("process:".length()));
            return new ProcessIut(spec, command, options);
        }
        throw new IutException(
                IutException.Kind.INFRA,
                "unknown implementation under test '" + spec + "': use reference, java:CLASS, process:COMMAND, fuzzylite[:PATH], jfuzzylite[:JAR] or jfuzzylogic:JAR");
    }
}
