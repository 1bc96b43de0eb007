package org.fclcert.syntax.dialect;

import java.util.Arrays;
import java.util.List;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.OrAlgorithm;

/**
 * The words a format reads after {@code AND :}, {@code OR :}, {@code ACT :}, {@code ACCU :} and {@code METHOD :},
 * spelt as its texts spell them: for the standard, Tables 1 and 3 to 5; for a library's dialect, the lists its
 * reader names in its own messages (so the reader and whoever offers the words, such as the language server's
 * completion, read one list).
 */
public record DialectMethods(List<String> and, List<String> or, List<String> activation, List<String> accumulation,
        List<String> defuzzification) {
    /** The standard's own: Table 3 (AND, OR), Table 4 (ACT), Table 5 (ACCU), Table 1 (METHOD). */
    public static final DialectMethods STANDARD = new DialectMethods(
            Arrays.stream(AndAlgorithm.values()).filter(AndAlgorithm::standard).map(Enum::name).toList(),
            Arrays.stream(OrAlgorithm.values()).filter(OrAlgorithm::standard).map(Enum::name).toList(),
            Arrays.stream(ActivationMethod.values()).filter(ActivationMethod::standard).map(Enum::name).toList(),
            Arrays.stream(AccumulationMethod.values()).filter(AccumulationMethod::standard).map(Enum::name).toList(),
            Arrays.stream(DefuzzificationMethod.values()).filter(DefuzzificationMethod::standard)
                    .map(DefuzzificationMethod::keyword).toList());

    public DialectMethods {
        and = List.copyOf(and);
        or = List.copyOf(or);
        activation = List.copyOf(activation);
        accumulation = List.copyOf(accumulation);
        defuzzification = List.copyOf(defuzzification);
    }

    /** The words of a format: the standard's for the strict reader and for formats without these statements. */
    public static DialectMethods of(Dialect dialect) {
        return dialect.reader() instanceof DialectReader r ? r.methods() : STANDARD;
    }

    /** A library dialect's lists, as its reader names them in messages ("MIN, PROD, BDIF"). */
    static DialectMethods of(LibraryDialect d) {
        return new DialectMethods(split(d.andNames()), split(d.orNames()), split(d.activationNames()),
                split(d.accumulationNames()), split(d.methodNames()));
    }

    private static List<String> split(String names) {
        return Arrays.stream(names.split(",")).map(String::strip).filter(w -> !w.isEmpty()).toList();
    }
}
