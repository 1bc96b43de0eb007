package org.fclcert.harness;

import org.fclcert.probe.DataCheckEntry;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonMappingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.stream.Collectors;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.fclcert.corpus.CorpusCase;
import org.fclcert.iut.IutText;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Limits;

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

    /** The parts of the run header a report is made from. */
    private static final List<String> HEADER_PARTS = List.of("iut", "toolkit", "corpus", "selection");

    /**
     * Reads a results file (a regular file within {@link Limits#MAX_SOURCE_BYTES}); fails with a located message
     * when there is no usable header line. Bytes that are not UTF-8 (a damaged file) become U+FFFD, with a warning.
     */
    public static ResultsFile read(Path file) throws IOException, InvalidResultsException {
        byte[] bytes = Limits.readFile(file);
        List<String> early = new ArrayList<>();
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            text = new String(bytes, StandardCharsets.UTF_8);
            early.add(file + ": bytes that are not UTF-8 read as U+FFFD (the file is damaged)");
        }
        ResultsFile read = parse(file.toString(), text.lines().toList());
        early.addAll(read.problems());
        return new ResultsFile(read.header(), read.results(), read.dataCheckList(), early);
    }

    /**
     * The results file {@code name} (as messages locate it) from its lines; fails with a located message when
     * there is no usable header line.
     */
    public static ResultsFile parse(String name, List<String> lines) throws InvalidResultsException {
        RunHeader header = null;
        List<CaseResult> results = new ArrayList<>();
        List<DataCheckEntry> dataCheckList = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.isBlank()) {
                continue;
            }
            String where = name + ":" + (i + 1);
            try {
                JsonNode node = Json.mapper().readTree(line);
                String type = node.path("type").asText("");
                if (type.equals("run")) {
                    Optional<String> missing = HEADER_PARTS.stream().filter(f -> !node.path(f).isObject()).findFirst();
                    if (missing.isPresent()) {
                        throw new InvalidResultsException(where + ": the run header has no '" + missing.get()
                                + "' object; the file is damaged (rerun fclcert certify to write it again)");
                    }
                    header = Json.mapper().treeToValue(node, RunHeader.class);
                    Optional<String> untold = untold(header);
                    if (untold.isPresent()) {
                        throw new InvalidResultsException(where + ": the run header has no usable '" + untold.get()
                                + "' text; the file is damaged (rerun fclcert certify to write it again)");
                    }
                    for (PlannedCase p : header.selection().planned()) {
                        Optional<String> foreign = foreign(p);
                        if (foreign.isPresent()) {
                            throw new InvalidResultsException(where + ": the run header plans a case whose "
                                    + foreign.get() + " is not in the form fclcert writes; the file is damaged"
                                    + " (rerun fclcert certify to write it again)");
                        }
                    }
                    Set<String> planned = new HashSet<>();
                    for (PlannedCase p : header.selection().planned()) {
                        if (!planned.add(p.id())) {
                            problems.add(where + ": the run header plans case '" + IutText.kept(String.valueOf(p.id()))
                                    + "' more than once; it is reported once");
                        }
                    }
                } else if (type.equals("case")) {
                    Optional<String> missing = Stream.of("id", "status")
                            .filter(f -> !node.path(f).isTextual() || node.path(f).asText().isBlank()).findFirst();
                    if (missing.isPresent()) {
                        problems.add(where + ": case line without '" + missing.get() + "' ignored");
                        continue;
                    }
                    CaseResult result = Json.mapper().treeToValue(node, CaseResult.class);
                    Optional<String> foreign = foreign(result.plan());
                    if (foreign.isPresent()) {
                        problems.add(where + ": case line ignored: its " + foreign.get()
                                + " is not in the form fclcert writes");
                        continue;
                    }
                    results.add(result);
                } else if (type.equals("dataCheckList")) {
                    List<DataCheckEntry> entries = Json.mapper().treeToValue(node, ResultsWriter.DataCheckLine.class)
                            .entries();
                    if (entries == null || entries.stream().anyMatch(ResultsFile::damaged)) {
                        problems.add(where + ": data check list line ignored: an entry lacks a part or has a bound"
                                + " fclcert does not write");
                        continue;
                    }
                    dataCheckList.clear();
                    dataCheckList.addAll(entries);
                } else if (type.equals(ResultsChain.END)) {
                    continue;   // the chain's seal: ResultsChain reads it
                } else {
                    problems.add(where + ": line of unknown type '" + type.replaceAll("[^A-Za-z0-9_-]", "?")
                            .substring(0, Math.min(type.length(), 40)) + "' ignored");
                }
            } catch (JsonMappingException e) {
                // its own message names Java types; say which field, in the file's terms
                String field = e.getPath().stream().map(JsonMappingException.Reference::getFieldName)
                        .filter(Objects::nonNull).collect(Collectors.joining("."));
                problems.add(where + ": line ignored: " + (field.isEmpty() ? "a value" : "field '" + field + "'")
                        + " has a value of the wrong kind");
            } catch (JsonProcessingException e) {
                problems.add(where + ": unreadable line ignored (not one JSON object)");
            } catch (RuntimeException e) {
                // a record refused a missing part (a damaged line): never a crash of `report --from`
                problems.add(where + ": line ignored: a required part is missing or empty");
            }
        }
        if (header == null) {
            throw new InvalidResultsException(name + ": no run header line ({\"type\":\"run\",...}); "
                    + "is this a results.jsonl written by fclcert certify?");
        }
        return new ResultsFile(header, results, dataCheckList, problems);
    }

    /**
     * The first part of a planned case that is not in the form fclcert writes — its id, level, a tested feature or a
     * flag — or empty. The reports show these parts as they are (they come from the corpus), so a damaged or forged
     * file must not bring other text into them.
     */
    private static Optional<String> foreign(PlannedCase p) {
        if (p.id() == null || !CorpusCase.ID_FORM.matcher(p.id()).matches()) {
            return Optional.of("id");
        }
        if (p.level() != null && Arrays.stream(ConformanceLevel.values()).noneMatch(l -> l.word().equals(p.level()))) {
            return Optional.of("level");
        }
        if (p.tests().stream().anyMatch(t -> t == null || !FEATURE_FORM.matcher(t).matches())) {
            return Optional.of("tested feature");
        }
        if (p.flags().stream().anyMatch(f -> f == null || !CorpusCase.FLAG_FORM.matcher(f).matches())) {
            return Optional.of("flag");
        }
        return Optional.empty();
    }

    /**
     * The first text of the header the reports cannot do without (they name and rerun the implementation), or a
     * {@code presentAs} that is no layout of fclcert's; empty when there is none.
     */
    private static Optional<String> untold(RunHeader h) {
        java.util.Map<String, String> texts = new java.util.LinkedHashMap<>();
        texts.put("iut.name", h.iut().name());
        texts.put("iut.version", h.iut().version());
        texts.put("iut.spec", h.iut().spec());
        texts.put("toolkit.version", h.toolkit().version());
        texts.put("corpus.sha256", h.corpus().sha256());
        texts.put("startedAt", h.startedAt());
        Optional<String> missing = texts.entrySet().stream().filter(e -> e.getValue() == null)
                .map(java.util.Map.Entry::getKey).findFirst();
        if (missing.isEmpty() && h.presentAs() != null && Arrays.stream(org.fclcert.syntax.dialect.Dialect.values())
                .noneMatch(d -> d.cliName().equals(h.presentAs()))) {
            return Optional.of("presentAs");   // a layout fclcert does not write: the reports name it as it is
        }
        return missing;
    }

    /** True when a Table 11 entry read back lacks one of its texts or has a bound fclcert does not write. */
    private static boolean damaged(DataCheckEntry e) {
        return e == null || Stream.of(e.id(), e.item(), e.value(), e.bound(), e.unit(), e.method(), e.note(),
                e.declared()).anyMatch(Objects::isNull) || !List.of(DataCheckEntry.EXACT, DataCheckEntry.AT_LEAST,
                DataCheckEntry.NOT_MEASURED).contains(e.bound());
    }

    /** The form of a feature id of the catalogue ({@code E-ACCU-NSUM}). */
    private static final Pattern FEATURE_FORM = Pattern.compile("[BEO]-[A-Z0-9]+(-[A-Z0-9]+)*");

    /** The file cannot be made into a report. */
    public static final class InvalidResultsException extends Exception {
        private static final long serialVersionUID = 1L;

        public InvalidResultsException(String message) {
            super(message);
        }
    }
}
