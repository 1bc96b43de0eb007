package org.fclcert.syntax;

import java.math.BigInteger;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.misc.Interval;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.ActivationMethod;
import org.fclcert.model.AndAlgorithm;
import org.fclcert.model.Condition;
import org.fclcert.model.DataType;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.Defuzzification;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Fuzzification;
import org.fclcert.model.Literal;
import org.fclcert.model.Located;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.Operand;
import org.fclcert.model.OptionsBlock;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.model.Point;
import org.fclcert.model.Program;
import org.fclcert.model.Range;
import org.fclcert.model.Rule;
import org.fclcert.model.RuleBlock;
import org.fclcert.model.SourceLocation;
import org.fclcert.model.Subconclusion;
import org.fclcert.model.Term;
import org.fclcert.model.Variable;
import org.fclcert.model.VariableKind;
import org.fclcert.model.VariableRef;
import org.fclcert.syntax.FclParser.*;

/**
 * Turns a parse tree without syntax errors into the immutable model, once. Besides building, it
 * reports what the grammar deliberately lets through so that it can be named precisely: the order of
 * a function block's parts, of DEFUZZIFY and RULEBLOCK items, duplicated settings, unknown
 * algorithm, method and type names, and the warnings about the standard's inconsistencies.
 * Long AND/OR chains are lists in the tree and are built iteratively.
 */
final class ModelBuilder {
    private final String sourceName;
    private final ReaderDiagnostics diagnostics;
    private final ReaderOptions options;

    ModelBuilder(String sourceName, ReaderDiagnostics diagnostics) {
        this(sourceName, diagnostics, ReaderOptions.STRICT);
    }

    ModelBuilder(String sourceName, ReaderDiagnostics diagnostics, ReaderOptions options) {
        this.sourceName = sourceName;
        this.diagnostics = diagnostics;
        this.options = options;
    }

    Program program(ProgramContext ctx) {
        List<FunctionBlock> blocks = new ArrayList<>();
        for (FunctionBlockContext fb : ctx.functionBlock()) {
            blocks.add(functionBlock(fb));
        }
        if (blocks.isEmpty()) {
            diagnostics.error(diagnostics.at(1, 1), SyntaxCode.EMPTY_PROGRAM,
                    "the text holds no FUNCTION_BLOCK: an FCL program is one or more function blocks (5.4)");
        }
        return new Program(sourceName, blocks);
    }

    // ---------------------------------------------------------------- function block

    /**
     * One item of a function block, built: its place in 5.4's order, how a message names it, where it starts,
     * and its model (the variables of a VAR section, a Fuzzification, Defuzzification, RuleBlock or
     * OptionsBlock).
     */
    private record Item(int rank, String what, Token start, Object model) {
    }

    /** Items the fast parse completed, built at once ({@link #buildItemEarly}); the rest are built at the end. */
    private final Map<FbItemContext, Item> earlyItems = new IdentityHashMap<>();
    /** Declarations the fast parse completed, built at once ({@link #buildDeclarationEarly}). */
    private final Map<VarDeclarationContext, List<Variable>> earlyDeclarations = new IdentityHashMap<>();

    /**
     * Builds a function block item as soon as a parse has completed it whole ({@link #buildWhile}), and drops
     * its subtree: a program of 100 000 FUZZIFY blocks never holds their trees all at once.
     */
    private void buildItemEarly(FbItemContext ctx) {
        earlyItems.put(ctx, item(ctx));
        // the item keeps its one child, without the child's subtree: a message about what follows names it
        ((ParserRuleContext) ctx.getChild(0)).children = null;
    }

    /** Likewise one variable declaration, so that a VAR section of 100 000 declarations keeps no trees. */
    private void buildDeclarationEarly(VarDeclarationContext ctx) {
        earlyDeclarations.put(ctx, declaration(ctx, kind((VarSectionContext) ctx.getParent())));
        ctx.children = null;
    }

