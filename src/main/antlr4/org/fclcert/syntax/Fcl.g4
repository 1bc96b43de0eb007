/*
 * The strict FCL grammar: IEC 61131-7 5.4 production rules plus the IEC 61131-3 pieces they rely on
 * (identifiers, numeric literals, comments, variable declarations).
 *
 * The grammar is deliberately a little more permissive than the standard in a few ways, so that the
 * reader can give precise messages instead of generic parse errors (the reader reports them all):
 *  - names may be spelled like some keywords (MAX, RANGE, REAL, ...); using a keyword as a name is
 *    then reported as "reserved keyword" while parsing continues;
 *  - a DEFUZZIFY block may end with END_FUZZIFY (the 1996 draft's spelling), OPTIONS may be spelled
 *    OPTION / END_OPTION (5.4's spelling), RANGE may have ':=' (5.2.3's prose), a rule may be named by
 *    an identifier (5.2.4's prose): an error or a warning says which;
 *  - function block items, DEFUZZIFY items and RULEBLOCK items may come in any order; the builder
 *    reports any order other than the one 5.4 fixes (or the draft's DEFUZZIFY order, with a warning);
 *  - algorithm, method and type names are any word; the builder names the allowed ones (Tables 1-5).
 * The lexer never fails: malformed identifiers and numbers get their own token types, which the
 * reader's token pre-scan reports and then turns into ordinary tokens so that parsing goes on.
 */
grammar Fcl;

options { caseInsensitive = true; contextSuperClass = FclRuleContext; }

@parser::members {
    /**
     * When set, receives each rule as soon as it is parsed, so that the reader can build its model
     * and drop its subtree at once: a 100 000-rule block then never holds all rule trees in memory.
     */
    java.util.function.Consumer<FuzzyRuleContext> ruleParsed;
    /** Likewise each function-block item and variable declaration ('@after': not run when the rule throws). */
    java.util.function.Consumer<FbItemContext> itemParsed;
    java.util.function.Consumer<VarDeclarationContext> declarationParsed;
    /**
     * When set, receives each name spelled as a keyword. Actions on just these rules cost far less than
     * a parse listener, which the parser calls on entering and leaving every rule.
     */
    java.util.function.Consumer<NameContext> keywordName;
}

program
    : functionBlock* EOF
    ;

functionBlock
    : FUNCTION_BLOCK name fbItem* END_FUNCTION_BLOCK
    ;

fbItem
@after { if (itemParsed != null) itemParsed.accept($ctx); }
    : varSection
    | fuzzifyBlock
    | defuzzifyBlock
    | ruleBlock
    | optionBlock
    ;

// ---- IEC 61131-3 variable declarations (5.2.1) ----

varSection
    : kind=(VAR_INPUT | VAR_OUTPUT | VAR) varDeclaration* END_VAR
    ;

varDeclaration
@after { if (declarationParsed != null) declarationParsed.accept($ctx); }
    : name (COMMA name)* COLON typeName (ASSIGN literal)? SEMI
    ;

typeName
    : word
    ;

// ---- FUZZIFY (5.2.2) ----

fuzzifyBlock
    : FUZZIFY name linguisticTerm* END_FUZZIFY
    ;

linguisticTerm
    : TERM name ASSIGN membershipFunction SEMI
    ;

membershipFunction
    : point (COMMA? point)*      # pointsFunction
    | operand                    # singletonFunction
    ;

point
    : LPAREN x=operand COMMA y=operand RPAREN
    ;

operand
    : literal
    | name
    ;

// ---- DEFUZZIFY (5.2.3) ----

defuzzifyBlock
    : DEFUZZIFY name defuzzifyItem* end=(END_DEFUZZIFY | END_FUZZIFY)
    ;

defuzzifyItem
    : range
    | linguisticTerm
    | defuzzificationMethod
    | defaultValue
    ;

range
    : RANGE ASSIGN? LPAREN min=literal DOTDOT max=literal RPAREN SEMI
    ;

defuzzificationMethod
    : METHOD COLON word SEMI
    ;

defaultValue
    : DEFAULT ASSIGN (literal | NC) SEMI
    ;

// ---- RULEBLOCK (5.2.4) ----

ruleBlock
    : RULEBLOCK name ruleBlockItem* END_RULEBLOCK
    ;

ruleBlockItem
    : operatorDefinition
    | activationMethod
    | accumulationMethod
    | fuzzyRule
    ;

operatorDefinition
    : op=(AND | OR) COLON word SEMI
    ;

activationMethod
    : ACT COLON word SEMI
    ;

accumulationMethod
    : ACCU COLON word SEMI
    ;

// 'built' holds the rule's model when the reader built it during the parse (see ruleParsed).
fuzzyRule
    locals [org.fclcert.model.Rule built]
    : RULE ruleName COLON IF condition THEN conclusion SEMI { if (ruleParsed != null) ruleParsed.accept($ctx); }
    ;

ruleName
    : INTEGER
    | name
    ;

// Table 6: parentheses bind tighter than NOT, NOT tighter than AND, AND tighter than OR.
condition
    : conjunction (OR conjunction)*
    ;

conjunction
    : factor (AND factor)*
    ;

// 5.4: x ::= ['NOT'] (subcondition | '(' condition ')'), so NOT NOT is not FCL.
factor
    : negation=NOT? (subcondition | LPAREN condition RPAREN)
    ;

