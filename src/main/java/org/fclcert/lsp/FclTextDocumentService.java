package org.fclcert.lsp;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.function.Function;
import java.util.function.Supplier;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionParams;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidCloseTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DidSaveTextDocumentParams;
import org.eclipse.lsp4j.DocumentFormattingParams;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.SymbolInformation;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.TextDocumentService;

/** The text document half of the protocol: each request answered from the document's current {@link Snapshot}. */
final class FclTextDocumentService implements TextDocumentService {
    private final FclLanguageServer server;

    FclTextDocumentService(FclLanguageServer server) {
        this.server = server;
    }

    @Override
    public void didOpen(DidOpenTextDocumentParams params) {
        server.guarded("didOpen", () -> {
            String uri = params.getTextDocument().getUri();
            server.documents().open(uri, params.getTextDocument().getText(), params.getTextDocument().getVersion());
            server.schedule(uri, true);
            return null;
        }, null);
    }

    @Override
    public void didChange(DidChangeTextDocumentParams params) {
        server.guarded("didChange", () -> {
            String uri = params.getTextDocument().getUri();
            Integer version = params.getTextDocument().getVersion();
            if (server.documents().change(uri, version == null ? 0 : version, params.getContentChanges())) {
                server.schedule(uri, false);
            } else {
                server.log(MessageType.Warning, "fclcert: change of " + uri + ", which is not open; ignored");
            }
            return null;
        }, null);
    }

    @Override
    public void didClose(DidCloseTextDocumentParams params) {
        server.guarded("didClose", () -> {
            server.forget(params.getTextDocument().getUri());
            return null;
        }, null);
    }

    @Override
    public void didSave(DidSaveTextDocumentParams params) {
        // the text arrives with each change; saving changes nothing
    }

    @Override
    public CompletableFuture<Hover> hover(HoverParams params) {
        return answer("hover", params::getTextDocument, s -> Hovers.at(s, params.getPosition()).orElse(null), null);
    }

    @Override
    public CompletableFuture<Either<List<? extends Location>, List<? extends LocationLink>>> definition(
            DefinitionParams params) {
        return answer("definition", params::getTextDocument,
                s -> Either.forLeft(Navigation.definition(s, params.getPosition())), Either.forLeft(List.of()));
    }

    @Override
    public CompletableFuture<List<? extends Location>> references(ReferenceParams params) {
        boolean declaration = params.getContext() == null || params.getContext().isIncludeDeclaration();
        return answer("references", params::getTextDocument,
                s -> Navigation.references(s, params.getPosition(), declaration), List.of());
    }

    @Override
    public CompletableFuture<List<Either<SymbolInformation, DocumentSymbol>>> documentSymbol(DocumentSymbolParams params) {
        return answer("documentSymbol", params::getTextDocument,
                s -> Navigation.symbols(s).stream().map(Either::<SymbolInformation, DocumentSymbol>forRight).toList(),
                List.of());
    }

    @Override
    public CompletableFuture<Either<List<CompletionItem>, CompletionList>> completion(CompletionParams params) {
        return answer("completion", params::getTextDocument,
                s -> Either.forLeft(Completions.at(s, params.getPosition())), Either.forLeft(List.of()));
    }

    @Override
    public CompletableFuture<List<? extends TextEdit>> formatting(DocumentFormattingParams params) {
        return answer("formatting", params::getTextDocument, s -> {
            Formatting.Result r = Formatting.of(s);
            if (r.refusal() != null) {
                server.show(MessageType.Warning, "fclcert: " + r.refusal());
            }
            return r.edits();
        }, List.of());
    }

    @Override
    public CompletableFuture<List<Either<Command, CodeAction>>> codeAction(CodeActionParams params) {
        return answer("codeAction", params::getTextDocument,
                s -> CodeActions.in(s, params.getRange()).stream().map(Either::<Command, CodeAction>forRight).toList(),
                List.of());
    }

    /** A request on a document: answered from its snapshot, {@code none} for a document not open. */
    private <T> CompletableFuture<T> answer(String what, Supplier<TextDocumentIdentifier> document,
            Function<Snapshot, T> work, T none) {
        return server.guarded(what, () -> {
            Optional<Snapshot> s = server.documents().snapshot(document.get().getUri());
            return s.isEmpty() ? none : work.apply(s.get());
        }, none);
    }
}
