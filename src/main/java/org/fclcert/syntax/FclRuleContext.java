package org.fclcert.syntax;

import java.util.ArrayList;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * The parse tree's nodes (Fcl.g4's contextSuperClass): a node's list of children starts at room for four, not
 * ANTLR's ten, since most nodes of FCL's grammar have one to four (a name, a subcondition, a point); growing
 * those lists was the largest single cost of reading a program (about a sixth of the time, issue 17).
 */
public class FclRuleContext extends ParserRuleContext {
    public FclRuleContext() {
    }

    public FclRuleContext(ParserRuleContext parent, int invokingStateNumber) {
        super(parent, invokingStateNumber);
    }

    @Override
    public <T extends ParseTree> T addAnyChild(T t) {
        if (children == null) {
            children = new ArrayList<>(4);
        }
        children.add(t);
        return t;
    }
}
