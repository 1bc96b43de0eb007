package org.fclcert.iut;

import java.util.List;
import java.util.Optional;
import org.fclcert.syntax.dialect.Dialect;

/**
 * The one list of the ways to reach an implementation under test ({@link #KINDS}) — {@code reference},
 * {@code java:CLASS}, {@code process:COMMAND} and the built-in library adapters — and {@link #open(String, IutOptions)},
 * which opens one from its spec. {@code --iut}'s help and completion, the Maven plugin's messages,
 * {@code --present-as auto} and the reports' "not observable" notes are all drawn from here: adding a built-in adapter
 * is its class and one entry.
 */
public final class Iuts {
    private Iuts() {}

    /** Opens an implementation from the text after its kind's name ({@code ""} when the spec has none). */
    @FunctionalInterface
    public interface Opener {
        ImplementationUnderTest open(String spec, String argument, IutOptions options) throws IutException;
    }

    /** Whether a kind's spec takes {@code :ARGUMENT} after its name. */
    public enum Argument { NONE, OPTIONAL, REQUIRED }

    /**
     * One kind of implementation under test.
     *
     * @param name         the spec's first word ({@code fuzzylite})
     * @param syntax       the spec as help texts show it ({@code fuzzylite[:PATH]})
     * @param summary      what it is, a few words for help texts and docs
     * @param argument     whether {@code :ARGUMENT} follows the name
     * @param presentedAs  the layout {@code --present-as auto} sends its positive cases in (empty: standard FCL only)
     * @param unobservable what the adapter cannot observe of its library, sentences for the reports
     * @param opener       opens a session
     */
    public record Kind(String name, String syntax, String summary, Argument argument, Optional<Dialect> presentedAs,
            List<String> unobservable, Opener opener) {
        public Kind {
            unobservable = List.copyOf(unobservable);
        }

        /** Whether {@code spec} (stripped) names this kind. */
        public boolean matches(String spec) {
            return switch (argument) {
                case NONE -> spec.equals(name);
                case OPTIONAL -> spec.equals(name) || spec.startsWith(name + ":");
                case REQUIRED -> spec.startsWith(name + ":");
            };
        }

        String argumentOf(String spec) {
            return spec.length() > name.length() ? spec.substring(name.length() + 1) : "";
        }
    }

    private static final String NAN_INPUTS = "its variables start at NaN: the adapter sets every input to 0 (the"
            + " initial value of a REAL) when an instance is made, so a program used directly must set every input";

