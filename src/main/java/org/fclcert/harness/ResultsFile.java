package org.fclcert.harness;

import org.fclcert.probe.DataCheckEntry;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A {@code results.jsonl} read back: its header, the case results it holds, and the lines it could not use
 * (typically the last line of a run killed while writing it).
 */
public record ResultsFile(RunHeader header, List<CaseResult> results, List<DataCheckEntry> dataCheckList,
        List<String> problems) {
    public ResultsFile {
        results = List.copyOf(results);
        dataCheckList = List.copyOf(dataCheckList);
        problems = List.copyOf(problems);
    }

    /** Reads a results file; fails with a located message when there is no usable header line. */
    public static ResultsFile read(Path file) throws IOException, InvalidResultsException {
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        RunHeader header = null;
        List<CaseResult> results = new ArrayList<>();
        List<DataCheckEntry> dataCheckList = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.isBlank()) {
                continue;
            }
            String where = file + ":" + (i + 1);
            try {
                JsonNode node = Json.mapper().readTree(line);
                String type = node.path("type").asText("");
                if (type.equals("run")) {
                    header = Json.mapper().treeToValue(node, RunHeader.class);
                } else if (type.equals("case")) {
                    results.add(Json.mapper().treeToValue(node, CaseResult.class));
                } else if (type.equals("dataCheckList")) {
                    dataCheckList.clear();
                    dataCheckList.addAll(Json.mapper().treeToValue(node, ResultsWriter.DataCheckLine.class).entries());
                } else {
                    problems.add(where + ": line of unknown type '" + type + "' ignored");
                }
            } catch (JsonProcessingException e) {
                problems.add(where + ": unreadable line ignored (" + e.getOriginalMessage() + ")");
            }
        }
        if (header == null) {
            throw new InvalidResultsException(file + ": no run header line ({\"type\":\"run\",...}); "
                    + "is this a results.jsonl written by fclcert certify?");
        }
        return new ResultsFile(header, results, dataCheckList, problems);
    }

    /** The file cannot be made into a report. */
    public static final class InvalidResultsException extends Exception {
        private static final long serialVersionUID = 1L;

        public InvalidResultsException(String message) {
            super(message);
        }
    }
}
