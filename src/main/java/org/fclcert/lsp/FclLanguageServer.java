package org.fclcert.lsp;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import org.eclipse.lsp4j.CodeActionKind;
import org.eclipse.lsp4j.CodeActionOptions;
import org.eclipse.lsp4j.CompletionOptions;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.ServerInfo;
import org.eclipse.lsp4j.TextDocumentSyncKind;
import org.eclipse.lsp4j.TextDocumentSyncOptions;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageClientAware;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.lsp4j.services.TextDocumentService;
import org.eclipse.lsp4j.services.WorkspaceService;
import org.fclcert.model.Toolkit;
import org.fclcert.syntax.SyntaxCode;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectCode;

/**
 * The FCL language server (docs/lsp.md). Diagnostics are check's findings, published when a document opens and
 * again after each edit once the edits pause for the debounce ({@link #DEFAULT_DEBOUNCE_MILLIS}, or the client's
 * {@code debounceMillis} initialization option); requests read the current version at once. The dialect is the
 * client's setting {@code fclcert.dialect} (initialization options or workspace configuration), else detected as
 * {@code --dialect auto} does, and shown to the user. Every request and notification is guarded: an internal error
 * becomes an error message logged to the client and an empty answer, and the server goes on.
 */
public final class FclLanguageServer implements LanguageServer, LanguageClientAware {
    /** Milliseconds of quiet after an edit before the diagnostics are recomputed. */
    public static final long DEFAULT_DEBOUNCE_MILLIS = 50;
    /**
     * Stack of the server's threads: reading and checking recurse once or a few times per nesting level of a
     * condition, as deep as the reader's limit allows (address space reserved, committed only when used).
     */
    static final long STACK_BYTES = 256L * 1024 * 1024;

    private final Documents documents = new Documents();
    private final ScheduledExecutorService diagnostics = Executors.newSingleThreadScheduledExecutor(threads("fclcert-lsp-diagnostics"));
    private final FclTextDocumentService textDocuments = new FclTextDocumentService(this);
    private final FclWorkspaceService workspace = new FclWorkspaceService(this);
    private final CompletableFuture<Void> exited = new CompletableFuture<>();
    private volatile LanguageClient client;
    private volatile long debounceMillis = DEFAULT_DEBOUNCE_MILLIS;
    private volatile boolean shutdown;

    /**
     * Serves one client over a pair of streams (stdin and stdout for {@code fclcert lsp}) until it sends
     * {@code exit} or its input ends. Returns the exit code the protocol asks for: 0 after {@code shutdown},
     * else 1.
     */
    public static int serve(InputStream in, OutputStream out) {
        return new FclLanguageServer().run(in, out);
    }

    /** {@link #serve} with this server (tests keep it to look at its state). */
    int run(InputStream in, OutputStream out) {
        FclLanguageServer server = this;
        ExecutorService messages = Executors.newCachedThreadPool(threads("fclcert-lsp"));
        try {
            Launcher<LanguageClient> launcher = new LSPLauncher.Builder<LanguageClient>().setLocalService(server)
                    .setRemoteInterface(LanguageClient.class).setInput(in).setOutput(out)
                    .setExecutorService(messages).create();
            server.connect(launcher.getRemoteProxy());
            CompletableFuture<Object> listening = CompletableFuture.anyOf(
                    CompletableFuture.runAsync(() -> waitFor(launcher), messages), server.exited);
            listening.join();
            return server.shutdown ? 0 : 1;
        } finally {
            server.stop();
            messages.shutdownNow();
        }
    }

    private static void waitFor(Launcher<LanguageClient> launcher) {
        try {
            launcher.startListening().get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException e) {
            // the input broke: the client is gone, which ends the session like the end of the input
        }
    }

