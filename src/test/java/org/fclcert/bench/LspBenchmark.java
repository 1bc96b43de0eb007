package org.fclcert.bench;

import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageServer;
import org.fclcert.lsp.FclLanguageServer;
import org.fclcert.lsp.RecordingClient;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * From an edit to its diagnostics in the language server, as an editor sees it: an LSP4J client sends one
 * keystroke's incremental change to a 10 000-line program ({@link ParseBenchmark#largeProgram}, 9 990 rules) and
 * waits for the diagnostics of that version. The server runs in this JVM over pipes, with the JSON of both ways.
 * {@code debounce}: 0 measures the work alone; 50 is the server's default pause before it recomputes. {@code text}:
 * {@code valid}, or {@code syntaxError} (one rule in the middle lacks its ';', so every reading takes the full
 * pipeline with repair, the slow path). See docs/performance.md ("The language server").
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
// the parallel collector, as ./fclcert runs the server (G1's pauses made the wall time here twice the CPU time)
@Fork(value = 1, jvmArgsAppend = {"-Xmx2g", "-XX:+UseParallelGC"})
@Warmup(iterations = 3, time = 4)
@Measurement(iterations = 5, time = 6)
public class LspBenchmark {
    static final int RULES = 9_990;

    @Param({"0", "50"})
    public int debounce;

    @Param({"valid", "syntaxError"})
    public String text;

    /** The server's dialect setting: {@code strict}, or {@code auto}, the default, which detects it on every edit. */
    @Param({"strict", "auto"})
    public String dialect;

    private final RecordingClient client = new RecordingClient();
    private PipedOutputStream toServer;
    private LanguageServer server;
    private String uri = "file:///bench/large.fcl";
    private int version = 1;
    private int lastLine;
    private int weightColumn;
    private boolean high;

    @Setup(Level.Trial)
    public void start() throws Exception {
        String program = ParseBenchmark.largeProgram(RULES);
        if (text.equals("syntaxError")) {
            program = program.replace("WITH 0.5; (* 5000 *)", "WITH 0.5 (* 5000 *)");
        }
        String[] lines = program.split("\n");
        lastLine = lines.length - 3;     // the last rule, before END_RULEBLOCK and END_FUNCTION_BLOCK
        weightColumn = lines[lastLine].indexOf("0.5");
        PipedInputStream serverIn = new PipedInputStream(1 << 22);
        toServer = new PipedOutputStream(serverIn);
        PipedInputStream clientIn = new PipedInputStream(1 << 22);
        PipedOutputStream toClient = new PipedOutputStream(clientIn);
        CompletableFuture.runAsync(() -> FclLanguageServer.serve(serverIn, toClient));
        var launcher = LSPLauncher.createClientLauncher(client, clientIn, toServer);
        launcher.startListening();
        server = launcher.getRemoteProxy();
        InitializeParams init = new InitializeParams();
        init.setCapabilities(new ClientCapabilities());
        init.setInitializationOptions(JsonParser.parseString(
                "{\"dialect\": \"" + dialect + "\", \"debounceMillis\": " + debounce + "}"));
        server.initialize(init).get(60, TimeUnit.SECONDS);
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(
                new TextDocumentItem(uri, "fcl", version, program)));
        await(version);
    }

    /** One keystroke: the weight of the last rule, 0.5 to 0.7 and back; the diagnostics of that version. */
    @Benchmark
    public int diagnosticsAfterAnEdit() throws Exception {
        high = !high;
        Range weight = new Range(new Position(lastLine, weightColumn + 2), new Position(lastLine, weightColumn + 3));
        server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(
                new VersionedTextDocumentIdentifier(uri, ++version),
                List.of(new TextDocumentContentChangeEvent(weight, high ? "7" : "5"))));
        return await(version).getDiagnostics().size();
    }

    private PublishDiagnosticsParams await(int v) throws InterruptedException {
        while (true) {
            PublishDiagnosticsParams p = client.diagnostics.poll(60, TimeUnit.SECONDS);
            if (p == null) {
                throw new IllegalStateException("no diagnostics for version " + v + " within 60 s");
            }
            if (p.getVersion() != null && p.getVersion() == v) {
                return p;
            }
        }
    }

    @TearDown(Level.Trial)
    public void stop() throws IOException {
        toServer.close();
    }
}