    /**
     * Has the parser hand each rule, function block item and declaration it completes to this builder, which
     * builds it at once and drops its subtree, as long as {@code whole} says the parse has not had to
     * recover from an error (until then every part it completes is whole). Once it has recovered, the tree is
     * never built ({@code whole} does not turn true again, and the reader then builds the repaired text's program,
     * not this tree): each part is only dropped as it completes, the very subtrees dropped above, so that the rest
     * of a large program after a mistake is not held as a tree for nothing. The error messages still see each
     * dropped part as such ({@code SyntaxMessages.describeElement}).
     */
    void buildWhile(FclParser parser, java.util.function.BooleanSupplier whole) {
        parser.ruleParsed = ctx -> {
            if (whole.getAsBoolean()) {
                buildEarly(ctx);
            } else {
                ctx.children = null;
            }
        };
        parser.itemParsed = ctx -> {
            if (whole.getAsBoolean()) {
                buildItemEarly(ctx);
            } else if (ctx.children != null) {
                // after a recovery an item may hold error nodes beside its block: drop every block's subtree
                for (org.antlr.v4.runtime.tree.ParseTree child : ctx.children) {
                    if (child instanceof ParserRuleContext block) {
                        block.children = null;
                    }
                }
            }
        };
        parser.declarationParsed = ctx -> {
            if (whole.getAsBoolean()) {
                buildDeclarationEarly(ctx);
            } else {
                ctx.children = null;
            }
        };
    }

    /** Drops what an abandoned parse built early (a large program's models, else held for nothing). */
    void forgetEarly() {
        earlyItems.clear();
        earlyDeclarations.clear();
    }

    private Item item(FbItemContext item) {
        Object model;
        if (item.varSection() != null) {
            model = varSection(item.varSection());
        } else if (item.fuzzifyBlock() != null) {
            model = fuzzification(item.fuzzifyBlock());
        } else if (item.defuzzifyBlock() != null) {
            model = defuzzification(item.defuzzifyBlock());
        } else if (item.ruleBlock() != null) {
            model = ruleBlock(item.ruleBlock());
        } else {
            model = options(item.optionBlock());
        }
        return new Item(bodyRank(item), describeItem(item), item.start, model);
    }

    @SuppressWarnings("unchecked")
    private FunctionBlock functionBlock(FunctionBlockContext ctx) {
        List<Item> items = new ArrayList<>();
        for (FbItemContext item : ctx.fbItem()) {
            Item built = earlyItems.remove(item);
            items.add(built != null ? built : item(item));
        }
        checkBodyOrder(items);
        List<Variable> variables = new ArrayList<>();
        List<Fuzzification> fuzzifications = new ArrayList<>();
        List<Defuzzification> defuzzifications = new ArrayList<>();
        List<RuleBlock> ruleBlocks = new ArrayList<>();
        List<OptionsBlock> options = new ArrayList<>();
        for (Item item : items) {
            if (item.model() instanceof List<?> declared) {
                variables.addAll((List<Variable>) declared);
            } else if (item.model() instanceof Fuzzification f) {
                fuzzifications.add(f);
            } else if (item.model() instanceof Defuzzification d) {
                defuzzifications.add(d);
            } else if (item.model() instanceof RuleBlock rb) {
                ruleBlocks.add(rb);
            } else if (item.model() instanceof OptionsBlock o) {
                options.add(o);
            }
        }
        return new FunctionBlock(name(ctx.name()), variables, fuzzifications, defuzzifications, ruleBlocks,
                options, at(ctx.start));
    }

    private static final String BODY_ORDER = "a function block declares its VAR_INPUT and VAR_OUTPUT sections,"
            + " then VAR, then its FUZZIFY blocks, DEFUZZIFY blocks, RULEBLOCKs and OPTIONS, in this order (5.4)";

    private void checkBodyOrder(List<Item> items) {
        int highest = 0;
        String highestWhat = null;
        for (Item item : items) {
            if (item.rank() < highest) {
                diagnostics.error(item.start(), SyntaxCode.BODY_ORDER, item.what() + " after " + highestWhat + ": "
                        + BODY_ORDER);
                return;
            }
            highest = item.rank();
            highestWhat = "a " + item.what();
        }
    }

    private static int bodyRank(FbItemContext item) {
        if (item.varSection() != null) {
            return item.varSection().kind.getType() == FclLexer.VAR ? 1 : 0;
        }
        if (item.fuzzifyBlock() != null) {
            return 2;
        }
        if (item.defuzzifyBlock() != null) {
            return 3;
        }
        return item.ruleBlock() != null ? 4 : 5;
    }

