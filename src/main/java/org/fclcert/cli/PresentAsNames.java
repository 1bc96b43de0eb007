package org.fclcert.cli;

import java.util.Iterator;
import org.fclcert.orchestration.PresentAs;
import picocli.CommandLine.TypeConversionException;

/** {@code --present-as}'s words for picocli's help text and completion, drawn from {@link PresentAs#words()}. */
final class PresentAsNames implements Iterable<String> {
    @Override
    public Iterator<String> iterator() {
        return PresentAs.words().iterator();
    }

    /** A word as picocli converts it: an unknown one is a usage error naming the words there are. */
    static PresentAs convert(String word) {
        try {
            return PresentAs.byWord(word);
        } catch (IllegalArgumentException e) {
            throw new TypeConversionException("expected one of " + DialectName.Naming.list(new PresentAsNames())
                    + " (case-insensitive) but was '" + word + "'");
        }
    }
}
