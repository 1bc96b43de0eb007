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
            case O_VAR_RETAIN -> "left out (it has no effect on evaluation)";
            default -> "written in standard syntax";
        };
    }
}
