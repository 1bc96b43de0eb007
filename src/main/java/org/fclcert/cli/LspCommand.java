package org.fclcert.cli;

import java.io.FileInputStream;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.util.concurrent.Callable;
import org.fclcert.lsp.FclLanguageServer;
import picocli.CommandLine.Command;

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
    @Override
    public Integer call() {
        // the raw descriptors: System.out may be wrapped, and nothing else may write to the protocol stream
        return FclLanguageServer.serve(new FileInputStream(FileDescriptor.in), new FileOutputStream(FileDescriptor.out));
    }
}