    private static String describeItem(FbItemContext item) {
        String keyword = item.start.getText().toUpperCase(Locale.ROOT);
        return item.varSection() != null ? keyword + " section" : keyword + " block";
    }

    // ---------------------------------------------------------------- variables

    private List<Variable> varSection(VarSectionContext ctx) {
        VariableKind kind = kind(ctx);
        List<Variable> variables = new ArrayList<>();
        for (VarDeclarationContext decl : ctx.varDeclaration()) {
            List<Variable> built = earlyDeclarations.remove(decl);
            variables.addAll(built != null ? built : declaration(decl, kind));
        }
        return variables;
    }

    private static VariableKind kind(VarSectionContext ctx) {
        return switch (ctx.kind.getType()) {
            case FclLexer.VAR_INPUT -> VariableKind.INPUT;
            case FclLexer.VAR_OUTPUT -> VariableKind.OUTPUT;
            default -> VariableKind.LOCAL;
        };
    }

    private List<Variable> declaration(VarDeclarationContext decl, VariableKind kind) {
        DataType type = dataType(decl.typeName());
        Optional<Literal> initial = decl.literal() == null ? Optional.empty() : Optional.of(literal(decl.literal()));
        List<NameContext> names = decl.name();
        List<Variable> variables = new ArrayList<>(names.size());
        for (NameContext n : names) {
            variables.add(new Variable(name(n), kind, type, initial, at(n.start)));
        }
        return variables;
    }

    private DataType dataType(TypeNameContext ctx) {
        Optional<DataType> type = DataType.byKeyword(ctx.getText());
        if (type.isEmpty()) {
            diagnostics.error(ctx.start, SyntaxCode.NOT_ELEMENTARY_TYPE, "'" + ctx.getText()
                    + "' is not an elementary numeric data type: an FCL variable is REAL, LREAL, SINT, INT, DINT,"
                    + " LINT, USINT, UINT, UDINT or ULINT (5.2.1, IEC 61131-3)");
            return DataType.REAL;
        }
        return type.get();
    }

    // ---------------------------------------------------------------- fuzzification

    private Fuzzification fuzzification(FuzzifyBlockContext ctx) {
        List<Term> terms = new ArrayList<>();
        for (LinguisticTermContext t : ctx.linguisticTerm()) {
            terms.add(term(t));
        }
        return new Fuzzification(name(ctx.name()), terms, at(ctx.start));
    }

    private Term term(LinguisticTermContext ctx) {
        MembershipFunction function;
        if (ctx.membershipFunction() instanceof PointsFunctionContext points) {
            List<Point> list = new ArrayList<>();
            for (PointContext p : points.point()) {
                list.add(new Point(operand(p.x), operand(p.y), at(p.start)));
            }
            function = new MembershipFunction.Points(list);
        } else {
            function = new MembershipFunction.Singleton(operand(((SingletonFunctionContext) ctx.membershipFunction()).operand()));
        }
        return new Term(name(ctx.name()), function, at(ctx.start));
    }

    // ---------------------------------------------------------------- defuzzification

    private Defuzzification defuzzification(DefuzzifyBlockContext ctx) {
        if (ctx.end.getType() == FclLexer.END_FUZZIFY && !options.endFuzzifyClosesDefuzzify()) {
            diagnostics.error(ctx.end, SyntaxCode.WRONG_END_KEYWORD, "a DEFUZZIFY block is closed by END_DEFUZZIFY,"
                    + " not END_FUZZIFY (the 1996 draft's spelling) (5.2.3)");
        }
        checkDefuzzifyOrder(ctx);
        Optional<Range> range = Optional.empty();
        List<Term> terms = new ArrayList<>();
        Optional<Located<DefuzzificationMethod>> method = Optional.empty();
        Optional<DefaultValue> defaultValue = Optional.empty();
        for (DefuzzifyItemContext item : ctx.defuzzifyItem()) {
            if (item.linguisticTerm() != null) {
                terms.add(term(item.linguisticTerm()));
            } else if (item.range() != null) {
                range = once(range, item.range(), "RANGE", this::range);
            } else if (item.defuzzificationMethod() != null) {
                method = once(method, item.defuzzificationMethod(), "METHOD", this::method);
            } else if (item.defaultValue() != null) {
                defaultValue = once(defaultValue, item.defaultValue(), "DEFAULT", this::defaultValue);
            }
        }
        return new Defuzzification(name(ctx.name()), range, terms, method, defaultValue, at(ctx.start));
    }

