package org.fclcert.iut;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads what the fuzzylite 6.0 command line writes: its banner (for the version), the FLL text of an
 * engine it imported (for the variable names, in its order), the data table of an evaluation, and its
 * error messages (for the line they name). Only text is read; nothing of fuzzylite is linked.
 */
final class FuzzyliteText {
    private static final Pattern VERSION = Pattern.compile("(?m)^version:\\s*(\\S+)");

    private FuzzyliteText() {}

    /** The engine fuzzylite built from a program, as its FLL export lists it. */
    record Engine(String name, List<String> inputs, List<String> outputs) {
        Engine {
            inputs = List.copyOf(inputs);
            outputs = List.copyOf(outputs);
        }
    }

    /** The version fuzzylite's banner names ({@code version: 6.0}). */
    static Optional<String> version(String banner) {
        Matcher m = VERSION.matcher(banner);
        return m.find() ? Optional.of(m.group(1)) : Optional.empty();
    }

    /** Engine name and the input and output variables, in fuzzylite's order, from FLL text. */
    static Engine engine(String fll) {
        String name = "";
        List<String> inputs = new ArrayList<>();
        List<String> outputs = new ArrayList<>();
        for (String line : fll.split("\\R")) {
            if (line.startsWith("Engine:")) {
                name = line.substring("Engine:".length()).strip();
            } else if (line.startsWith("InputVariable:")) {
                inputs.add(line.substring("InputVariable:".length()).strip());
            } else if (line.startsWith("OutputVariable:")) {
                outputs.add(line.substring("OutputVariable:".length()).strip());
            }
        }
        return new Engine(name, inputs, outputs);
    }

    /**
     * The message of fuzzylite's first error: its first non-blank line of output (the second line, such as
     * {@code {at ::fromString() [line:84]}}, names fuzzylite's own source and is dropped).
     */
    static String firstMessage(String stdout) {
        return stdout.lines().map(String::strip).filter(l -> !l.isEmpty()).findFirst().orElse("");
    }

    /**
     * The 1-based line of {@code program} an error message points at: the number when fuzzylite gives one,
     * else the first line whose text (semicolons dropped, blanks collapsed — as fuzzylite quotes it) equals
     * the quoted statement. Empty when the message names no line, or the quote matches none.
     */
    static OptionalInt line(String message, String program) {
        return LibraryMessages.fuzzyliteLine(message, program);
    }

    /**
     * The rows of a data table written with {@code -dheader true -dinputs false}: a header of output names,
     * then one row of values per evaluation. {@code nan} and {@code inf} (in any sign and case) are read as
     * such.
     *
     * @throws IllegalArgumentException when the table is not of that shape (the message says how)
     */
    static Table table(String fld) {
        List<String> lines = fld.lines().filter(l -> !l.isBlank()).toList();
        if (lines.isEmpty()) {
            throw new IllegalArgumentException("the table is empty");
        }
        List<String> names = List.of(lines.get(0).strip().split("\\s+"));
        List<double[]> rows = new ArrayList<>();
        for (int k = 1; k < lines.size(); k++) {
            String[] cells = lines.get(k).strip().split("\\s+");
            if (cells.length != names.size()) {
                throw new IllegalArgumentException("row " + k + " has " + cells.length + " values for "
                        + names.size() + " outputs: " + lines.get(k).strip());
            }
            double[] row = new double[cells.length];
            for (int c = 0; c < cells.length; c++) {
                row[c] = number(cells[c]);
            }
            rows.add(row);
        }
        return new Table(names, rows);
    }

    /** A data table: output names and rows of values. */
    record Table(List<String> names, List<double[]> rows) {
    }

    static double number(String cell) {
        String s = cell.strip().toLowerCase(java.util.Locale.ROOT);
        return switch (s) {
            case "nan", "-nan", "+nan" -> Double.NaN;
            case "inf", "+inf", "infinity" -> Double.POSITIVE_INFINITY;
            case "-inf", "-infinity" -> Double.NEGATIVE_INFINITY;
            default -> {
                try {
                    yield Double.parseDouble(s);
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("'" + cell + "' is not a number");
                }
            }
        };
    }
}