    /** Every kind, in the order help texts list them; a spec is matched against them in this order. */
    public static final List<Kind> KINDS = List.of(
            new Kind("reference", "reference", "fclcert's own reference evaluator", Argument.NONE, Optional.empty(),
                    List.of(), (spec, argument, options) -> new ReferenceIut()),
            new Kind("java", "java:CLASS", "a class implementing the vendor SPI (org.fclcert.iut.spi), on --classpath,"
                    + " in a child JVM (--in-process: in fclcert's JVM)", Argument.REQUIRED, Optional.empty(), List.of(),
                    (spec, argument, options) -> options.inProcess() ? JavaIut.open(spec, argument.strip(), options)
                            : JavaProcessIut.open(spec, argument.strip(), options)),
            new Kind("process", "process:COMMAND", "a program speaking the JSON-lines protocol (docs/iut-protocol.md)",
                    Argument.REQUIRED, Optional.empty(), List.of(),
                    (spec, argument, options) -> new ProcessIut(spec, CommandLineSplitter.split(argument), options)),
            new Kind(FuzzyliteIut.SPEC, "fuzzylite[:PATH]", "the fuzzylite 6.0 command line (Debian package fuzzylite)",
                    Argument.OPTIONAL, Optional.of(Dialect.FUZZYLITE), List.of(
                            "fuzzylite silently drops a rule it cannot read (upper-case IF, IS NOT, comma-separated"
                                    + " conclusions, an undefined term) and still loads: such a rule shows only as wrong values",
                            "it builds only the first function block of a program",
                            "see docs/iut-protocol.md, \"fuzzylite\""),
                    (spec, argument, options) -> FuzzyliteIut.open(spec, options)),
            new Kind(JfuzzyliteImplementation.SPEC, "jfuzzylite[:JAR]", "jfuzzylite 6.0.1 in fclcert's JVM, in a class loader of its own",
                    Argument.OPTIONAL, Optional.of(Dialect.FUZZYLITE), List.of(
                            "jfuzzylite builds only the first function block of a program",
                            NAN_INPUTS,
                            "a call that hangs cannot be killed in process: it is abandoned on its thread",
                            "see docs/iut-protocol.md, \"jfuzzylite\""),
                    (spec, argument, options) -> JfuzzyliteImplementation.open(spec, options)),
            new Kind(JFuzzyLogicIut.SPEC, "jfuzzylogic:JAR", "jFuzzyLogic, its jar run in a JVM of its own",
                    Argument.OPTIONAL, Optional.of(Dialect.JFUZZYLOGIC), List.of(
                            "jFuzzyLogic prints parse errors and still returns a system: fclcert counts a printed"
                                    + " parse error as a rejection; one it recovers from without printing shows only as wrong values",
                            NAN_INPUTS,
                            "it runs in a JVM of its own; its static state lives as long as that JVM",
                            "see docs/iut-protocol.md, \"jFuzzyLogic\""),
                    (spec, argument, options) -> JFuzzyLogicIut.open(spec, options)),
            new Kind(FfllIut.SPEC, "ffll[:LIBRARY]", "FFLL 2.2.1 through fclcert's bridge, in a process of its own",
                    Argument.OPTIONAL, Optional.of(Dialect.FFLL), List.of(
                            "FFLL addresses inputs by their index in declaration order and has one output: the bridge"
                                    + " matches input names to FFLL's own variables and returns that output only",
                            "FFLL has no DEFAULT: when no rule fired it returns the smallest positive float (FLT_MIN,"
                                    + " about 1.2e-38), which the bridge passes on unchanged",
                            "FFLL reads only the first function block and loads programs from files; a crash (segmentation"
                                    + " fault) ends its process, which is restarted",
                            "see docs/iut-protocol.md, \"FFLL\""),
                    (spec, argument, options) -> FfllIut.open(spec, options)),
            new Kind(PyfuzzyliteIut.SPEC, "pyfuzzylite[:PYTHON]", "pyfuzzylite 8 (PyPI) through fclcert's bridge, in a"
                    + " Python process of its own", Argument.OPTIONAL, Optional.of(Dialect.FLL), List.of(
                            "pyfuzzylite reads only FLL: standard FCL is refused by its FLL importer, so its semantics"
                                    + " are reached only through the cases presented as FLL",
                            "FLL holds one engine: only the first function block of a program is presented",
                            "its importer names no line: the bridge gives the first line that its message quotes",
                            "see docs/iut-protocol.md, \"pyfuzzylite\""),
                    (spec, argument, options) -> PyfuzzyliteIut.open(spec, options)),
            new Kind(OctaveFltIut.SPEC, "octave-flt[:OCTAVE-CLI]", "the Octave fuzzy-logic-toolkit (readfis, evalfis)"
                    + " through fclcert's bridge, one octave-cli per session", Argument.OPTIONAL, Optional.of(Dialect.FIS),
                    List.of("it reads MATLAB's FIS only: programs are presented as FIS, so a case FIS cannot express"
                                    + " (a DEFAULT used where no rule fires, point terms other than triangles, trapezoids"
                                    + " and shoulders, rules other than one flat AND or OR) is not presented",
                            "evalfis samples a Mamdani output at 101 points of its Range, and refuses an input outside"
                                    + " an input's Range: the bridge widens that Range (it has no other effect)",
                            "see docs/iut-protocol.md, \"Octave fuzzy-logic-toolkit\""),
                    (spec, argument, options) -> OctaveFltIut.open(spec, options)));

    /** The kind a spec names, if any. */
    public static Optional<Kind> kind(String spec) {
        String s = spec == null ? "" : spec.strip();
        return KINDS.stream().filter(k -> k.matches(s)).findFirst();
    }

    /** The specs as help texts show them ({@code reference}, {@code java:CLASS}, ..., {@code fuzzylite[:PATH]}). */
    public static List<String> syntaxes() {
        return KINDS.stream().map(Kind::syntax).toList();
    }

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
        String s = spec.strip();
        Kind kind = kind(s).orElseThrow(() -> new IutException(IutException.Kind.INFRA,
                "unknown implementation under test '" + s + "': use " + String.join(", ", syntaxes())));
        return kind.opener().open(s, kind.argumentOf(s), options);
    }

    /** The layout {@code --present-as auto} picks for a spec: its kind's, empty for none or an unknown spec. */
    public static Optional<Dialect> presentedAs(String spec) {
        return kind(spec).flatMap(Kind::presentedAs);
    }

    /**
     * Whether an implementation is sent, as it is, a corpus case written in {@code dialect} (a case's {@code dialect:},
     * conformance/README.md): standard FCL always; a library's dialect only by the adapter whose own layout it is
     * ({@link Kind#presentedAs}: fuzzylite's FCL to fuzzylite and jfuzzylite, FLL to pyfuzzylite, ...), and every
     * dialect by the reference, which reads each with fclcert's reader of it. A vendor's implementation ({@code java:},
     * {@code process:}) speaks the standard only. The others get such a case as not presentable (not determined).
     */
    public static boolean reads(String spec, Dialect dialect) {
        if (dialect == Dialect.STRICT) {
            return true;
        }
        Optional<Kind> kind = kind(spec);
        return kind.isPresent() && (kind.get().name().equals("reference")
                || kind.get().presentedAs().equals(Optional.of(dialect)));
    }

    /**
     * What a built-in adapter cannot observe of its library, in sentences for the reports (empty for other
     * specs). The details are in {@code docs/iut-protocol.md}, in the adapter's section.
     */
    public static List<String> unobservable(String spec) {
        return kind(spec).map(Kind::unobservable).orElse(List.of());
    }
}
