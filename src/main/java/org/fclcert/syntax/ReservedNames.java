package org.fclcert.syntax;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.antlr.v4.runtime.Token;

/**
 * Finds keywords used as names while the parser runs. The grammar accepts the keywords that cannot
 * be mistaken for structure (MAX, RANGE, REAL, ...) where a name stands, so that this can say exactly
 * which keyword names what, while parsing goes on. The parser hands over each such name as it parses it
 * ({@code FclParser.keywordName}), which costs far less than walking a tree of millions of nodes afterwards.
 */
final class ReservedNames implements Consumer<FclParser.NameContext> {
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
    public void accept(FclParser.NameContext name) {
        keywordNames.add(name);
    }
}
