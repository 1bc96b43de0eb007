package org.fclcert.corpus;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.dataformat.yaml.YAMLMapper;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.eval.EvaluationCode;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;
import org.fclcert.syntax.dialect.Dialect;

/**
 * Reads one case file: splits off the metadata comment, parses its YAML, validates every field and reports
 * each problem with its line. Collects problems instead of stopping at the first one.
 */
final class CaseFileReader {
    static final String OPEN = "(*---";
    static final String CLOSE = "---*)";

    private static final Set<String> KEYS = Set.of("id", "title", "level", "features", "tests", "tolerance",
            "flags", "derivation", "block", "vectors", "expect", "error", "dialect");
    private static final Pattern ID = CorpusCase.ID_FORM;
    private static final Pattern CODE = Pattern.compile("FCL-[SCWV][0-9]{3}");
    private static final Pattern FLAG = CorpusCase.FLAG_FORM;
    /** The characters YAML takes as line breaks besides the newline (a CR before a newline is gone already). */
    private static final Pattern OTHER_BREAK = Pattern.compile("[\\r\\u0085\\u2028\\u2029]");
    private static final Pattern DECIMAL = Pattern.compile("[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?");
    private static final YAMLMapper YAML = YAMLMapper.builder()
            .enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION)
            .build();

    private final Path file;
    private final String text;
    private final List<CorpusProblem> problems;
    private String yaml = "";

    private CaseFileReader(Path file, String text, List<CorpusProblem> problems) {
        this.file = file;
        this.text = text;
        this.problems = problems;
    }

    /** The case, or empty when the file has problems (all of them appended to {@code problems}). */
    static Optional<CorpusCase> read(Path file, String text, List<CorpusProblem> problems) {
        int before = problems.size();
        Optional<CorpusCase> c = new CaseFileReader(file, text, problems).read();
        return problems.size() == before ? c : Optional.empty();
    }

    /**
     * The program text: the metadata comment replaced by as many line breaks as it contains, so that the
     * program's lines keep their numbers. The text must start with the metadata comment.
     */
    static String stripMetadata(String text, int closeEnd) {
        String comment = text.substring(0, closeEnd);
        long breaks = comment.chars().filter(ch -> ch == '\n').count();
        return "\n".repeat((int) breaks) + text.substring(closeEnd);
    }

    private Optional<CorpusCase> read() {
        if (!text.startsWith(OPEN)) {
            problem(1, "a case file must start with the metadata comment '" + OPEN + "' on its first line");
            return Optional.empty();
        }
        Matcher close = Pattern.compile("(?m)^" + Pattern.quote(CLOSE)).matcher(text);
        if (!close.find()) {
            problem(1, "the metadata comment is never closed: add a line starting with '" + CLOSE + "'");
            return Optional.empty();
        }
        // The YAML starts right after "(*---" on line 1, so YAML line n is file line n.
        yaml = text.substring(OPEN.length(), close.start());
        Matcher otherBreak = OTHER_BREAK.matcher(yaml);
        if (otherBreak.find()) {
            // YAML starts a line there too: every line it names after it would be wrong
            int line = 1 + (int) yaml.substring(0, otherBreak.start()).chars().filter(c -> c == '\n').count();
            problem(line, "the metadata has a line break other than a newline (a lone carriage return, U+0085,"
                    + " U+2028 or U+2029): write each line ending in a newline");
            return Optional.empty();
        }
        Optional<JsonNode> root = parseYaml();
        if (root.isEmpty()) {
            return Optional.empty();
        }
        return build(root.get(), stripMetadata(text, close.end()));
    }

    private Optional<JsonNode> parseYaml() {
        try {
            JsonNode root = YAML.readTree(yaml);
            if (root == null || !root.isObject()) {
                problem(2, "the metadata must be a YAML mapping of fields (id, title, level, ...)");
                return Optional.empty();
            }
            return Optional.of(root);
        } catch (JsonProcessingException e) {
            int line = e.getLocation() == null ? 1 : Math.max(1, e.getLocation().getLineNr());
            problem(line, "the metadata is not valid YAML: " + e.getOriginalMessage());
            return Optional.empty();
        }
    }

    private Optional<CorpusCase> build(JsonNode root, String program) {
        for (Iterator<String> it = root.fieldNames(); it.hasNext(); ) {
            String key = it.next();
            if (!KEYS.contains(key)) {
                problem(lineOf(key), "unknown metadata field '" + key + "' (allowed: " + String.join(", ",
                        KEYS.stream().sorted().toList()) + ")");
            }
        }
        String id = requiredText(root, "id");
        if (id != null && !ID.matcher(id).matches()) {
            problem(lineOf("id"), "id '" + id + "' does not follow the scheme B-|E-|O-|N-<TOPIC>-NNN (e.g. B-COGS-001)");
        }
        String title = requiredText(root, "title");
        ConformanceLevel level = level(root);
        List<Feature> features = featureList(root, "features");
        List<Feature> tests = featureList(root, "tests");
        List<String> flags = flags(root);
        Optional<String> derivation = optionalText(root, "derivation");
        Optional<String> block = optionalText(root, "block");
        Dialect dialect = dialect(root);
        boolean reject = expectReject(root);
        Tolerance tolerance = tolerance(root, reject);
        List<Vector> vectors = reject ? List.of() : vectors(root);
        Optional<ExpectedError> error = reject ? expectedError(root) : Optional.empty();
        if (!reject && root.has("error")) {
            problem(lineOf("error"), "'error' is only for negative cases (with 'expect: reject')");
        }
        if (reject && root.has("vectors")) {
            problem(lineOf("vectors"), "a negative case ('expect: reject') has no vectors");
        }
        return Optional.of(new CorpusCase(id == null ? "" : id, title == null ? "" : title, level, features, tests,
                tolerance, flags, derivation, block, vectors, reject, error, program, file, dialect));
    }

    private String requiredText(JsonNode root, String key) {
        JsonNode n = root.get(key);
        if (n == null || n.isNull()) {
            problem(1, "missing required field '" + key + "'");
            return null;
        }
        if (!n.isValueNode() || n.asText().isBlank()) {
            problem(lineOf(key), "field '" + key + "' must be a non-empty text");
            return null;
        }
        return n.asText().strip();
    }

    private Optional<String> optionalText(JsonNode root, String key) {
        JsonNode n = root.get(key);
        if (n == null || n.isNull()) {
            return Optional.empty();
        }
        if (!n.isValueNode() || n.asText().isBlank()) {
            problem(lineOf(key), "field '" + key + "' must be a non-empty text when present");
            return Optional.empty();
        }
        return Optional.of(n.asText().strip());
    }

    /**
     * The syntax the program is written in: absent for standard FCL (plus the Open Level methods); else the
     * command-line name of a library's dialect ({@code fuzzylite}, {@code jfuzzylogic}, ...; {@link Dialect} is the
     * one list). {@code strict} is refused: it is what leaving the field out says.
     */
    private Dialect dialect(JsonNode root) {
        Optional<String> name = optionalText(root, "dialect");
        if (name.isEmpty()) {
            return Dialect.STRICT;
        }
        Optional<Dialect> d = Dialect.byCliName(name.get()).filter(x -> x.cliName().equals(name.get()));
        List<String> allowed = Dialect.cliNames().stream().filter(n -> !n.equals(Dialect.STRICT.cliName())).toList();
        if (d.isEmpty() || d.get() == Dialect.STRICT) {
            problem(lineOf("dialect"), "dialect '" + name.get() + "' is not a library's dialect (allowed: "
                    + String.join(", ", allowed) + "; leave the field out for standard FCL)");
            return Dialect.STRICT;
        }
        return d.get();
    }

    private ConformanceLevel level(JsonNode root) {
        String word = requiredText(root, "level");
        if (word == null) {
            return ConformanceLevel.BASIC;
        }
        for (ConformanceLevel l : ConformanceLevel.values()) {
            if (l.word().equals(word)) {
                return l;
            }
        }
        problem(lineOf("level"), "level '" + word + "' is not one of basic, extension, open");
        return ConformanceLevel.BASIC;
    }

    private List<Feature> featureList(JsonNode root, String key) {
        JsonNode n = root.get(key);
        if (n == null || !n.isArray()) {
            problem(n == null ? 1 : lineOf(key), n == null
                    ? "missing required field '" + key + "' (a list of feature ids, e.g. [B-FB, B-COGS])"
                    : "field '" + key + "' must be a list of feature ids, e.g. [B-FB, B-COGS]");
            return List.of();
        }
        List<Feature> result = new ArrayList<>();
        for (JsonNode item : n) {
            Optional<Feature> f = Feature.byId(item.asText());
            if (f.isEmpty()) {
                problem(lineOf(key), "'" + item.asText() + "' in '" + key + "' is not a feature id of the catalogue");
            } else if (result.contains(f.get())) {
                problem(lineOf(key), "'" + item.asText() + "' is listed twice in '" + key + "'");
            } else {
                result.add(f.get());
            }
        }
        return result;
    }

    private List<String> flags(JsonNode root) {
        JsonNode n = root.get("flags");
        if (n == null || n.isNull()) {
            return List.of();
        }
        if (!n.isArray()) {
            problem(lineOf("flags"), "field 'flags' must be a list, e.g. [stateful]");
            return List.of();
        }
        List<String> result = new ArrayList<>();
        for (JsonNode item : n) {
            String flag = item.asText();
            if (!FLAG.matcher(flag).matches()) {
                problem(lineOf("flags"), "unknown flag '" + flag + "' (allowed: stateful, interpretation:<point>, knife-edge:<vector>)");
            } else {
                result.add(flag);
            }
        }
        return result;
    }

    private boolean expectReject(JsonNode root) {
        JsonNode n = root.get("expect");
        if (n == null || n.isNull()) {
            return false;
        }
        if (!"reject".equals(n.asText())) {
            problem(lineOf("expect"), "field 'expect' can only be 'reject' (leave it out for a positive case)");
        }
        return true;
    }

    private Tolerance tolerance(JsonNode root, boolean reject) {
        JsonNode n = root.get("tolerance");
        if (n == null || n.isNull()) {
            if (!reject) {
                problem(1, "missing required field 'tolerance' (exact or continuous)");
            }
            return Tolerance.EXACT;
        }
        for (Tolerance t : Tolerance.values()) {
            if (t.word().equals(n.asText())) {
                return t;
            }
        }
        problem(lineOf("tolerance"), "tolerance '" + n.asText() + "' is not one of exact, continuous");
        return Tolerance.EXACT;
    }

    private Optional<ExpectedError> expectedError(JsonNode root) {
        JsonNode n = root.get("error");
        if (n == null || !n.isObject()) {
            problem(n == null ? 1 : lineOf("error"),
                    "a negative case needs 'error: {code: FCL-Cnnn, line: N}' naming its single error");
            return Optional.empty();
        }
        JsonNode code = n.get("code");
        JsonNode line = n.get("line");
        boolean ok = true;
        if (code == null || !CODE.matcher(code.asText()).matches()) {
            problem(lineOf("error"), "error code must look like FCL-S001 or FCL-C002");
            ok = false;
        }
        if (line == null || !line.canConvertToInt() || !line.isIntegralNumber() || line.asInt() < 1) {
            problem(lineOf("error"), "error line must be a positive whole number (the line in the case file)");
            ok = false;
        }
        if (n.size() != 2) {
            problem(lineOf("error"), "'error' has exactly two fields, code and line");
            ok = false;
        }
        return ok ? Optional.of(new ExpectedError(code.asText(), line.asInt())) : Optional.empty();
    }

    private List<Vector> vectors(JsonNode root) {
        JsonNode n = root.get("vectors");
        if (n == null || !n.isArray() || n.isEmpty()) {
            problem(n == null ? 1 : lineOf("vectors"), "a positive case needs a non-empty list 'vectors' of "
                    + "{in: {...}, out: {...}} steps (or 'expect: reject' for a negative case)");
            return List.of();
        }
        List<Vector> result = new ArrayList<>();
        int index = 0;
        for (JsonNode step : n) {
            index++;
            String where = "vector " + index;
            if (step.isObject() && step.size() == 2 && step.has("in") && step.has("error")) {
                refused(step, where).ifPresent(code -> result.add(Vector.refused(numbers(step.get("in"),
                        where + " 'in'"), code)));
                continue;
            }
            if (!step.isObject() || step.size() != 2 || !step.has("in") || !step.has("out")) {
                problem(lineOf("vectors"), where + " must have exactly the fields 'in' and 'out' (or 'in' and 'error')");
                continue;
            }
            Map<String, Double> in = numbers(step.get("in"), where + " 'in'");
            Map<String, Double> out = numbers(step.get("out"), where + " 'out'");
            if (step.get("out").isEmpty()) {
                problem(lineOf("vectors"), where + " expects no output at all: list at least one");
            }
            result.add(new Vector(in, out));
        }
        return result;
    }

    /** The code of a step that must be refused: an evaluation error a program and its inputs can cause. */
    private Optional<String> refused(JsonNode step, String where) {
        String code = step.get("error").asText("");
        Optional<EvaluationCode> known = EvaluationCode.of(code);
        if (known.isEmpty() || !known.get().causedByTheProgram()) {
            String allowed = java.util.Arrays.stream(EvaluationCode.values()).filter(EvaluationCode::causedByTheProgram)
                    .map(EvaluationCode::code).collect(java.util.stream.Collectors.joining(", "));
            problem(lineOf("vectors"), where + ": 'error' must name an evaluation error a program can cause ("
                    + allowed + "), not '" + code + "'");
            return Optional.empty();
        }
        return Optional.of(code);
    }

    private Map<String, Double> numbers(JsonNode n, String where) {
        Map<String, Double> result = new LinkedHashMap<>();
        if (!n.isObject()) {
            problem(lineOf("vectors"), where + " must be a mapping name: number");
            return result;
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = n.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            Optional<Double> value = number(e.getValue());
            if (value.isEmpty()) {
                problem(lineOf("vectors"), where + ": '" + e.getKey() + "' must be a finite number, not '"
                        + e.getValue().asText() + "'");
            } else {
                result.put(e.getKey(), value.get());
            }
        }
        return result;
    }

    private static Optional<Double> number(JsonNode n) {
        double v;
        if (n.isNumber()) {
            v = n.asDouble();
        } else if (n.isTextual() && DECIMAL.matcher(n.asText().strip()).matches()) {
            // YAML 1.1 reads 1e-3 (no dot) as text; accept any plain decimal spelling.
            v = Double.parseDouble(n.asText().strip());
        } else {
            return Optional.empty();
        }
        return Double.isFinite(v) ? Optional.of(v) : Optional.empty();
    }

    /** The file line of a top-level metadata field (2 when it cannot be found). */
    private int lineOf(String key) {
        Matcher m = Pattern.compile("(?m)^" + Pattern.quote(key) + "\\s*:").matcher(yaml);
        if (!m.find()) {
            return 2;
        }
        return 1 + (int) yaml.substring(0, m.start()).chars().filter(ch -> ch == '\n').count();
    }

    private void problem(int line, String message) {
        problems.add(new CorpusProblem(file, line, message));
    }
}
