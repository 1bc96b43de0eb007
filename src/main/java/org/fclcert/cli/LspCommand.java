package org.fclcert.cli;

import java.io.FileInputStream;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.fclcert.lsp.FclLanguageServer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code fclcert lsp}: the language server on stdin and stdout (docs/lsp.md). Those streams carry the protocol
 * only, so the command prints nothing; the server's messages go to the editor.
 */
@Command(name = "lsp", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "Run the FCL language server over stdin/stdout (Language Server Protocol) for an editor: "
                + "check's diagnostics as you type, hover, go to definition, references, outline, completion, "
                + "formatting and quick fixes. The editor starts it; settings: fclcert.dialect (default auto).",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = {"0:the editor ended the session with shutdown and exit",
            "1:the input ended (or exit came) without shutdown", ExitCodes.INTERNAL_LINE})
final class LspCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    /** LSP4J's logger, held so that its configuration stays (a logger only weakly referenced may be collected). */
    private static final Logger LSP4J = Logger.getLogger("org.eclipse.lsp4j");

    @Override
    public Integer call() {
        // what LSP4J logs (a broken pipe when the editor vanishes, a message it cannot parse) goes to stderr, which
        // editors keep as the server's log, as one line each: never a stack trace
        PrintWriter err = spec.commandLine().getErr();
        LSP4J.setUseParentHandlers(false);
        LSP4J.addHandler(new Handler() {
            @Override
            public void publish(LogRecord r) {
                Throwable t = r.getThrown();
                err.println("fclcert lsp: " + r.getLevel().getName().toLowerCase(java.util.Locale.ROOT) + ": "
                        + (t != null && t.getMessage() != null ? t.getMessage() : r.getMessage()));
                err.flush();
            }

            @Override
            public void flush() {
                err.flush();
            }

            @Override
            public void close() {
            }
        });
        // the raw descriptors: System.out may be wrapped, and nothing else may write to the protocol stream
        return FclLanguageServer.serve(new FileInputStream(FileDescriptor.in), new FileOutputStream(FileDescriptor.out));
    }
}
