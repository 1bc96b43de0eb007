package org.fclcert.iut;

import java.util.List;

/**
 * Opens an implementation under test from its spec: {@code reference}, {@code java:CLASS}, {@code process:COMMAND},
 * or a built-in adapter: fuzzylite 6.0 ({@code fuzzylite} or {@code fuzzylite:PATH}), jfuzzylite 6.0.1
 * ({@code jfuzzylite} or {@code jfuzzylite:JAR}), jFuzzyLogic ({@code jfuzzylogic:JAR}) and FFLL 2.2.1
 * ({@code ffll} or {@code ffll:LIBRARY}).
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
        if (spec.equals(FfllIut.SPEC) || spec.startsWith(FfllIut.SPEC + ":")) {
            return FfllIut.open(spec, options);
        }
        if (spec.startsWith("process:")) {
            List<String> command = CommandLineSplitter.split(spec.substring("process:".length()));
            return new ProcessIut(spec, command, options);
        }
        throw new IutException(
                IutException.Kind.INFRA,
                "unknown implementation under test '" + spec + "': use reference, java:CLASS, process:COMMAND, fuzzylite[:PATH], jfuzzylite[:JAR], jfuzzylogic:JAR or ffll[:LIBRARY]");
    }

    /**
     * What a built-in adapter cannot observe of its library, in sentences for the reports (empty for other
     * specs). The details are in {@code docs/iut-protocol.md}, in the adapter's section.
     */
    public static List<String> unobservable(String spec) {
        String s = spec == null ? "" : spec.strip();
        if (s.equals(FuzzyliteIut.SPEC) || s.startsWith(FuzzyliteIut.SPEC + ":")) {
            return List.of("fuzzylite silently drops a rule it cannot read (upper-case IF, IS NOT, comma-separated"
                    + " conclusions, an undefined term) and still loads: such a rule shows only as wrong values",
                    "it builds only the first function block of a program",
                    "see docs/iut-protocol.md, \"fuzzylite\"");
        }
        if (s.equals(JfuzzyliteImplementation.SPEC) || s.startsWith(JfuzzyliteImplementation.SPEC + ":")) {
            return List.of("jfuzzylite builds only the first function block of a program",
                    "its variables start at NaN: the adapter sets every input to 0 (the initial value of a REAL)"
                            + " when an instance is made, so a program used directly must set every input",
                    "a call that hangs cannot be killed in process: it is abandoned on its thread",
                    "see docs/iut-protocol.md, \"jfuzzylite\"");
        }
        if (s.equals(JFuzzyLogicIut.SPEC) || s.startsWith(JFuzzyLogicIut.SPEC + ":")) {
            return List.of("jFuzzyLogic prints parse errors and still returns a system: fclcert counts a printed"
                    + " parse error as a rejection; one it recovers from without printing shows only as wrong values",
                    "its variables start at NaN: the adapter sets every input to 0 (the initial value of a REAL)"
                            + " when an instance is made, so a program used directly must set every input",
                    "it runs in a JVM of its own; its static state lives as long as that JVM",
                    "see docs/iut-protocol.md, \"jFuzzyLogic\"");
        }
        if (s.equals(FfllIut.SPEC) || s.startsWith(FfllIut.SPEC + ":")) {
            return List.of("FFLL addresses inputs by their index in declaration order and has one output: the bridge"
                    + " matches input names to FFLL's own variables and returns that output only",
                    "FFLL has no DEFAULT: when no rule fired it returns the smallest positive float (FLT_MIN,"
                            + " about 1.2e-38), which the bridge passes on unchanged",
                    "FFLL reads only the first function block and loads programs from files; a crash (segmentation"
                            + " fault) ends its process, which is restarted",
                    "see docs/iut-protocol.md, \"FFLL\"");
        }
        return List.of();
    }
}
