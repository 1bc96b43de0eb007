package org.fclcert.lsp;

import org.eclipse.lsp4j.DidChangeConfigurationParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.services.WorkspaceService;

/** The workspace half: the setting {@code fclcert.dialect} (and {@code debounceMillis}) may change at any time. */
final class FclWorkspaceService implements WorkspaceService {
    private final FclLanguageServer server;

    FclWorkspaceService(FclLanguageServer server) {
        this.server = server;
    }

    @Override
    public void didChangeConfiguration(DidChangeConfigurationParams params) {
        server.guarded("didChangeConfiguration", () -> {
            server.settings(params.getSettings());
            server.republishAll();
            return null;
        }, null);
    }

    @Override
    public void didChangeWatchedFiles(DidChangeWatchedFilesParams params) {
        // only open documents are read, and their text comes from the client
    }
}
