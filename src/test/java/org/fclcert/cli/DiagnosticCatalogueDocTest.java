package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.fclcert.check.Analysis;
import org.fclcert.check.CheckCode;
import org.fclcert.check.CheckRule;
import org.fclcert.check.Checker;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Severity;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;
import org.junit.jupiter.api.Test;

/**
 * docs/diagnostics.md and the catalogue agree in both directions: every code the catalogue has is in a table of
 * the docs with the same severity, meaning and clause (and, for a check, the rule class that owns it), and the
 * docs have no code the catalogue lacks. The main sources spell a code as a string only where they declare it
 * in the catalogue, and mention (in comments, docs and README) only codes that exist.
 */
class DiagnosticCatalogueDocTest {
    private static final Path DOC = Path.of("docs/diagnostics.md");
    private static final Pattern ANY_CODE = Pattern.compile("FCL-[A-Z]\\d{3}");
    /** A code spelled as a whole string literal in Java. */
    private static final Pattern CODE_LITERAL = Pattern.compile("\"FCL-[A-Z]\\d{3}\"");
    /** The two places a code's string may be written: an enum constant or a check rule's declaration. */
    private static final Pattern DECLARATION = Pattern.compile(
            "^\\s+[A-Z][A-Z0-9_]*\\(\"FCL-[A-Z]\\d{3}\",.*|.*\\bCheckCode\\.(error|warning)\\(\"FCL-[CW]\\d{3}\",.*");

    /** One row of a docs table, by column name. */
    record Row(int line, Map<String, String> cells) {
        String get(String column) {
            return cells.get(column);
        }
    }

    @Test
    void theDocumentListsExactlyTheCataloguesCodesWithTheirSeverityMeaningAndClause() throws IOException {
        // the rows as the catalogue gives them, to copy from when a code is added or changed
        Path rows = Path.of("target/diagnostics-expected-rows.md");
        Files.createDirectories(rows.getParent());
        Files.writeString(rows, DiagnosticCatalogue.all().stream().map(DiagnosticCatalogueDocTest::expectedRow)
                .collect(Collectors.joining("\n", "", "\n")));
        Map<String, Row> documented = documentedCodes();
        List<String> problems = new ArrayList<>();
        for (DiagnosticCode c : DiagnosticCatalogue.all()) {
            Row row = documented.get(c.code());
            if (row == null) {
                problems.add(c.code() + " is in the catalogue but not in " + DOC);
                continue;
            }
            same(problems, c, "severity", c.severity().word(), row);
            same(problems, c, "meaning", c.meaning(), row);
            same(problems, c, "clause", c.clause(), row);
            if (c instanceof CheckCode) {
                same(problems, c, "rule class", "`" + ownerOf(c).getClass().getSimpleName() + "`", row);
            }
        }
        Set<String> catalogued = DiagnosticCatalogue.all().stream().map(DiagnosticCode::code).collect(Collectors.toSet());
        documented.forEach((code, row) -> {
            if (!catalogued.contains(code)) {
                problems.add(DOC + ":" + row.line() + ": " + code + " is documented but no part of fclcert declares it");
            }
        });
        assertEquals(List.of(), problems, "the rows the catalogue gives are in " + rows);
    }

    @Test
    void theCatalogueHasEveryFamilyAndEachCodeOnce() {
        List<String> codes = DiagnosticCatalogue.all().stream().map(DiagnosticCode::code).toList();
        assertEquals(codes.size(), Set.copyOf(codes).size(), "a code declared twice");
        for (String prefix : List.of("FCL-S0", "FCL-W1", "FCL-D", "FCL-S3", "FCL-W3", "FCL-C", "FCL-W0", "FCL-V",
                "FCL-X")) {
            assertTrue(codes.stream().anyMatch(c -> c.startsWith(prefix)), "no code " + prefix + "...");
        }
        for (DiagnosticCode c : DiagnosticCatalogue.all()) {
            assertEquals(c, DiagnosticCatalogue.find(c.code()).orElseThrow());
            assertFalse(c.meaning().isBlank() || c.clause().isBlank(), c.code());
            assertFalse(c.meaning().contains("\n") || c.meaning().contains("|"), c.code() + ": one line, no '|'");
            // the W family is the warnings', the other letters the errors' (FCL-X001 may be lowered by the user);
            // FCL-X2nn are the library writers' warnings (a library's known deviations)
            assertEquals(c.code().startsWith("FCL-W") || c.code().equals("FCL-X002") || c.code().startsWith("FCL-X2")
                    || c.code().startsWith("FCL-D1") && c.severity() == Severity.WARNING,
                    c.severity() == Severity.WARNING, c.code());
        }
        assertEquals("FCL-S999", DiagnosticCatalogue.find("FCL-S999").orElseThrow().code());
        assertTrue(DiagnosticCatalogue.find("FCL-Q123").isEmpty());
    }

    @Test
    void mainSourcesSpellACodeOnlyWhereTheyDeclareIt() throws IOException {
        List<String> problems = new ArrayList<>();
        for (Path file : mainSources()) {
            List<String> lines = Files.readAllLines(file);
            for (int i = 0; i < lines.size(); i++) {
                String line = lines.get(i);
                if (CODE_LITERAL.matcher(line).find() && !DECLARATION.matcher(line).matches()) {
                    problems.add(file + ":" + (i + 1) + ": " + line.strip());
                }
            }
        }
        assertEquals(List.of(), problems, "report a catalogue constant, not a code written as a string");
    }