    static ThreadFactory threads(String name) {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(null, r, name + "-" + n.incrementAndGet(), STACK_BYTES);
            t.setDaemon(true);
            return t;
        };
    }

    @Override
    public void connect(LanguageClient client) {
        this.client = client;
    }

    @Override
    public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
        return guarded("initialize", () -> {
            settings(params == null ? null : params.getInitializationOptions());
            ServerCapabilities c = new ServerCapabilities();
            TextDocumentSyncOptions sync = new TextDocumentSyncOptions();
            sync.setOpenClose(true);
            sync.setChange(TextDocumentSyncKind.Incremental);
            c.setTextDocumentSync(sync);
            c.setHoverProvider(true);
            c.setDefinitionProvider(true);
            c.setReferencesProvider(true);
            c.setDocumentSymbolProvider(true);
            c.setCompletionProvider(new CompletionOptions(false, List.of(":")));
            c.setDocumentFormattingProvider(true);
            c.setCodeActionProvider(new CodeActionOptions(List.of(CodeActionKind.QuickFix)));
            return new InitializeResult(c, new ServerInfo("fclcert", Toolkit.version()));
        }, null);
    }

    @Override
    public CompletableFuture<Object> shutdown() {
        shutdown = true;
        return CompletableFuture.completedFuture(null);
    }

    @Override
    public void exit() {
        exited.complete(null);
    }

    @Override
    public TextDocumentService getTextDocumentService() {
        return textDocuments;
    }

    @Override
    public WorkspaceService getWorkspaceService() {
        return workspace;
    }

    Documents documents() {
        return documents;
    }

    /** How many documents the server holds, and how many diagnostics runs wait: its whole state (for tests). */
    public int[] state() {
        return new int[] {documents.size(), documents.waiting()};
    }

    /**
     * Reads {@code dialect} and {@code debounceMillis} from initialization options or workspace settings, given
     * plainly or under {@code fclcert}; an unknown dialect is reported to the user and changes nothing.
     */
    void settings(Object options) {
        if (!(options instanceof JsonObject all)) {
            return;
        }
        JsonObject o = all.has("fclcert") && all.get("fclcert").isJsonObject() ? all.getAsJsonObject("fclcert") : all;
        JsonElement d = o.get("dialect");
        if (d != null && d.isJsonPrimitive()) {
            String name = d.getAsString();
            if (name.equalsIgnoreCase("auto")) {
                documents.dialect(Optional.empty());
            } else {
                Optional<Dialect> named = Dialect.byCliName(name);
                if (named.isPresent()) {
                    documents.dialect(named);
                } else {
                    show(MessageType.Error, "fclcert: unknown dialect '" + name + "' in the setting fclcert.dialect; one of "
                            + String.join(", ", Arrays.stream(Dialect.values()).map(Dialect::cliName).toList())
                            + " or auto");
                }
            }
        }
        JsonElement ms = o.get("debounceMillis");
        if (ms != null && ms.isJsonPrimitive() && ms.getAsJsonPrimitive().isNumber()) {
            debounceMillis = Math.max(0, Math.min(10_000, ms.getAsLong()));
        }
    }

    /** Publishes the diagnostics of a document's current version after the debounce, replacing a waiting run. */
    void schedule(String uri, boolean now) {
        try {
            documents.pending(uri, diagnostics.schedule(() -> publish(uri), now ? 0 : debounceMillis,
                    TimeUnit.MILLISECONDS));
        } catch (java.util.concurrent.RejectedExecutionException e) {
            // stopping: nothing more to publish
        }
    }

    void republishAll() {
        documents.uris().forEach(uri -> schedule(uri, true));
    }

    private void publish(String uri) {
        guarded("diagnostics of " + uri, () -> {
            Optional<Snapshot> s = documents.snapshot(uri);
            if (s.isEmpty() || !documents.current(s.get())) {
                return null;    // closed or edited meanwhile: the run after the edit publishes
            }
            Snapshot snapshot = s.get();
            if (documents.newNote(uri, snapshot.dialectNote())) {
                boolean strict = snapshot.dialect() == Dialect.STRICT && snapshot.diagnostics().stream()
                        .noneMatch(d -> d.diagnosticCode() == DialectCode.DIALECT_UNCLEAR
                                || d.diagnosticCode() == SyntaxCode.INTERNAL_ERROR);
                String note = "fclcert: " + snapshot.sourceName() + ": " + snapshot.dialectNote();
                if (strict) {
                    log(MessageType.Info, note);
                } else {
                    show(MessageType.Info, note);
                }
            }
            LanguageClient c = client;
            if (c != null) {
                c.publishDiagnostics(new PublishDiagnosticsParams(uri, Diagnostics.of(snapshot), snapshot.version()));
            }
            return null;
        }, null);
    }

    void forget(String uri) {
        documents.close(uri);
        LanguageClient c = client;
        if (c != null) {
            c.publishDiagnostics(new PublishDiagnosticsParams(uri, List.of()));
        }
    }

    /** Runs a piece of the server; an internal error is logged to the client and {@code fallback} answered. */
    <T> CompletableFuture<T> guarded(String what, Supplier<T> work, T fallback) {
        try {
            return CompletableFuture.completedFuture(work.get());
        } catch (Throwable e) {
            StringWriter trace = new StringWriter();
            e.printStackTrace(new PrintWriter(trace));
            String[] lines = trace.toString().split("\n");
            log(MessageType.Error, "fclcert: internal error in " + what + ": " + e + "\n"
                    + String.join("\n", Arrays.asList(lines).subList(1, Math.min(lines.length, 8))));
            return CompletableFuture.completedFuture(fallback);
        }
    }

    void log(MessageType type, String message) {
        LanguageClient c = client;
        if (c != null) {
            c.logMessage(new MessageParams(type, message));
        }
    }

    void show(MessageType type, String message) {
        LanguageClient c = client;
        if (c != null) {
            c.showMessage(new MessageParams(type, message));
        }
    }

    private void stop() {
        diagnostics.shutdownNow();
    }
}
