package org.fclcert.syntax.dialect;

import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import org.fclcert.syntax.FclReader;
import org.fclcert.syntax.StrictReader;

/**
 * The one list of the formats fclcert reads: the standard itself and the dialects of the libraries in the wild
 * (docs/peers.md, docs/dialects.md). Each constant is the format's registration on the reading side: its
 * command-line name, its name in messages, a line for the help texts and its reader. Everything that lists
 * formats — {@code --dialect}, {@code --present-as}, {@code convert --from/--to}, the Maven plugin, {@code --dialect
 * auto} — is drawn from here; the writing side is {@code org.fclcert.write.DialectWriters.writer} (one case per
 * constant, which the compiler holds complete). Every reader produces the same semantic model; a dialect reader
 * records each construct outside the standard as an Open Level feature of the program.
 */
public enum Dialect {
    STRICT("strict", "IEC 61131-7 as written", "IEC 61131-7", StrictReader::new),
    FFLL("ffll", "Free Fuzzy Logic Library (FFLL)", "FFLL's FCL", FfllReader::new),
    JFUZZYLOGIC("jfuzzylogic", "jFuzzyLogic", "jFuzzyLogic's FCL", JFuzzyLogicReader::new),
    FUZZYLITE("fuzzylite", "fuzzylite", "fuzzylite's FCL", FuzzyliteReader::new),
    FLL("fll", "fuzzylite's FLL", "fuzzylite's own format (.fll)", FllReader::new),
    FIS("fis", "MATLAB FIS", "MATLAB's .fis text (Mamdani, Sugeno)", FisReader::new);

    private final String cliName;
    private final String displayName;
    private final String summary;
    private final Supplier<FclReader> reader;

    Dialect(String cliName, String displayName, String summary, Supplier<FclReader> reader) {
        this.cliName = cliName;
        this.displayName = displayName;
        this.summary = summary;
        this.reader = reader;
    }

    /** The name used on the command line ({@code --dialect ffll}). */
    public String cliName() {
        return cliName;
    }

    public String displayName() {
        return displayName;
    }

    /** A few words for the help texts: what the format is ({@code fuzzylite's FCL}). */
    public String summary() {
        return summary;
    }

    /** A new reader of this format (the strict reader for {@link #STRICT}). */
    public FclReader reader() {
        return reader.get();
    }

    public static Optional<Dialect> byCliName(String name) {
        return Arrays.stream(values()).filter(d -> d.cliName.equalsIgnoreCase(name)).findFirst();
    }

    /** The command-line names, in declaration order. */
    public static List<String> cliNames() {
        return Arrays.stream(values()).map(Dialect::cliName).toList();
    }
}
