package org.fclcert.cli;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fclcert.cli.EvalCommand.InputProblem;

/**
 * The input table of {@code eval --csv}: a header line of input names and rows of numbers,
 * comma-separated. Blank lines and lines starting with {@code #} are skipped; cells are trimmed.
 */
record CsvTable(List<String> columns, List<Row> rows, int headerLine) {
    /** One data row and its 1-based line number in the file. */
    record Row(int line, List<String> cells) {
    }

    static CsvTable parse(String path, List<String> lines) throws InputProblem {
        List<String> columns = null;
        int headerLine = 0;
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            List<String> cells = Arrays.stream(line.split(",", -1)).map(String::strip).toList();
            if (columns == null) {
                if (cells.size() == 1 && line.indexOf(';') > 0) {
                    throw new InputProblem(path + ":" + (i + 1) + ": the header is separated by semicolons; eval --csv"
                            + " reads comma-separated values (e.g. " + line.replace(';', ',') + ")");
                }
                columns = cells;
                headerLine = i + 1;
                if (cells.stream().anyMatch(String::isEmpty)) {
                    throw new InputProblem(path + ":" + (i + 1) + ": the header has an empty column name");
                }
            } else if (cells.size() != columns.size()) {
                throw new InputProblem(path + ":" + (i + 1) + ": " + DiagnosticPrinter.count(cells.size(), "cell")
                        + " where the header has " + columns.size());
            } else {
                rows.add(new Row(i + 1, cells));
            }
        }
        if (columns == null) {
            throw new InputProblem(path + ": no header line (input names separated by commas)");
        }
        return new CsvTable(columns, rows, headerLine);
    }
}
