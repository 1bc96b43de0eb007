package org.fclcert.syntax.dialect;

import java.util.List;
import java.util.Optional;
import org.fclcert.model.AccumulationMethod;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Hedge;
import org.fclcert.model.MembershipFunction;
import org.fclcert.model.OrAlgorithm;
import org.fclcert.syntax.dialect.DialectLexer.Token;
import org.fclcert.syntax.dialect.DialectReader.Giveaway;

/**
 * One library's FCL dialect, as a strategy of the shared reading core ({@link DialectParser},
 * {@link DialectRuleParser}): what it accepts beyond the common grammar, what its constructs mean, and
 * which constructs give it away ({@link #giveaways}). Adding a dialect of this family is one subclass,
 * its {@link ShapeNames} table and a line in {@link DialectReaders}.
 */
abstract class LibraryDialect {

    abstract Dialect dialect();

    /** The library's name in messages, e.g. {@code jFuzzyLogic}. */
    final String library() {
        return dialect().displayName();
    }

    abstract DialectLexer.Style lexing();

    abstract ShapeNames.Table shapes();

    // ---------------------------------------------------------------- what it accepts

    /** A block keyword as written; the default accepts any case. */
    void checkKeyword(DialectParser p, Token t, String word) {
    }

    /** A name as written (e.g. jFuzzyLogic rejects a leading '_'). */
    void checkName(DialectParser p, Token t) {
    }

    /** Whether {@code nan}, {@code inf}, {@code -inf} are numbers (in RANGE and DEFAULT). */
    boolean infinities() {
        return false;
    }

    /** Whether {@code RANGE := (lo .. hi);} may follow a declaration in VAR_INPUT / VAR_OUTPUT (jFuzzyLogic). */
    boolean rangeAfterDeclaration() {
        return false;
    }

    /** Whether a FUZZIFY block takes {@code RANGE := (lo .. hi);} (jFuzzyLogic's grammar does not). */
    boolean rangeInFuzzify() {
        return true;
    }

    /** A statement of a FUZZIFY block other than TERM and RANGE; false when the dialect has none there. */
    boolean fuzzifyStatement(DialectParser p, Token t) {
        return false;
    }

    /** A statement of a DEFUZZIFY block other than TERM, RANGE, METHOD and DEFAULT. */
    boolean defuzzifyStatement(DialectParser p, Token t, DialectParser.Output out) {
        return false;
    }

    /** A statement of a RULEBLOCK other than AND, OR, ACT, ACCU and RULE. */
    boolean ruleBlockStatement(DialectParser p, Token t) {
        return false;
    }

    /** The words the parser names when a DEFUZZIFY statement is not understood. */
    abstract String defuzzifyStatements();

    /** METHOD by its upper-case word, or empty when the dialect has no such method. */
    abstract Optional<DefuzzificationMethod> method(DialectParser p, Token word, String upper);

    abstract String methodNames();

    /** ACCU by its upper-case word, or empty. */
    abstract Optional<AccumulationMethod> accumulation(String upper);

    abstract String accumulationNames();

    /** An OR algorithm's name as the model spells it (jFuzzyLogic writes PROBOR for ASUM). */
    String orAlgorithm(String upper) {
        return upper;
    }

    /** An AND algorithm's name as the model spells it. */
    String andAlgorithm(String upper) {
        return upper;
    }

    /** Whether a point or a linear shape's parameter may be a variable's name (jFuzzyLogic, as the standard: 5.2.2). */
    boolean variablesAsPoints() {
        return false;
    }

    /** Which of several terms of one name the library uses: the first (fuzzylite), else the last (jFuzzyLogic). */
    boolean firstOfRepeatedTerms() {
        return true;
    }

    /** A variable's name written as a point or parameter ({@link #variablesAsPoints()}). */
    void pointVariable(DialectParser p, Token name) {
    }

    /** Whether ACT takes t-norms outside Table 4 (fuzzylite: BDIF, EPROD, HPROD, DPROD, NMIN). */
    boolean otherActivations() {
        return false;
    }

    /** The ACT algorithms the dialect names, for messages. */
    String activationNames() {
        return "MIN, PROD";
    }

    /** The AND and OR algorithms the dialect names, for messages. */
    abstract String andNames();

    abstract String orNames();

    /** A term of the dialect's own forms (named-shape words are read from {@link #shapes()}), or empty. */
    Optional<MembershipFunction> specialTerm(DialectParser p, Token word, DialectParser.TermContext where) {
        return Optional.empty();
    }

    /** Whether a TERM or RULE is read from one line (fuzzylite). */
    boolean oneLineStatements() {
        return false;
    }

    // ---------------------------------------------------------------- rules

    /** Whether rule keywords must be lower case (fuzzylite reads {@code if is and or then with}). */
    boolean lowerCaseRuleKeywords() {
        return false;
    }

    /** The rule keyword as this dialect's users write it, for messages. */
    String ruleKeyword(String word) {
        return lowerCaseRuleKeywords() ? word.toLowerCase(java.util.Locale.ROOT) : word;
    }

    /** Whether {@code NOT condition} is an operator (jFuzzyLogic); fuzzylite writes {@code not} as a hedge. */
    boolean notOperator() {
        return false;
    }

    /** A hedge word before a term, or empty. */
    abstract Optional<Hedge> hedge(Token t);

    /** The hedges before a conclusion's term, applied to the rule's degree (fuzzylite). */
    boolean hedgesInConclusions() {
        return false;
    }

    /** Whether the token joins two subconclusions ({@code ,} in jFuzzyLogic, {@code and} in fuzzylite). */
    abstract boolean conclusionSeparator(DialectParser p, Token t);

    /** Whether the library gives AND and OR one priority (jFuzzyLogic), which the reader warns about. */
    boolean oneAndOrPriority() {
        return false;
    }

    // ---------------------------------------------------------------- what it means

    /** Settings the library supplies at the end of a DEFUZZIFY block (e.g. jFuzzyLogic's METHOD CoG). */
    void finishOutput(DialectParser p, DialectParser.Output out) {
    }

    /** Settings and warnings at the end of a RULEBLOCK. */
    void finishRuleBlock(DialectParser p, DialectParser.Block block) {
    }

    /** The function block as the library means it, after all its blocks are read. */
    FunctionBlock finishFunctionBlock(DialectParser p, FunctionBlock fb) {
        return fb;
    }

    // ---------------------------------------------------------------- which giveaways identify it

    /**
     * The constructs in the text that only this library writes, each with its weight (how specific it is:
     * 3 for a construct no other dialect has, 1 for one shared with another library), never from inside a
     * comment. See {@link Giveaways}.
     */
    abstract List<Giveaway> giveaways(Giveaways.Scan scan);
}
