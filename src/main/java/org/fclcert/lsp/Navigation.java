package org.fclcert.lsp;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.SymbolKind;
import org.fclcert.model.Names;

/** Go to definition, find references and the document's outline, for function blocks, variables, terms and rule blocks. */
final class Navigation {
    private Navigation() {
    }

    /** The range of a token. */
    static Range range(Snapshot s, Outline.Tok t) {
        SourceText src = s.source();
        return new Range(src.position(src.offset(t.line(), t.column())), src.position(src.offset(t.line(), t.endColumn())));
    }

    /** The name at a position (the token under the cursor, or the one just before it). */
    static Optional<Outline.Occurrence> occurrenceAt(Snapshot s, Position p) {
        Outline o = s.outline();
        int offset = s.source().offset(p);
        int column = s.text().codePointCount(s.source().offset(new Position(p.getLine(), 0)), offset);
        int index = o.tokenAt(p.getLine() + 1, column, false);
        if (index < 0 || o.occurrenceAt(index).isEmpty()) {
            index = o.tokenAt(p.getLine() + 1, column, true);
        }
        return index < 0 ? Optional.empty() : o.occurrenceAt(index);
    }

    static List<Location> definition(Snapshot s, Position p) {
        return occurrenceAt(s, p).flatMap(o -> s.outline().declaration(o))
                .map(d -> List.of(location(s, d))).orElse(List.of());
    }

    static List<Location> references(Snapshot s, Position p, boolean includeDeclaration) {
        Optional<Outline.Occurrence> at = occurrenceAt(s, p);
        if (at.isEmpty()) {
            return List.of();
        }
        List<Location> out = new ArrayList<>();
        for (Outline.Occurrence o : s.outline().references(at.get())) {
            if (includeDeclaration || !o.declaration()) {
                out.add(location(s, o));
            }
        }
        return out;
    }

    private static Location location(Snapshot s, Outline.Occurrence o) {
        return new Location(s.uri(), range(s, s.outline().tokens().get(o.token())));
    }

    /**
     * The outline: each function block with its variables (their terms inside) and its rule blocks (their rules
     * inside), from the tokens, so that a text with errors has an outline too.
     */
    static List<DocumentSymbol> symbols(Snapshot s) {
        Outline o = s.outline();
        List<DocumentSymbol> blocks = new ArrayList<>();
        for (Outline.Span fb : o.spans()) {
            if (fb.kind() != Outline.Kind.FUNCTION_BLOCK) {
                continue;
            }
            DocumentSymbol block = symbol(s, fb.name().isEmpty() ? "(unnamed)" : fb.name(), SymbolKind.Module,
                    s.dialectNote(), fb.first(), fb.last(), nameToken(o, fb.first()));
            List<DocumentSymbol> children = new ArrayList<>();
            for (Outline.Occurrence v : o.occurrences()) {
                if (v.kind() == Outline.Kind.VARIABLE && v.declaration() && inside(v.token(), fb)) {
                    DocumentSymbol var = symbol(s, v.name(), SymbolKind.Variable, v.section().keyword(), v.token(),
                            v.token(), v.token());
                    List<DocumentSymbol> terms = new ArrayList<>();
                    for (Outline.Occurrence t : o.occurrences()) {
                        if (t.kind() == Outline.Kind.TERM && t.declaration() && inside(t.token(), fb)
                                && t.owner() != null && Names.same(t.owner(), v.name())) {
                            terms.add(symbol(s, t.name(), SymbolKind.EnumMember, "term", t.token(), t.token(), t.token()));
                        }
                    }
                    var.setChildren(terms);
                    children.add(var);
                }
            }
            for (Outline.Span rb : o.spans()) {
                if (rb.kind() == Outline.Kind.RULE_BLOCK && rb.first() >= fb.first() && rb.last() <= fb.last()) {
                    DocumentSymbol ruleBlock = symbol(s, rb.name(), SymbolKind.Namespace, "RULEBLOCK", rb.first(),
                            rb.last(), nameToken(o, rb.first()));
                    List<DocumentSymbol> rules = new ArrayList<>();
                    for (Outline.Span r : o.spans()) {
                        if (r.kind() == Outline.Kind.RULE && r.first() > rb.first() && r.last() < rb.last()) {
                            rules.add(symbol(s, "RULE " + r.name(), SymbolKind.Event, null, r.first(), r.last(),
                                    r.first()));
                        }
                    }
                    ruleBlock.setChildren(rules);
                    children.add(ruleBlock);
                }
            }
            block.setChildren(children);
            blocks.add(block);
        }
        return blocks;
    }

    private static boolean inside(int token, Outline.Span span) {
        return span.first() <= token && token <= span.last();
    }

    private static int nameToken(Outline o, int keyword) {
        return keyword + 1 < o.tokens().size() && o.tokens().get(keyword + 1).isName() ? keyword + 1 : keyword;
    }

    private static DocumentSymbol symbol(Snapshot s, String name, SymbolKind kind, String detail, int first, int last,
            int selection) {
        Range whole = new Range(range(s, s.outline().tokens().get(first)).getStart(),
                range(s, s.outline().tokens().get(last)).getEnd());
        return new DocumentSymbol(name, kind, whole, range(s, s.outline().tokens().get(selection)), detail);
    }
}
