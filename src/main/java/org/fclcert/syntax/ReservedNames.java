package org.fclcert.syntax;

import java.util.ArrayDeque;
import java.util.Deque;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * Reports keywords used as names. The grammar accepts the keywords that cannot be mistaken for
 * structure (MAX, RANGE, REAL, ...) where a name stands, so that this walk can say exactly which
 * keyword names what, while parsing goes on. The walk is iterative: trees can be very wide and deep.
 */
final class ReservedNames {
    private ReservedNames() {
    }

    static void check(ParseTree root, ReaderDiagnostics diagnostics) {
        Deque<ParseTree> stack = new ArrayDeque<>();
        stack.push(root);
        while (!stack.isEmpty()) {
            ParseTree node = stack.pop();
            if (node instanceof FclParser.NameContext name) {
                // only a keyword the grammar took as a name; a token error recovery put here is reported already
                Token token = name.getStart();
                if (name.softKeyword() != null && token != null) {
                    diagnostics.error(token, SyntaxCode.RESERVED_KEYWORD,
                            Keywords.reservedMessage(token, Keywords.role(name)));
                }
                continue;
            }
            for (int i = node.getChildCount() - 1; i >= 0; i--) {
                stack.push(node.getChild(i));
            }
        }
    }
}