    /** Builds a setting the first time; a second one is an error naming where the first was. */
    private <C extends ParserRuleContext, T> Optional<T> once(Optional<T> previous, C ctx, String what,
            Function<C, Optional<T>> build) {
        if (previous.isPresent()) {
            diagnostics.error(ctx.start, SyntaxCode.DUPLICATE_SETTING, "a second " + what + " in this block:"
                    + " each block gives " + what + " at most once");
            return previous;
        }
        return build.apply(ctx);
    }

    private static final String DEFUZZIFY_ORDER = "a DEFUZZIFY block gives RANGE, then its TERMs, then METHOD,"
            + " then DEFAULT (5.4)";

    private void checkDefuzzifyOrder(DefuzzifyBlockContext ctx) {
        List<DefuzzifyItemContext> items = ctx.defuzzifyItem();
        int firstOutOfOrder = firstOutOfOrder(items);
        if (firstOutOfOrder < 0) {
            return;
        }
        DefuzzifyItemContext last = items.get(items.size() - 1);
        boolean rangeLastOnly = last.range() != null && firstOutOfOrder(items.subList(0, items.size() - 1)) < 0
                && items.stream().filter(i -> i.range() != null).count() == 1;
        if (rangeLastOnly) {
            rangeLast(last.start, diagnostics, options);
            return;
        }
        DefuzzifyItemContext item = items.get(firstOutOfOrder);
        DefuzzifyItemContext before = items.stream().limit(firstOutOfOrder)
                .max(java.util.Comparator.comparingInt(ModelBuilder::defuzzifyRank)).orElseThrow();
        diagnostics.error(item.start, SyntaxCode.DEFUZZIFY_BLOCK, keyword(item) + " after " + keyword(before) + ": "
                + DEFUZZIFY_ORDER);
    }

    /** The one RANGE of a DEFUZZIFY block, after all its other items (the draft's order): a warning. */
    static void rangeLast(Token range, ReaderDiagnostics diagnostics, ReaderOptions options) {
        if (!options.draftFormsAccepted()) {
            diagnostics.warning(range, SyntaxCode.DRAFT_DEFUZZIFY_ORDER, "RANGE after the other DEFUZZIFY items"
                    + " follows the 1996 draft; accepted, but " + DEFUZZIFY_ORDER);
        }
    }

    private static String keyword(ParserRuleContext item) {
        return item.start.getText().toUpperCase(Locale.ROOT);
    }

    private static int firstOutOfOrder(List<DefuzzifyItemContext> items) {
        int highest = 0;
        for (int i = 0; i < items.size(); i++) {
            int rank = defuzzifyRank(items.get(i));
            if (rank < highest) {
                return i;
            }
            highest = rank;
        }
        return -1;
    }

    private static int defuzzifyRank(DefuzzifyItemContext item) {
        if (item.range() != null) {
            return 0;
        }
        if (item.linguisticTerm() != null) {
            return 1;
        }
        return item.defuzzificationMethod() != null ? 2 : 3;
    }

    private Optional<Range> range(RangeContext ctx) {
        if (ctx.ASSIGN() != null) {
            rangeAssignment(ctx.ASSIGN().getSymbol(), diagnostics, options);
        }
        return Optional.of(new Range(literal(ctx.min), literal(ctx.max), at(ctx.start)));
    }

    /** {@code RANGE := (...)}: a warning that this is 5.2.3's prose form, not 5.4's. */
    static void rangeAssignment(Token assign, ReaderDiagnostics diagnostics, ReaderOptions options) {
        if (!options.draftFormsAccepted()) {
            diagnostics.warning(assign, SyntaxCode.RANGE_ASSIGNMENT, "'RANGE := (...)' is the form"
                    + " of 5.2.3's prose; the 5.4 production writes 'RANGE (min .. max);' without ':='");
        }
    }