subcondition
    : variable=name (IS negation=NOT? term=name)?
    ;

conclusion
    : subconclusion (COMMA subconclusion)*
    ;

subconclusion
    : variable=name (IS term=name)? (with=WITH weight=operand)?
    ;

// ---- OPTIONS (5.2.5); the content is kept verbatim from the source text ----

optionBlock
    : start=(OPTIONS | OPTION) ~(END_OPTIONS | END_OPTION | END_FUNCTION_BLOCK)* end=(END_OPTIONS | END_OPTION)
    ;

// ---- names, words and literals ----

// A name is an identifier; keywords are accepted here only to be reported precisely.
name
    : IDENT
    | softKeyword { if (keywordName != null) keywordName.accept($ctx); }
    ;

// A word is an identifier or keyword where a keyword is expected (types, algorithms, methods).
word
    : IDENT
    | softKeyword
    ;

softKeyword
    : RANGE | METHOD | DEFAULT | NC | ACT | ACCU
    | COG | COGS | COA | LM | RM
    | MIN | MAX | PROD | ASUM | BSUM | BDIF | NSUM
    | REAL | LREAL | SINT | INT | DINT | LINT | USINT | UINT | UDINT | ULINT
    ;

literal
    : INTEGER
    | BASED_INTEGER
    | REAL_LITERAL
    ;

// ---------------------------------------------------------------- lexer

FUNCTION_BLOCK     : 'FUNCTION_BLOCK';
END_FUNCTION_BLOCK : 'END_FUNCTION_BLOCK';
VAR_INPUT          : 'VAR_INPUT';
VAR_OUTPUT         : 'VAR_OUTPUT';
VAR                : 'VAR';
END_VAR            : 'END_VAR';
FUZZIFY            : 'FUZZIFY';
END_FUZZIFY        : 'END_FUZZIFY';
DEFUZZIFY          : 'DEFUZZIFY';
END_DEFUZZIFY      : 'END_DEFUZZIFY';
RULEBLOCK          : 'RULEBLOCK';
END_RULEBLOCK      : 'END_RULEBLOCK';
OPTIONS            : 'OPTIONS';
END_OPTIONS        : 'END_OPTIONS';
OPTION             : 'OPTION';
END_OPTION         : 'END_OPTION';
TERM               : 'TERM';
RANGE              : 'RANGE';
METHOD             : 'METHOD';
DEFAULT            : 'DEFAULT';
NC                 : 'NC';
COG                : 'CoG';
COGS               : 'CoGS';
COA                : 'CoA';
LM                 : 'LM';
RM                 : 'RM';
AND                : 'AND';
OR                 : 'OR';
NOT                : 'NOT';
ACT                : 'ACT';
ACCU               : 'ACCU';
MIN                : 'MIN';
MAX                : 'MAX';
PROD               : 'PROD';
ASUM               : 'ASUM';
BSUM               : 'BSUM';
BDIF               : 'BDIF';
NSUM               : 'NSUM';
RULE               : 'RULE';
IF                 : 'IF';
THEN               : 'THEN';
IS                 : 'IS';
WITH               : 'WITH';
REAL               : 'REAL';
LREAL              : 'LREAL';
SINT               : 'SINT';
INT                : 'INT';
DINT               : 'DINT';
LINT               : 'LINT';
USINT              : 'USINT';
UINT               : 'UINT';
UDINT              : 'UDINT';
ULINT              : 'ULINT';

ASSIGN : ':=';
COLON  : ':';
SEMI   : ';';
COMMA  : ',';
LPAREN : '(';
RPAREN : ')';
DOTDOT : '..';
// '=' is not FCL; it is lexed so that Annex D's 'color = brown' gets a precise message.
EQUALS : '=';

// IEC 61131-3 B.1.2 numbers. Digit groups are lexed loosely ([0-9_]) and checked by the reader,
// which then gives a precise message for '1__0' or '1_'.
REAL_LITERAL  : [+-]? DIGITS '.' DIGITS EXPONENT? ;
BASED_INTEGER : [+-]? [0-9]+ '#' [0-9a-z_]+ ;
INTEGER       : [+-]? DIGITS ;
// Malformed reals, reported by the reader: '.5' and '1E5'. ('5.' lexes as 5 and a stray '.', which
// the reader joins again; a lexer predicate here would keep ANTLR from caching the number DFA.)
BAD_REAL
    : [+-]? '.' DIGITS EXPONENT?
    | [+-]? DIGITS EXPONENT
    ;

fragment DIGITS   : [0-9] [0-9_]* ;
fragment EXPONENT : 'E' [+-]? DIGITS ;

// IEC 61131-3 B.1.1: letters, digits and single underscores, a leading underscore allowed. Anything
// else made of these characters ('a__b', 'speed_', '_') is a BAD_IDENT, which the reader explains.
IDENT     : ([a-z] | '_' [a-z0-9]) ('_'? [a-z0-9])* ;
BAD_IDENT : [a-z_] [a-z0-9_]* ;

// Comments do not nest (IEC 61131-3): the first '*)' ends the comment. An unterminated comment
// runs to the end of the text and is reported by the reader.
COMMENT : '(*' .*? ('*)' | EOF) -> channel(HIDDEN) ;
WS      : [ \t\r\n\f\u000B]+ -> skip ;

// Anything else; the reader reports it as an unexpected character.
ANY : . ;
