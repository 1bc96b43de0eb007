package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.tree.ErrorNode;
import org.antlr.v4.runtime.tree.ParseTreeListener;
import org.antlr.v4.runtime.tree.TerminalNode;

/**
 * Finds keywords used as names while the parser runs. The grammar accepts the keywords that cannot
 * be mistaken for structure (MAX, RANGE, REAL, ...) where a name stands, so that this can say exactly
 * which keyword names what, while parsing goes on. Listening during the parse costs far less than
 * walking a tree of millions of nodes afterwards.
 */
final class ReservedNames implements ParseTreeListener {
    private final List<FclParser.NameContext> keywordNames = new ArrayList<>();

    /** Forgets what an abandoned parse attempt found (the SLL attempt before the LL one). */
    void reset() {
        keywordNames.clear();
    }

    void report(ReaderDiagnostics diagnostics) {
        for (FclParser.NameContext name : keywordNames) {
            Token token = name.getStart();
            diagnostics.error(token, SyntaxCode.RESERVED_KEYWORD, Keywords.reservedMessage(token, Keywords.role(name)));
        }
    }

    @Override
    public void exitEveryRule(ParserRuleContext ctx) {
        // only a keyword the grammar took as a name; a token error recovery put here is reported already
        if (ctx instanceof FclParser.NameContext name && name.softKeyword() != null && name.getStart() != null) {
            keywordNames.add(name);
        }
    }

    @Override
    public void enterEveryRule(ParserRuleContext ctx) {
    }

    @Override
    public void visitTerminal(TerminalNode node) {
    }

    @Override
    public void visitErrorNode(ErrorNode node) {
    }
}