    @Test
    void everyCodeMentionedInSourcesAndDocsExists() throws IOException {
        Set<String> catalogued = DiagnosticCatalogue.all().stream().map(DiagnosticCode::code).collect(Collectors.toSet());
        List<Path> texts = new ArrayList<>(mainSources());
        try (Stream<Path> docs = Files.list(Path.of("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).forEach(texts::add);
        }
        texts.add(Path.of("README.md"));
        Set<String> unknown = new TreeSet<>();
        for (Path file : texts) {
            List<String> lines = Files.readAllLines(file);
            for (int i = 0; i < lines.size(); i++) {
                Matcher m = ANY_CODE.matcher(lines.get(i));
                while (m.find()) {
                    if (!catalogued.contains(m.group())) {
                        unknown.add(file + ":" + (i + 1) + ": " + m.group());
                    }
                }
            }
        }
        assertEquals(Set.of(), unknown, "codes that no part of fclcert declares");
    }

    /**
     * Producers report each code with the severity the catalogue gives it: every .fcl file of the project
     * (examples, corpus, test programs), read strictly and in every dialect, with the checks.
     */
    @Test
    void producersReportEachCodeWithItsCataloguedSeverity() throws IOException {
        List<Path> files = new ArrayList<>();
        for (String dir : List.of("examples", "conformance", "src/test/resources")) {
            try (Stream<Path> s = Files.walk(Path.of(dir))) {
                s.filter(p -> p.toString().endsWith(".fcl")).sorted().forEach(files::add);
            }
        }
        assertTrue(files.size() > 250, "fcl files found: " + files.size());
        Set<String> seen = new TreeSet<>();
        List<String> problems = new ArrayList<>();
        for (Path file : files) {
            String text = Files.readString(file);
            for (Dialect dialect : Dialect.values()) {
                for (Diagnostic d : Analysis.analyze(DialectReaders.reader(dialect), file.toString(), text).diagnostics()) {
                    seen.add(d.code());
                    if (d.severity() != d.diagnosticCode().severity()) {
                        problems.add(dialect.cliName() + ": " + d);
                    }
                }
            }
        }
        assertEquals(List.of(), problems);
        assertTrue(seen.size() > 60, "codes seen: " + seen);   // the files reach most families' codes
    }

    /** The doc's table rows whose first cell is a code, by code; a code in two rows is a failure. */
    private static Map<String, Row> documentedCodes() throws IOException {
        List<String> lines = Files.readAllLines(DOC);
        Map<String, Row> rows = new LinkedHashMap<>();
        List<String> header = List.of();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (!line.startsWith("|")) {
                header = List.of();
                continue;
            }
            List<String> cells = cells(line);
            if (header.isEmpty()) {
                header = cells;
                continue;
            }
            if (!ANY_CODE.matcher(cells.get(0)).matches()) {
                continue;
            }
            assertTrue(header.containsAll(List.of("code", "severity", "meaning", "clause")),
                    DOC + ":" + (i + 1) + ": a table of codes needs the columns code, severity, meaning, clause");
            assertEquals(header.size(), cells.size(), DOC + ":" + (i + 1) + ": cells");
            Map<String, String> byColumn = new LinkedHashMap<>();
            for (int k = 0; k < header.size(); k++) {
                byColumn.put(header.get(k), cells.get(k));
            }
            Row before = rows.put(cells.get(0), new Row(i + 1, byColumn));
            assertTrue(before == null, DOC + ":" + (i + 1) + ": " + cells.get(0) + " is listed twice");
        }
        return rows;
    }

    /** The cells of a table row, trimmed, with {@code \|} read as a '|' inside a cell. */
    private static List<String> cells(String line) {
        String inner = line.strip().replaceAll("^\\|", "").replaceAll("\\|$", "");
        List<String> out = new ArrayList<>();
        for (String cell : inner.split("(?<!\\\\)\\|", -1)) {
            out.add(cell.strip().replace("\\|", "|"));
        }
        return out;
    }

    private static void same(List<String> problems, DiagnosticCode c, String column, String want, Row row) {
        String got = row.get(column);
        if (got != null && !got.equals(want)) {
            problems.add(DOC + ":" + row.line() + ": " + c.code() + " " + column + " is '" + got + "', the catalogue says '"
                    + want + "'");
        }
    }

    private static CheckRule ownerOf(DiagnosticCode c) {
        return Checker.standardRules().stream().filter(r -> r.diagnosticCode().equals(c)).findFirst().orElseThrow();
    }

    private static String expectedRow(DiagnosticCode c) {
        String rule = c instanceof CheckCode ? " `" + ownerOf(c).getClass().getSimpleName() + "` |" : "";
        return "| " + c.code() + " | " + c.severity().word() + " |" + rule + " " + c.meaning() + " | " + c.clause() + " |";
    }

    private static List<Path> mainSources() throws IOException {
        try (Stream<Path> files = Files.walk(Path.of("src/main/java"))) {
            return files.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
    }
}