    private Optional<Located<DefuzzificationMethod>> method(DefuzzificationMethodContext ctx) {
        Optional<DefuzzificationMethod> m = method(ctx.word().getText(), options);
        if (m.isEmpty()) {
            diagnostics.error(ctx.word().start, SyntaxCode.METHOD, "'" + ctx.word().getText()
                    + "' is not a defuzzification method: METHOD takes CoG, CoGS, CoA, LM or RM (5.2.3, Table 1)");
        }
        return m.map(v -> new Located<>(v, at(ctx.start)));
    }

    /** The defuzzification method a METHOD word names: Table 1's, or one of the options' non-standard ones. */
    static Optional<DefuzzificationMethod> method(String word, ReaderOptions options) {
        Optional<DefuzzificationMethod> m = DefuzzificationMethod.byKeyword(word);
        return m.isPresent() ? m
                : options.nonStandardMethods().stream().filter(x -> x.keyword().equalsIgnoreCase(word)).findFirst();
    }

    private Optional<DefaultValue> defaultValue(DefaultValueContext ctx) {
        if (ctx.NC() != null) {
            return Optional.of(new DefaultValue.NoChange(at(ctx.start)));
        }
        return Optional.of(new DefaultValue.Constant(literal(ctx.literal()), at(ctx.start)));
    }

    // ---------------------------------------------------------------- rule blocks

    private RuleBlock ruleBlock(RuleBlockContext ctx) {
        checkRuleBlockOrder(ctx);
        Optional<Located<AndAlgorithm>> and = Optional.empty();
        Optional<Located<OrAlgorithm>> or = Optional.empty();
        Optional<Located<ActivationMethod>> act = Optional.empty();
        Optional<Located<AccumulationMethod>> accu = Optional.empty();
        List<Rule> rules = new ArrayList<>();
        for (RuleBlockItemContext item : ctx.ruleBlockItem()) {
            if (item.fuzzyRule() != null) {
                FuzzyRuleContext r = item.fuzzyRule();
                rules.add(r.built != null ? r.built : rule(r));
            } else if (item.operatorDefinition() != null && item.operatorDefinition().op.getType() == FclLexer.AND) {
                and = once(and, item.operatorDefinition(), "AND",
                        c -> algorithm(c, AndAlgorithm.class, SyntaxCode.OPERATOR_DEFINITION,
                                "an AND algorithm: AND takes MIN, PROD or BDIF (5.2.4, Table 3)"));
            } else if (item.operatorDefinition() != null) {
                or = once(or, item.operatorDefinition(), "OR",
                        c -> algorithm(c, OrAlgorithm.class, SyntaxCode.OPERATOR_DEFINITION,
                                "an OR algorithm: OR takes MAX, ASUM or BSUM (5.2.4, Table 3)"));
            } else if (item.activationMethod() != null) {
                act = once(act, item.activationMethod(), "ACT",
                        c -> algorithm(c, ActivationMethod.class, SyntaxCode.ACTIVATION,
                                "an activation method: ACT takes MIN or PROD (5.2.4, Table 4)"));
            } else if (item.accumulationMethod() != null) {
                accu = once(accu, item.accumulationMethod(), "ACCU",
                        c -> algorithm(c, AccumulationMethod.class, SyntaxCode.ACCUMULATION,
                                "an accumulation method: ACCU takes MAX, BSUM or NSUM (5.2.4, Table 5)"));
            }
        }
        return new RuleBlock(name(ctx.name()), and, or, act, accu, rules, at(ctx.start));
    }

    private <E extends Enum<E>> Optional<Located<E>> algorithm(ParserRuleContext ctx, Class<E> type, SyntaxCode code,
            String allowed) {
        WordContext word = ctx.getRuleContext(WordContext.class, 0);
        Optional<E> value = standardAlgorithm(type, word.getText());
        if (value.isPresent()) {
            return Optional.of(new Located<>(value.get(), at(ctx.start)));
        }
        diagnostics.error(word.start, code, "'" + word.getText() + "' is not " + allowed);
        return Optional.empty();
    }

