package org.fclcert.write;

import org.fclcert.model.Feature;

/** How the converted program writes each dialect construct, in a few words, for the findings of a conversion. */
final class DialectSyntaxText {
    private DialectSyntaxText() {
    }

    static String standardForm(Feature f) {
        return switch (f) {
            case O_FFLL_TERM_ONLY_CONDITION -> "written as 'variable IS term' with the input of its position";
            case O_FFLL_TERM_ONLY_CONCLUSION -> "written as 'variable IS term' with the output of its position";
            case O_FFLL_OUTPUT_FUZZIFY -> "the terms are written in the output's DEFUZZIFY block";
            case O_END_FUZZIFY -> "written as END_DEFUZZIFY";
            case O_ACCUM -> "written as ACCU";
            case O_RANGE_COMMENT -> "an output's range is written as its RANGE, an input's is left out (the standard"
                    + " has none; inputs outside it take the terms' outer degrees either way)";
            case O_FFLL_NO_DEFAULT -> "written as DEFAULT := 0";
            case O_FFLL_NO_METHOD -> "written as METHOD : CoG";
            case O_DECLARATION_WITHOUT_COLON -> "written with ':'";
            case O_SPACED_ASSIGN -> "written as ':='";
            case O_VAR_RETAIN -> "left out (it has no effect on evaluation)";
            case O_SHAPE_SINGLETONS -> "written as a singleton";
            case O_SHAPE_DISCRETE -> "written as its points";
            case O_METHOD_MM -> "the spelling MM is MoM (whose conversion is judged at METHOD)";
            case O_METHOD_COGF -> "written as CoG (what the reader takes COGF for)";
            case O_COMMENT_STYLE -> "left out (a comment carries no meaning)";
            case O_INPUT_RANGE -> "left out (an input's RANGE has no effect on evaluation; the standard has none)";
            case O_INFINITE_RANGE -> "left out (a RANGE with an infinite end is read as no RANGE)";
            case O_ACCU_IN_DEFUZZIFY -> "written as the ACCU of the rule blocks concluding the output";
            case O_IMPLICIT_SETTING -> "the setting the library supplies is written out";
            case O_ENABLED -> "left out (ENABLED : TRUE has no effect)";
            case O_LOCK_PREVIOUS -> "written as DEFAULT NC (how fclcert reads it; see FCL-W305)";
            case O_LOCK_RANGE -> "left out (fclcert's CoG, CoA, LM, RM and MoM on point and shape terms stay in the RANGE)";
            case O_RULE_WITHOUT_SEMICOLON -> "written with ';'";
            case O_CONCLUSION_AND -> "written with ',' between the subconclusions";
            case O_UNNAMED_BLOCK -> "written with the name the reader gave it";
            case O_BLOCK_NAME_VERBATIM -> "written as the identifier the reader made of it";
            case O_DECLARATION_RANGE -> "an output's range is written as its RANGE, an input's is left out";
            case O_TRAILING_TEXT -> "left out (the library ignores it)";
            case O_IMPLIED_RANGE -> "written as the output's RANGE (the universe the library implies)";
            default -> "written in standard syntax";
        };
    }
}
