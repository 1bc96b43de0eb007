package org.fclcert.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionContext;
import org.eclipse.lsp4j.CodeActionParams;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidChangeConfigurationParams;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidCloseTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DocumentFormattingParams;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.FormattingOptions;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.ReferenceContext;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.TextDocumentSyncKind;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageServer;
import org.fclcert.cli.Main;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The language server driven by an LSP4J client over a pair of pipes, as an editor drives it: every capability
 * (diagnostics, hover, definition, references, outline, completion, formatting, code actions, the dialect setting)
 * and bad input (any text, requests out of order, unknown methods, broken messages, a client that vanishes).
 * Expected values are counted by hand in the programs below or taken from {@code fclcert check} and
 * {@code fclcert fmt}, the front end whose output the server must equal.
 */
class LspClientTest {
    /** The program of NeovimLspTest: an unused term, a missing ';', no DEFAULT, a misspelt variable and term. */
    private static final String MISTAKES = resource("mistakes.fcl");

    private static final String VALID = """
            FUNCTION_BLOCK valve
            VAR_INPUT
                level : REAL;
            END_VAR
            VAR_OUTPUT
                flow : REAL;
            END_VAR
            FUZZIFY level
                TERM low := (0, 1) (6, 0);
                TERM high := (4, 0) (10, 1);
            END_FUZZIFY
            DEFUZZIFY flow
                RANGE (0 .. 100);
                TERM shut := 0;
                TERM open := 100;
                METHOD : CoGS;
                DEFAULT := 0;
            END_DEFUZZIFY
            RULEBLOCK main
                AND : MIN;
                ACCU : MAX;
                RULE 1 : IF level IS low THEN flow IS open;
                RULE 2 : IF level IS high THEN flow IS shut;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    @TempDir
    Path dir;

    private final RecordingClient client = new RecordingClient();
    private FclLanguageServer server;
    private LanguageServer remote;
    private Launcher<LanguageServer> launcher;
    private PipedOutputStream toServer;
    private PipedInputStream fromClient;
    private CompletableFuture<Integer> served;
    private int version;

    @BeforeEach
    void start() throws Exception {
        server = new FclLanguageServer();
        fromClient = new PipedInputStream(1 << 20);
        toServer = new PipedOutputStream(fromClient);
        PipedInputStream fromServer = new PipedInputStream(1 << 20);
        PipedOutputStream toClient = new PipedOutputStream(fromServer);
        served = CompletableFuture.supplyAsync(() -> server.run(fromClient, toClient));
        launcher = LSPLauncher.createClientLauncher(client, fromServer, toServer);
        launcher.startListening();
        remote = launcher.getRemoteProxy();
    }

    @AfterEach
    void stop() throws IOException {
        toServer.close();
    }

    private InitializeResult initialize(String options) throws Exception {
        InitializeParams p = new InitializeParams();
        p.setCapabilities(new ClientCapabilities());
        if (options != null) {
            p.setInitializationOptions(JsonParser.parseString(options));
        }
        InitializeResult r = remote.initialize(p).get(30, TimeUnit.SECONDS);
        remote.initialized(new org.eclipse.lsp4j.InitializedParams());
        return r;
    }

    private String open(String name, String text) throws Exception {
        Path file = dir.resolve(name);
        Files.writeString(file, text);
        String uri = file.toUri().toString();
        remote.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "fcl", ++version, text)));
        return uri;
    }

    private PublishDiagnosticsParams diagnosticsOf(String uri) throws InterruptedException {
        while (true) {
            PublishDiagnosticsParams p = client.diagnostics.poll(30, TimeUnit.SECONDS);
            assertNotNull(p, "no diagnostics for " + uri + " within 30 s");
            if (p.getUri().equals(uri)) {
                return p;
            }
        }
    }

    private static TextDocumentIdentifier doc(String uri) {
        return new TextDocumentIdentifier(uri);
    }

    /** check's JSON findings for a file, as line:col severity code message (0-based line and column). */
    private static List<String> check(Path file, String dialect) {
        StringWriter out = new StringWriter();
        Main.run(new PrintWriter(out), new PrintWriter(new StringWriter()), "check", "--format", "json", "--dialect",
                dialect, file.toString());
        List<String> lines = new ArrayList<>();
        for (var e : JsonParser.parseString(out.toString()).getAsJsonArray()) {
            JsonObject d = e.getAsJsonObject();
            lines.add((d.get("line").getAsInt() - 1) + ":" + (d.get("column").getAsInt() - 1) + " "
                    + d.get("severity").getAsString() + " " + d.get("code").getAsString() + " " + d.get("message").getAsString());
        }
        return lines;
    }

    private static List<String> shown(PublishDiagnosticsParams p) {
        return p.getDiagnostics().stream().map(d -> d.getRange().getStart().getLine() + ":"
                + d.getRange().getStart().getCharacter() + " " + d.getSeverity().name().toLowerCase() + " "
                + d.getCode().getLeft() + " " + d.getMessage()).toList();
    }

    @Test
    void announcesEveryCapability() throws Exception {
        InitializeResult r = initialize(null);
        var c = r.getCapabilities();
        assertEquals(TextDocumentSyncKind.Incremental, c.getTextDocumentSync().getRight().getChange());
        assertTrue(c.getHoverProvider().getLeft());
        assertTrue(c.getDefinitionProvider().getLeft());
        assertTrue(c.getReferencesProvider().getLeft());
        assertTrue(c.getDocumentSymbolProvider().getLeft());
        assertTrue(c.getDocumentFormattingProvider().getLeft());
        assertNotNull(c.getCompletionProvider());
        assertEquals(List.of("quickfix"), c.getCodeActionProvider().getRight().getCodeActionKinds());
        assertEquals("fclcert", r.getServerInfo().getName());
    }

    @Test
    void diagnosticsAreCheckFindingsWithRangesAndClauses() throws Exception {
        initialize("{\"dialect\": \"strict\"}");
        String uri = open("mistakes.fcl", MISTAKES);
        PublishDiagnosticsParams p = diagnosticsOf(uri);
        assertEquals(check(dir.resolve("mistakes.fcl"), "strict"), shown(p));
        Diagnostic undefined = p.getDiagnostics().get(3);
        assertEquals("FCL-C001", undefined.getCode().getLeft());
        // 'servce' on line 25, columns 17 to 22: the whole name
        assertEquals(new Range(new Position(24, 16), new Position(24, 22)), undefined.getRange());
        assertEquals("urn:iec:std:iec:61131-7#5.2.1", undefined.getCodeDescription().getHref());
        assertEquals("fclcert", undefined.getSource());
        // 'Table 3'-style clauses are encoded: the S014 cites 5.2.2
        assertEquals("urn:iec:std:iec:61131-7#5.2.2", p.getDiagnostics().get(1).getCodeDescription().getHref());
        assertEquals("urn:iec:std:iec:61131-7#Table%203", Diagnostics.clauseUri("Table 3"));
    }

    @Test
    void editsAreDebouncedAndTheLastVersionIsPublished() throws Exception {
        initialize("{\"dialect\": \"strict\", \"debounceMillis\": 300}");
        String uri = open("valid.fcl", VALID);
        assertEquals(List.of(), diagnosticsOf(uri).getDiagnostics());
        // three quick edits: 'low' -> 'lo', 'lw', 'lox' in RULE 1 (line 22, 'low' at columns 25-27)
        for (String t : List.of("lo", "lw", "lox")) {
            change(uri, new Range(new Position(21, 25), new Position(21, 25 + (t.equals("lo") ? 3 : 2))), t);
        }
        PublishDiagnosticsParams p = diagnosticsOf(uri);
        assertEquals(version, p.getVersion(), "only the last version is published after the pause");
        assertEquals(1, p.getDiagnostics().size(), shown(p).toString());
        assertTrue(p.getDiagnostics().get(0).getMessage().contains("'lox' is not a term of input 'level'"));
        assertNull(client.diagnostics.poll(1, TimeUnit.SECONDS), "the earlier versions are never published");
    }

    private void change(String uri, Range range, String text) {
        TextDocumentContentChangeEvent e = range == null ? new TextDocumentContentChangeEvent(text)
                : new TextDocumentContentChangeEvent(range, text);
        remote.getTextDocumentService().didChange(new DidChangeTextDocumentParams(
                new VersionedTextDocumentIdentifier(uri, ++version), List.of(e)));
    }

    private Hover hover(String uri, int line, int character) throws Exception {
        return remote.getTextDocumentService().hover(new HoverParams(doc(uri), new Position(line, character)))
                .get(30, TimeUnit.SECONDS);
    }

    @Test
    void hoverNamesVariablesTermsKeywordsAndDiagnostics() throws Exception {
        initialize("{\"dialect\": \"strict\"}");
        String uri = open("valid.fcl", VALID);
        // 'flow' in RULE 1 (line 22, columns 35-38): output with its RANGE, METHOD, DEFAULT and terms
        String flow = hover(uri, 21, 35).getContents().getRight().getValue();
        assertTrue(flow.startsWith("**flow** : REAL — declared in VAR_OUTPUT of valve, line 6"), flow);
        assertTrue(flow.contains("RANGE (0 .. 100)") && flow.contains("METHOD : CoGS") && flow.contains("DEFAULT := 0")
                && flow.contains("terms: shut, open"), flow);
        // 'high' in RULE 2: rising ramp (5, 0) (10, 1), degree 1 from 10 on (the last degree holds beyond)
        assertEquals("**level IS high**: rising ramp through (4, 0) (10, 1); degree 1 at x ≥ 10",
                hover(uri, 22, 26).getContents().getRight().getValue());
        // 'open' where declared: a singleton
        assertEquals("**flow IS open**: singleton: degree 1 at 100, 0 elsewhere",
                hover(uri, 14, 10).getContents().getRight().getValue());
        // the keyword RULEBLOCK
        String keyword = hover(uri, 18, 2).getContents().getRight().getValue();
        assertTrue(keyword.startsWith("**RULEBLOCK** (IEC 61131-7 5.2.4)"), keyword);

        String bad = open("mistakes.fcl", MISTAKES);
        diagnosticsOf(bad);
        // on 'servce': check's own line for it
        String text = hover(bad, 24, 18).getContents().getRight().getValue();
        assertTrue(text.contains("`" + dir.resolve("mistakes.fcl") + ":25:17: error FCL-C001: servce IS poor: 'servce'"),
                text);
        // a trapezoid in the mistakes file: 'good' of service, degree 1 between 4 and 6
        assertEquals("**service IS good**: trapezoid through (1, 0) (4, 1) (6, 1) (9, 0); degree 1 at 4 ≤ x ≤ 6",
                hover(bad, 25, 28).getContents().getRight().getValue());
        assertTrue(hover(bad, 0, 2).getContents().getRight().getValue().startsWith("**FUNCTION_BLOCK** (IEC 61131-7 5.2.1, 5.4)"));
        assertNull(hover(bad, 999, 999), "nothing past the end");
        // a text no repair mends (two slips in one rule): still the declaration, from the tokens
        String unreadable = open("unreadable.fcl", MISTAKES.replace("IF service IS good THEN", "IF service IS IS good THEN THEN"));
        diagnosticsOf(unreadable);
        assertEquals("**service** — declared in VAR_INPUT of tipper, line 3 (the text has errors the reader cannot"
                + " mend, so its type and terms are not shown)", hover(unreadable, 25, 18).getContents().getRight().getValue()
                .replaceAll("(?s)^`.*`\\n\\n", ""));
    }

    @Test
    void definitionReferencesAndOutline() throws Exception {
        initialize(null);
        String uri = open("mistakes.fcl", MISTAKES);
        diagnosticsOf(uri);
        var service = remote.getTextDocumentService().definition(new DefinitionParams(doc(uri), new Position(25, 18)))
                .get(30, TimeUnit.SECONDS).getLeft();
        assertEquals(List.of(new Range(new Position(2, 4), new Position(2, 11))), service.stream().map(Location::getRange).toList());
        var generous = remote.getTextDocumentService().definition(new DefinitionParams(doc(uri), new Position(25, 45)))
                .get(30, TimeUnit.SECONDS).getLeft();
        assertEquals(new Position(18, 9), generous.get(0).getRange().getStart());
        var ruleBlock = remote.getTextDocumentService().definition(new DefinitionParams(doc(uri), new Position(21, 11)))
                .get(30, TimeUnit.SECONDS).getLeft();
        assertEquals(new Position(21, 10), ruleBlock.get(0).getRange().getStart());
        // 'service': declared on line 3, FUZZIFY service on line 9, RULE 2 on line 26 ('servce' is another name)
        List<? extends Location> refs = remote.getTextDocumentService().references(new ReferenceParams(doc(uri),
                new Position(2, 5), new ReferenceContext(true))).get(30, TimeUnit.SECONDS);
        assertEquals(List.of(2, 8, 25), refs.stream().map(l -> l.getRange().getStart().getLine()).toList());
        List<? extends Location> uses = remote.getTextDocumentService().references(new ReferenceParams(doc(uri),
                new Position(2, 5), new ReferenceContext(false))).get(30, TimeUnit.SECONDS);
        assertEquals(List.of(8, 25), uses.stream().map(l -> l.getRange().getStart().getLine()).toList());
        // term 'cheap' of tip: its TERM on line 18 and RULE 1 on line 25
        List<? extends Location> cheap = remote.getTextDocumentService().references(new ReferenceParams(doc(uri),
                new Position(17, 10), new ReferenceContext(true))).get(30, TimeUnit.SECONDS);
        assertEquals(List.of(17, 24), cheap.stream().map(l -> l.getRange().getStart().getLine()).toList());

        var symbols = remote.getTextDocumentService().documentSymbol(new DocumentSymbolParams(doc(uri)))
                .get(30, TimeUnit.SECONDS);
        assertEquals(1, symbols.size());
        DocumentSymbol tipper = symbols.get(0).getRight();
        assertEquals("tipper", tipper.getName());
        assertEquals(List.of("service", "food", "tip", "No1"), tipper.getChildren().stream().map(DocumentSymbol::getName).toList());
        assertEquals(List.of("poor", "good"), tipper.getChildren().get(0).getChildren().stream().map(DocumentSymbol::getName).toList());
        assertEquals("VAR_OUTPUT", tipper.getChildren().get(2).getDetail());
        assertEquals(List.of("RULE 1", "RULE 2"), tipper.getChildren().get(3).getChildren().stream().map(DocumentSymbol::getName).toList());
        assertEquals(new Range(new Position(0, 0), new Position(27, 18)), tipper.getRange());
    }

    /** The labels offered at the end of {@code text}. */
    private List<String> complete(String text) throws Exception {
        String uri = open("c" + version + ".fcl", text);
        String[] lines = text.split("\n", -1);
        Position end = new Position(lines.length - 1, lines[lines.length - 1].length());
        return remote.getTextDocumentService().completion(new CompletionParams(doc(uri), end)).get(30, TimeUnit.SECONDS)
                .getLeft().stream().map(CompletionItem::getLabel).toList();
    }

    @Test
    void completionKnowsWhereItIs() throws Exception {
        // strict: under auto the cut texts below (no DEFAULT) would read as jFuzzyLogic, whose words come too
        initialize("{\"dialect\": \"strict\"}");
        String head = VALID.substring(0, VALID.indexOf("    RULE 1"));
        assertEquals(List.of("level", "NOT"), complete(head + "    RULE 1 : IF "));
        assertEquals(List.of("level", "NOT"), complete(head + "    RULE 1 : IF level IS low AND "));
        assertEquals(List.of("flow"), complete(head + "    RULE 1 : IF level IS low THEN "));
        assertEquals(List.of("low", "high", "NOT"), complete(head + "    RULE 1 : IF level IS "));
        assertEquals(List.of("shut", "open"), complete(head + "    RULE 1 : IF level IS low THEN flow IS "));
        // the word being typed is replaced, so what is offered ignores it
        assertEquals(List.of("low", "high", "NOT"), complete(head + "    RULE 1 : IF level IS hi"));
        String block = VALID.substring(0, VALID.indexOf("    AND : MIN"));
        assertEquals(List.of("MIN", "PROD", "BDIF"), complete(block + "    AND : "));
        assertEquals(List.of("MAX", "ASUM", "BSUM"), complete(block + "    OR : "));
        assertEquals(List.of("MIN", "PROD"), complete(block + "    ACT : "));
        assertEquals(List.of("MAX", "BSUM", "NSUM"), complete(block + "    ACCU : "));
        String defuzzify = VALID.substring(0, VALID.indexOf("    METHOD"));
        assertEquals(List.of("CoG", "CoGS", "CoA", "LM", "RM"), complete(defuzzify + "    METHOD : "));
        // keywords from the grammar: inside DEFUZZIFY the items and its end (not the draft's END_FUZZIFY)
        assertEquals(List.of("END_DEFUZZIFY", "TERM", "RANGE", "METHOD", "DEFAULT"),
                complete("FUNCTION_BLOCK f\nDEFUZZIFY y\n    "));
        assertEquals(List.of("END_FUZZIFY", "TERM"), complete("FUNCTION_BLOCK f\nFUZZIFY x\n    "));
        assertEquals(List.of("FUNCTION_BLOCK"), complete(""));
        assertTrue(complete("FUNCTION_BLOCK f\nVAR_INPUT\n    x : ").containsAll(List.of("REAL", "LREAL", "INT")));
        List<String> items = complete("FUNCTION_BLOCK f\n");
        assertTrue(items.containsAll(List.of("END_FUNCTION_BLOCK", "VAR_INPUT", "VAR_OUTPUT", "FUZZIFY", "RULEBLOCK")), items.toString());
        assertFalse(items.contains("OPTION"), "5.4's OPTION spelling is reported, not offered");
    }

    /**
     * In a library's dialect the standard's words come first, then the dialect's own spellings. The expected words
     * are the libraries' own: jFuzzyLogic's FclParser (its jar) has the tokens DMIN, NIPMIN, HAMACHER, DMAX,
     * NIPMAX, EINSTEIN, PROBOR and COGF; fuzzylite's FCL importer reads the s-norms ASUM, ESUM (Einstein),
     * HSUM (Hamacher), DSUM (drastic), NMAX (nilpotent) and, by its class name, UnboundedSum for ACCU and LM, RM, MM, COGSS besides the standard's.
     */
    @Test
    void completionOffersTheDialectsMethodsToo() throws Exception {
        initialize("{\"dialect\": \"jfuzzylogic\"}");
        String block = VALID.substring(0, VALID.indexOf("    AND : MIN"));
        assertEquals(List.of("MIN", "PROD", "BDIF", "DMIN", "NIPMIN", "HAMACHER"), complete(block + "    AND : "));
        assertEquals(List.of("MAX", "ASUM", "BSUM", "DMAX", "NIPMAX", "EINSTEIN"), complete(block + "    OR : "));
        assertEquals(List.of("MAX", "BSUM", "NSUM", "PROBOR", "SUM"), complete(block + "    ACCU : "));
        String defuzzify = VALID.substring(0, VALID.indexOf("    METHOD"));
        assertEquals(List.of("CoG", "CoGS", "CoA", "LM", "RM", "COGF", "MM"), complete(defuzzify + "    METHOD : "));
        String uri = open("jfl.fcl", block + "    OR : ");
        String[] lines = (block + "    OR : ").split("\n", -1);
        List<CompletionItem> items = remote.getTextDocumentService().completion(new CompletionParams(doc(uri),
                new Position(lines.length - 1, lines[lines.length - 1].length()))).get(30, TimeUnit.SECONDS).getLeft();
        assertEquals("OR algorithm, Table 3", items.get(0).getDetail());
        assertEquals("OR algorithm of jFuzzyLogic (not in the standard)", items.get(3).getDetail());

        remote.getWorkspaceService().didChangeConfiguration(new DidChangeConfigurationParams(
                JsonParser.parseString("{\"fclcert\": {\"dialect\": \"fuzzylite\"}}")));
        assertEquals(List.of("MAX", "BSUM", "NSUM", "ASUM", "UnboundedSum", "ESUM", "HSUM", "DSUM", "NMAX"),
                complete(block + "    ACCU : "));
        assertEquals(List.of("CoG", "CoGS", "CoA", "LM", "RM", "MM", "COGSS"), complete(defuzzify + "    METHOD : "));
        remote.getWorkspaceService().didChangeConfiguration(new DidChangeConfigurationParams(
                JsonParser.parseString("{\"fclcert\": {\"dialect\": \"ffll\"}}")));
        assertEquals(List.of("CoG", "CoGS", "CoA", "LM", "RM", "MoM"), complete(defuzzify + "    METHOD : "));
        assertEquals(List.of("MIN", "PROD", "BDIF"), complete(block + "    AND : "));

        // detected, not set: ACCU inside DEFUZZIFY gives fuzzylite away (docs/dialects.md)
        remote.getWorkspaceService().didChangeConfiguration(new DidChangeConfigurationParams(
                JsonParser.parseString("{\"fclcert\": {\"dialect\": \"auto\"}}")));
        String fuzzylite = VALID.replace("    METHOD : CoGS;\n", "    METHOD : CoGS;\n    ACCU : MAX;\n");
        String accu = fuzzylite.substring(0, fuzzylite.indexOf("    ACCU : MAX;\n    RULE") + "    ACCU : ".length());
        assertEquals(List.of("MAX", "BSUM", "NSUM", "ASUM", "UnboundedSum", "ESUM", "HSUM", "DSUM", "NMAX"), complete(accu));
    }

    private List<? extends TextEdit> format(String uri) throws Exception {
        return remote.getTextDocumentService().formatting(new DocumentFormattingParams(doc(uri),
                new FormattingOptions(4, true))).get(30, TimeUnit.SECONDS);
    }

    @Test
    void formattingIsFmtsLayoutAndKeepsComments() throws Exception {
        initialize("{\"dialect\": \"strict\"}");
        String messy = VALID.replace("    level : REAL;", "  level:REAL;").replace("RULE 1 : IF", "RULE 1:IF");
        String uri = open("messy.fcl", messy);
        List<? extends TextEdit> edits = format(uri);
        StringWriter fmt = new StringWriter();
        Main.run(new PrintWriter(fmt), new PrintWriter(new StringWriter()), "fmt", dir.resolve("messy.fcl").toString());
        assertEquals(1, edits.size());
        assertEquals(fmt.toString(), edits.get(0).getNewText());
        assertEquals(new Range(new Position(0, 0), new Position(25, 0)), edits.get(0).getRange());

        // comments are kept where they stood, as fmt keeps them
        String commented = open("commented.fcl", "(* the valve *)\n" + messy.replace("  level:REAL;",
                "  level:REAL;    (* m *)"));
        List<? extends TextEdit> kept = format(commented);
        StringWriter fmtCommented = new StringWriter();
        Main.run(new PrintWriter(fmtCommented), new PrintWriter(new StringWriter()), "fmt",
                dir.resolve("commented.fcl").toString());
        assertEquals(1, kept.size());
        assertEquals(fmtCommented.toString(), kept.get(0).getNewText());
        assertTrue(kept.get(0).getNewText().startsWith("(* the valve *)\nFUNCTION_BLOCK valve\nVAR_INPUT\n"
                + "    level : REAL; (* m *)\nEND_VAR\n"), kept.get(0).getNewText());

        String broken = open("broken.fcl", MISTAKES);
        assertEquals(List.of(), format(broken));
        assertTrue(client.shown.poll(30, TimeUnit.SECONDS).getMessage().contains("has errors; not formatted"));
    }

    /** A valve in jFuzzyLogic's dialect (COGS, no RANGE), laid out carelessly. */
    private static final String JFUZZYLOGIC_MESSY = """
            FUNCTION_BLOCK valve
            VAR_INPUT level:REAL; END_VAR
            VAR_OUTPUT flow:REAL; END_VAR
            FUZZIFY level
              TERM low:=(0,1) (6,0);  TERM high:=(4,0) (10,1);
            END_FUZZIFY
            DEFUZZIFY flow
              TERM shut:=0; TERM open:=100;
              METHOD:COGS; DEFAULT:=0;
            END_DEFUZZIFY
            RULEBLOCK r
              AND:MIN; ACT:MIN; ACCU:MAX;
              RULE 1:IF level IS low THEN flow IS open;
              RULE 2:IF level IS high THEN flow IS shut;
            END_RULEBLOCK
            END_FUNCTION_BLOCK
            """;

    /** The next warning shown to the user (the notes of which dialect a document was read in pass by). */
    private MessageParams shownWarning() throws InterruptedException {
        while (true) {
            MessageParams m = client.shown.poll(30, TimeUnit.SECONDS);
            assertNotNull(m, "no warning shown within 30 s");
            if (m.getType() == MessageType.Warning) {
                return m;
            }
        }
    }

    @Test
    void formattingADialectDocumentUsesThatDialectsWriter() throws Exception {
        initialize("{\"dialect\": \"jfuzzylogic\"}");
        String uri = open("jfl.fcl", JFUZZYLOGIC_MESSY);
        List<? extends TextEdit> edits = format(uri);
        assertEquals(1, edits.size());
        String formatted = edits.get(0).getNewText();
        // jFuzzyLogic's layout as 'fclcert convert --to jfuzzylogic' writes it (the same writer), not standard FCL
        StringWriter converted = new StringWriter();
        Main.run(new PrintWriter(converted), new PrintWriter(new StringWriter()), "convert", "--from", "jfuzzylogic",
                "--to", "jfuzzylogic", dir.resolve("jfl.fcl").toString());
        assertEquals(converted.toString(), formatted);
        assertTrue(formatted.contains("    TERM low := (0, 1) (6, 0);\n") && formatted.contains("METHOD : COGS;"), formatted);
        // the writer's layout is its own fixed point: formatting it again changes nothing and refuses nothing
        String again = open("jfl-formatted.fcl", formatted);
        assertTrue(diagnosticsOf(again).getDiagnostics().isEmpty());
        assertEquals(List.of(), format(again));
        for (MessageParams m = client.shown.poll(1, TimeUnit.SECONDS); m != null; m = client.shown.poll(1, TimeUnit.SECONDS)) {
            assertEquals(MessageType.Info, m.getType(), m.getMessage());   // which dialect it was read in, nothing more
        }

        // a comment its writer would drop: left alone, and the user is told why
        String commented = open("jfl-commented.fcl", JFUZZYLOGIC_MESSY.replace("TERM open:=100;", "TERM open:=100; // %"));
        assertEquals(List.of(), format(commented));
        MessageParams refusal = shownWarning();
        assertTrue(refusal.getMessage().contains("jfl-commented.fcl is read as jFuzzyLogic; not formatted: it has"
                + " 1 comment, which fclcert's jFuzzyLogic writer does not keep"), refusal.getMessage());

        // fuzzylite's FLL: its writer's layout, a fixed point as well
        remote.getWorkspaceService().didChangeConfiguration(new DidChangeConfigurationParams(
                JsonParser.parseString("{\"fclcert\": {\"dialect\": \"fll\"}}")));
        String fll = open("dimmer.fll", """
                Engine: dimmer
                InputVariable: x
                  range: 0.000 1.000
                  term: low Triangle 0.000 0.250 0.500
                OutputVariable: y
                  range: 0.000 1.000
                  aggregation: Maximum
                  defuzzifier: Centroid 200
                  default: nan
                  term: dim Triangle 0.000 0.250 0.500
                RuleBlock: rules
                  implication: Minimum
                  rule: if x is low then y is dim
                """);
        diagnosticsOf(fll);
        List<? extends TextEdit> fllEdits = format(fll);
        assertEquals(1, fllEdits.size());
        String fllText = fllEdits.get(0).getNewText();
        assertTrue(fllText.startsWith("Engine: dimmer\n") && fllText.contains("  rule: if x is low then y is dim\n"),
                fllText);
        String fllAgain = open("dimmer-again.fll", fllText);
        diagnosticsOf(fllAgain);
        assertEquals(List.of(), format(fllAgain));
    }

    @Test
    void codeActionsMendWhatCheckFinds() throws Exception {
        initialize("{\"dialect\": \"strict\"}");
        String uri = open("mistakes.fcl", MISTAKES);
        PublishDiagnosticsParams p = diagnosticsOf(uri);
        Range all = new Range(new Position(0, 0), new Position(30, 0));
        List<CodeAction> actions = remote.getTextDocumentService().codeAction(new CodeActionParams(doc(uri), all,
                new CodeActionContext(p.getDiagnostics()))).get(30, TimeUnit.SECONDS).stream().map(e -> e.getRight()).toList();
        assertEquals(List.of("Insert the missing ';'", "Add 'DEFAULT := NC;'", "Change 'servce' to 'service'",
                "Change 'rancd' to 'rancid'"), actions.stream().map(CodeAction::getTitle).toList());
        // every fix applied: check then finds only the unused term and the program's real coverage gap (service
        // above 9 is neither poor nor good, food above 3 is not rancid: no rule fires), which no fix is offered for
        List<TextEdit> edits = new ArrayList<>();
        actions.forEach(a -> edits.addAll(a.getEdit().getChanges().get(uri)));
        String fixed = apply(MISTAKES, edits);
        Files.writeString(dir.resolve("fixed.fcl"), fixed);
        List<String> after = check(dir.resolve("fixed.fcl"), "strict");
        assertEquals(2, after.size(), after.toString());
        assertTrue(after.get(0).contains("FCL-W001"), after.toString());
        assertTrue(after.get(1).contains("FCL-W005") && after.get(1).contains("service in [9, inf)"), after.toString());
        assertTrue(fixed.contains("    DEFAULT := NC;\nEND_DEFUZZIFY"), fixed);

        // ACCU written in DEFUZZIFY (strict reading): moved into the RULEBLOCK
        String accu = MISTAKES.replace("    METHOD : CoG;\n", "    METHOD : CoG;\n    ACCU : MAX;\n")
                .replace("    ACCU : MAX;\n    RULE 1", "    RULE 1");
        String misplaced = open("accu.fcl", accu);
        PublishDiagnosticsParams q = diagnosticsOf(misplaced);
        List<CodeAction> move = remote.getTextDocumentService().codeAction(new CodeActionParams(doc(misplaced), all,
                new CodeActionContext(q.getDiagnostics()))).get(30, TimeUnit.SECONDS).stream().map(e -> e.getRight())
                .filter(a -> a.getTitle().startsWith("Move")).toList();
        assertEquals(1, move.size());
        assertEquals("Move 'ACCU : MAX;' into RULEBLOCK No1", move.get(0).getTitle());
        String moved = apply(accu, move.get(0).getEdit().getChanges().get(misplaced));
        // before the first rule: where 5.4 places accumulation (after AND), so the text is the mistakes file again
        assertEquals(MISTAKES, moved);
    }

    /** Applies non-overlapping edits, last first. */
    private static String apply(String text, List<TextEdit> edits) {
        SourceText src = new SourceText(text);
        List<TextEdit> sorted = new ArrayList<>(edits);
        sorted.sort(Comparator.comparingInt((TextEdit e) -> src.offset(e.getRange().getStart())).reversed());
        StringBuilder s = new StringBuilder(text);
        for (TextEdit e : sorted) {
            s.replace(src.offset(e.getRange().getStart()), src.offset(e.getRange().getEnd()), e.getNewText());
        }
        return s.toString();
    }

    @Test
    void dialectFromTheSettingOrDetectedAndShown() throws Exception {
        initialize(null);
        // fuzzylite's giveaway, ACCU inside DEFUZZIFY: auto reads it as fuzzylite and says so
        String accu = MISTAKES.replace("    METHOD : CoG;\n", "    METHOD : CoG;\n    ACCU : MAX;\n");
        String uri = open("accu.fcl", accu);
        PublishDiagnosticsParams auto = diagnosticsOf(uri);
        MessageParams note = client.shown.poll(30, TimeUnit.SECONDS);
        assertTrue(note.getMessage().contains("read as fuzzylite") && note.getMessage().contains("ACCU inside DEFUZZIFY"),
                note.getMessage());
        assertEquals(check(dir.resolve("accu.fcl"), "auto"), shown(auto));
        remote.getWorkspaceService().didChangeConfiguration(new DidChangeConfigurationParams(
                JsonParser.parseString("{\"fclcert\": {\"dialect\": \"strict\"}}")));
        PublishDiagnosticsParams strict = diagnosticsOf(uri);
        assertEquals(check(dir.resolve("accu.fcl"), "strict"), shown(strict));
        assertTrue(shown(strict).stream().anyMatch(s -> s.contains("ACCU and ACT belong in a RULEBLOCK")));
        remote.getWorkspaceService().didChangeConfiguration(new DidChangeConfigurationParams(
                JsonParser.parseString("{\"fclcert\": {\"dialect\": \"klingon\"}}")));
        MessageParams unknown = client.shown.poll(30, TimeUnit.SECONDS);
        assertEquals(MessageType.Error, unknown.getType());
        assertTrue(unknown.getMessage().contains("unknown dialect 'klingon'"), unknown.getMessage());
    }

    /**
     * Under auto the server keeps a document's dialect choice across edits that cannot change it (digits typed over
     * in a number outside a TERM, {@code DialectReaders.kept}) and detects it again after any other: either way
     * every edit's diagnostics are check's for the edited file, in each dialect auto can choose, on texts with
     * errors (a syntax error and undefined names: the reader's repair path).
     */
    @Test
    void afterDigitEditsTheDiagnosticsAreChecksInEveryDialectAutoChooses() throws Exception {
        initialize(null);
        String strict = MISTAKES.replace("    METHOD : CoG;\n", "    METHOD : CoG;\n    DEFAULT := 0;\n")
                .replace("THEN tip IS generous;", "THEN tip IS generous WITH 0.5;");
        Map<String, String> texts = new java.util.LinkedHashMap<>();
        texts.put("standard FCL", strict);
        texts.put("Free Fuzzy Logic Library (FFLL)", strict.replace("ACCU : MAX;", "ACCUM : MAX;"));
        texts.put("jFuzzyLogic", strict.replace("DEFAULT := 0;", "/* jFuzzyLogic's comment */"));
        texts.put("fuzzylite", strict.replace("    ACCU : MAX;\n", "").replace("DEFAULT := 0;", "DEFAULT := 0;\n    ACCU : MAX;"));
        texts.put("fuzzylite's FLL", "Engine: e\nInputVariable: x\n  range: 0 10\n  term: low Triangle 0 5 10 20\n"
                + "OutputVariable: y\n  range: 0 1\n  aggregation: Maximum\n  term: on Ramp 0 1\nRuleBlock: r\n  rule: if x is lw then y is on\n");
        texts.put("MATLAB FIS", "[System]\nName='s'\nNumInputs=1\nNumOutputs=1\nNumRules=1\n[Input1]\nName='x'\nRange=[0 10]\n"
                + "MF1='low':'trimf',[0 5 10 15]\n[Output1]\nName='y'\nRange=[0 1]\nMF1='on':'trimf',[0 1 2]\n"
                + "[Rules]\n1, 2 (1) : 1\n");
        int n = 0;
        for (var e : texts.entrySet()) {
            String name = "digits" + n++ + (e.getKey().endsWith("FLL") ? ".fll" : e.getKey().endsWith("FIS") ? ".fis" : ".fcl");
            String text = e.getValue();
            String uri = open(name, text);
            assertEquals(check(dir.resolve(name), "auto"), shown(diagnosticsOf(uri)), e.getKey());
            MessageParams note = e.getKey().equals("standard FCL") ? client.logged.poll(30, TimeUnit.SECONDS)
                    : client.shown.poll(30, TimeUnit.SECONDS);
            assertTrue(note.getMessage().contains("read as " + e.getKey()), e.getKey() + ": " + note.getMessage());
            assertFalse(check(dir.resolve(name), "auto").isEmpty(), e.getKey() + " has errors");
            // every fifth digit typed over: rule numbers and weights (kept) and points (detected again)
            List<Integer> digits = new ArrayList<>();
            for (int i = 0; i < text.length(); i++) {
                if (Character.isDigit(text.charAt(i))) {
                    digits.add(i);
                }
            }
            for (int k = 0; k < digits.size(); k += 5) {
                int at = digits.get(k);
                String typed = String.valueOf((char) ('0' + (text.charAt(at) - '0' + 3) % 10));
                int line = (int) text.substring(0, at).chars().filter(c -> c == '\n').count();
                int column = at - text.lastIndexOf('\n', at - 1) - 1;
                text = text.substring(0, at) + typed + text.substring(at + 1);
                Files.writeString(dir.resolve(name), text);
                change(uri, new Range(new Position(line, column), new Position(line, column + 1)), typed);
                PublishDiagnosticsParams p = diagnosticsOf(uri);
                while (p.getVersion() != version) {
                    p = diagnosticsOf(uri);
                }
                assertEquals(check(dir.resolve(name), "auto"), shown(p), e.getKey() + " after '" + typed + "' at "
                        + (line + 1) + ":" + (column + 1) + "\n" + text);
            }
        }
    }

    @Test
    void badInputNeverStopsTheServer() throws Exception {
        // requests before initialize and on documents never opened: empty answers
        assertNull(hover("file:///nowhere.fcl", 0, 0));
        initialize(null);
        // any text: binary noise, an unterminated comment, deep parentheses, a character beyond the BMP, nothing
        StringBuilder deep = new StringBuilder("FUNCTION_BLOCK f\nRULEBLOCK r\nRULE 1 : IF ");
        deep.append("(".repeat(5000)).append("x");
        for (String text : List.of("\u0000\u0001\uFFFF garbage ;;; :=", "(* never closed", deep.toString(),
                "FUNCTION_BLOCK \uD83D\uDE00 x END_FUNCTION_BLOCK", "")) {
            String uri = open("any" + version + ".fcl", text);
            assertFalse(diagnosticsOf(uri).getDiagnostics().isEmpty() && !text.isEmpty());
            hover(uri, 0, 3);
            complete(text);
            remote.getTextDocumentService().documentSymbol(new DocumentSymbolParams(doc(uri))).get(30, TimeUnit.SECONDS);
            format(uri);
        }
        // an edit to a document not open; a range outside the text; a request without its document
        change("file:///nowhere.fcl", null, "x");
        assertTrue(logged(m -> m.getMessage().contains("which is not open")).getMessage().endsWith("ignored"));
        String uri = open("valid.fcl", VALID);
        diagnosticsOf(uri);
        change(uri, new Range(new Position(500, -3), new Position(-1, 900)), "");
        assertNotNull(diagnosticsOf(uri));
        assertNull(remote.getTextDocumentService().hover(new HoverParams()).get(30, TimeUnit.SECONDS));
        MessageParams error = logged(m -> m.getType() == MessageType.Error);
        assertTrue(error.getMessage().startsWith("fclcert: internal error in hover: java.lang.NullPointerException"),
                error.getMessage());
        // an unknown method; a broken message on the wire
        ExecutionException unknown = assertThrows(ExecutionException.class, () -> launcher.getRemoteEndpoint()
                .request("fclcert/noSuchMethod", Map.of()).get(30, TimeUnit.SECONDS));
        assertEquals(ResponseErrorCode.MethodNotFound.getValue(),
                ((ResponseErrorException) unknown.getCause()).getResponseError().getCode());
        synchronized (toServer) {
            toServer.write("Content-Length: 9\r\n\r\n{\"id\":1,}".getBytes(StandardCharsets.US_ASCII));
            toServer.flush();
        }
        // still serving: the keyword under the cursor
        assertTrue(hover(uri, 0, 2).getContents().getRight().getValue().startsWith("**FUNCTION_BLOCK**"));
        remote.shutdown().get(30, TimeUnit.SECONDS);
        remote.exit();
        assertEquals(0, served.get(30, TimeUnit.SECONDS), "shutdown, then exit: exit code 0");
    }

    /** The first message logged to the client that matches, waiting for it up to 30 s. */
    private MessageParams logged(java.util.function.Predicate<MessageParams> wanted) throws InterruptedException {
        for (MessageParams m = client.logged.poll(30, TimeUnit.SECONDS); m != null; m = client.logged.poll(30, TimeUnit.SECONDS)) {
            if (wanted.test(m)) {
                return m;
            }
        }
        throw new AssertionError("no such message logged to the client within 30 s");
    }

    @Test
    void aVanishedClientEndsTheSession() throws Exception {
        initialize(null);
        open("valid.fcl", VALID);
        toServer.close();
        assertEquals(1, served.get(30, TimeUnit.SECONDS), "the input ended without shutdown: exit code 1");
    }

    @Test
    void stateStaysBoundedOverAThousandEdits() throws Exception {
        initialize("{\"debounceMillis\": 20}");
        String uri = open("valid.fcl", VALID);
        diagnosticsOf(uri);
        long afterHundred = 0;
        for (int i = 1; i <= 1000; i++) {
            // 'RANGE (0 .. 100);' on line 13: the upper end 100 becomes 100..999, one keystroke each
            change(uri, new Range(new Position(12, 16), new Position(12, 19)), String.valueOf(100 + (i % 900)));
            if (i % 50 == 0) {
                hover(uri, 21, 35);
            }
            if (i == 100) {
                afterHundred = usedHeapAfterGc();
            }
        }
        hover(uri, 21, 35);
        int[] state = server.state();
        assertEquals(1, state[0], "one open document");
        assertTrue(state[1] <= 1, "at most one diagnostics run waits per document");
        long growth = usedHeapAfterGc() - afterHundred;
        assertTrue(growth < 32L << 20, "heap grew by " + (growth >> 20) + " MB from edit 100 to edit 1000");
        remote.getTextDocumentService().didClose(new DidCloseTextDocumentParams(doc(uri)));
        hover(uri, 0, 0);   // a request after the close is answered after it
        assertEquals(0, server.state()[0], "closing forgets the document");
    }

    private static long usedHeapAfterGc() throws InterruptedException {
        long used = Long.MAX_VALUE;
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(50);
            used = Math.min(used, ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed());
        }
        return used;
    }

    private static String resource(String name) {
        try (var in = LspClientTest.class.getResourceAsStream(name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