    /** The standard's algorithm or method of this kind (Tables 3 to 5) that the word names, in any case. */
    static <E extends Enum<E>> Optional<E> standardAlgorithm(Class<E> type, String word) {
        String text = word.toUpperCase(Locale.ROOT);
        for (E value : type.getEnumConstants()) {
            boolean nonStandard = value instanceof AccumulationMethod a && !a.standard()   // PROBOR, SUM: dialect readers only
                    || value instanceof AndAlgorithm x && !x.standard() || value instanceof OrAlgorithm y && !y.standard()
                    || value instanceof ActivationMethod m && !m.standard();
            if (value.name().equals(text) && !nonStandard) {
                return Optional.of(value);
            }
        }
        return Optional.empty();
    }

    private static final String RULE_BLOCK_ORDER = "a rule block gives its AND:/OR: definitions, then ACT:, then ACCU:,"
            + " then its rules (5.4)";

    private void checkRuleBlockOrder(RuleBlockContext ctx) {
        int highest = 0;
        RuleBlockItemContext highestItem = null;
        for (RuleBlockItemContext item : ctx.ruleBlockItem()) {
            int rank = item.operatorDefinition() != null ? 0
                    : item.activationMethod() != null ? 1 : item.accumulationMethod() != null ? 2 : 3;
            if (rank < highest) {
                String before = highestItem.fuzzyRule() != null ? "a rule" : "'" + keyword(highestItem) + ":'";
                diagnostics.error(item.start, SyntaxCode.RULE_BLOCK, "'" + keyword(item) + ":' after " + before + ": "
                        + RULE_BLOCK_ORDER);
                return;
            }
            if (rank > highest || highestItem == null) {
                highest = rank;
                highestItem = item;
            }
        }
    }

    /**
     * Builds a rule while the parse is still running, then drops the rule's subtree (keeping the
     * context itself, which still knows its first token). Only for a rule a parse completed whole
     * ({@link #buildWhile}).
     */
    private void buildEarly(FuzzyRuleContext ctx) {
        ctx.built = rule(ctx);
        ctx.children = null;
    }

    /** Digits only, without a leading zero (unless the number is 0): the text BigInteger would give back. */
    static boolean plainNumber(String text) {
        if (text.isEmpty() || text.length() > 1 && text.charAt(0) == '0') {
            return false;
        }
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) < '0' || text.charAt(i) > '9') {
                return false;
            }
        }
        return true;
    }

    private Rule rule(FuzzyRuleContext ctx) {
        return new Rule(ruleName(ctx.ruleName()), condition(ctx.condition()), conclusion(ctx.conclusion()),
                at(ctx.start));
    }

    private String ruleName(RuleNameContext ctx) {
        if (ctx.INTEGER() != null) {
            String text = ctx.INTEGER().getText().replace("_", "");
            if (text.startsWith("+") || text.startsWith("-")) {
                diagnostics.error(ctx.start, SyntaxCode.RULE_HEADER, "a rule number has no sign: write 'RULE "
                        + text.substring(1) + ":' (5.4)");
                text = text.substring(1);
            }
            if (plainNumber(text)) {
                return text;    // already canonical: no BigInteger round trip for the usual rule number
            }
            try {
                return new BigInteger(text).toString();
            } catch (NumberFormatException e) {
                return text;  // malformed digits, already reported as FCL-S004
            }
        }
        diagnostics.warning(ctx.start, SyntaxCode.RULE_NAMED_BY_IDENTIFIER, "rule named '" + ctx.getText()
                + "': 5.2.4's prose allows a name, but the 5.4 production requires a rule number");
        return name(ctx.name());
    }

    // Table 6: OR of ANDs of factors; each level is a list in the tree, so no recursion per operand.
    private Condition condition(ConditionContext ctx) {
        List<ConjunctionContext> parts = ctx.conjunction();
        if (parts.size() == 1) {
            return conjunction(parts.get(0));
        }
        List<Condition> operands = new ArrayList<>(parts.size());
        for (ConjunctionContext c : parts) {
            operands.add(conjunction(c));
        }
        return new Condition.Or(operands, at(ctx.start));
    }

    private Condition conjunction(ConjunctionContext ctx) {
        List<FactorContext> parts = ctx.factor();
        if (parts.size() == 1) {
            return factor(parts.get(0));
        }
        List<Condition> operands = new ArrayList<>(parts.size());
        for (FactorContext f : parts) {
            operands.add(factor(f));
        }
        return new Condition.And(operands, at(ctx.start));
    }

    private Condition factor(FactorContext ctx) {
        Condition inner = ctx.subcondition() != null
                ? subcondition(ctx.subcondition())
                : new Condition.Parenthesized(condition(ctx.condition()), at(ctx.LPAREN().getSymbol()));
        return ctx.negation != null ? new Condition.Not(inner, at(ctx.start)) : inner;
    }

    private Condition subcondition(SubconditionContext ctx) {
        if (ctx.term == null) {
            return new Condition.VariableSubcondition(name(ctx.variable), at(ctx.start));
        }
        return new Condition.TermSubcondition(name(ctx.variable), name(ctx.term), ctx.negation != null, at(ctx.start));
    }

    private List<Subconclusion> conclusion(ConclusionContext ctx) {
        List<SubconclusionContext> parts = ctx.subconclusion();
        List<Subconclusion> result = new ArrayList<>(parts.size());
        for (SubconclusionContext s : parts) {
            result.add(subconclusion(s));
        }
        SubconclusionContext last = parts.get(parts.size() - 1);
        if (parts.size() > 1 && last.with != null) {
            withAfterLastSubconclusion(last.with, diagnostics);
        }
        return result;
    }

    /** WITH after the last of several subconclusions: a warning that 5.2.4 and 5.4 disagree on its reach. */
    static void withAfterLastSubconclusion(Token with, ReaderDiagnostics diagnostics) {
        diagnostics.warning(with, SyntaxCode.WITH_AFTER_LAST_SUBCONCLUSION, "WITH after the last"
                + " of several subconclusions: 5.2.4 makes it that subconclusion's weighting factor, 5.4 the"
                + " whole rule's; fclcert applies it to that subconclusion only");
    }

    private Subconclusion subconclusion(SubconclusionContext ctx) {
        Optional<String> term = ctx.term == null ? Optional.empty() : Optional.of(name(ctx.term));
        Optional<Operand> weight = ctx.weight == null ? Optional.empty() : Optional.of(operand(ctx.weight));
        return new Subconclusion(name(ctx.variable), term, weight, at(ctx.start));
    }

    // ---------------------------------------------------------------- options

    private OptionsBlock options(OptionBlockContext ctx) {
        if (ctx.start.getType() == FclLexer.OPTION && !options.draftFormsAccepted()) {
            diagnostics.warning(ctx.start, SyntaxCode.OPTION_SPELLING, "'OPTION' is how the 5.4 production spells it;"
                    + " 5.2.5 and Table 7 write OPTIONS ... END_OPTIONS");
        }
        if (ctx.end.getType() == FclLexer.END_OPTION && !options.draftFormsAccepted()) {
            diagnostics.warning(ctx.end, SyntaxCode.OPTION_SPELLING, "'END_OPTION' is how the 5.4 production spells"
                    + " it; 5.2.5 and Table 7 write END_OPTIONS");
        }
        int from = ctx.start.getStopIndex() + 1;
        int to = ctx.end.getStartIndex() - 1;
        String content = to < from ? "" : ctx.start.getInputStream().getText(Interval.of(from, to));
        return new OptionsBlock(content.strip(), at(ctx.start));
    }

    // ---------------------------------------------------------------- leaves

    private Operand operand(OperandContext ctx) {
        if (ctx.literal() != null) {
            return literal(ctx.literal());
        }
        return new VariableRef(name(ctx.name()), at(ctx.start));
    }

    private Literal literal(LiteralContext ctx) {
        return literal(ctx.start, at(ctx.start));
    }

    /** The literal a number token (INTEGER, BASED_INTEGER or REAL_LITERAL) writes, at the given place. */
    static Literal literal(Token t, SourceLocation at) {
        String text = t.getText();
        double value = NumberSyntax.value(t.getType(), text);
        return new Literal(value, NumberSyntax.integral(t.getType()), at,
                NumberSyntax.wideInteger(t.getType(), text, value));
    }

    private static String name(NameContext ctx) {
        return ctx.start.getText();
    }

    private SourceLocation at(Token token) {
        return diagnostics.at(token);
    }
}
