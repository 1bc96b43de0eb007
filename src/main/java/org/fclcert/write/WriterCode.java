package org.fclcert.write;

import org.fclcert.model.DiagnosticCode;
import org.fclcert.model.Severity;

/**
 * The codes of what a {@link DialectWriter} reports. {@code FCL-X1nn} (errors): the program says something the
 * library's FCL cannot say, so the written text means something else even as fclcert reads that dialect.
 * {@code FCL-X2nn} (warnings): the text means the same as fclcert reads the dialect, but the library itself is
 * known to compute it otherwise (docs/peers.md); the round trip cannot see these. Entries of the
 * catalogue ({@code cli.DiagnosticCatalogue}), listed in docs/diagnostics.md.
 */
public enum WriterCode implements DiagnosticCode {
    INITIAL_VALUE("FCL-X101", "an initial value the library's FCL cannot declare"),
    WEIGHT_VARIABLE("FCL-X102", "a WITH weight given by a variable"),
    POINT_VARIABLE("FCL-X103", "a membership-function point given by a variable"),
    BARE_VARIABLE("FCL-X104", "a bare variable as a subcondition or subconclusion (Table 9)"),
    HEDGE("FCL-X105", "a hedge the library does not have"),
    SHAPE("FCL-X106", "a membership function the library does not have"),
    OPERATOR("FCL-X107", "an operator or a combination of operators the library cannot state"),
    ACCUMULATION("FCL-X108", "an accumulation the library cannot state for that output"),
    RULE_FORM("FCL-X109", "a rule the library's rule syntax cannot state"),
    METHOD("FCL-X110", "a defuzzification method the library does not have"),
    DEFAULT("FCL-X111", "a DEFAULT the library cannot state"),
    NAME("FCL-X112", "a name the library does not read"),
    TYPE("FCL-X113", "a data type the library does not declare"),
    STRUCTURE("FCL-X114", "more function blocks, outputs or rule blocks than the library's model holds"),
    SAMPLED("FCL-X201", "the library samples this defuzzification instead of computing it exactly"),
    NSUM("FCL-X202", "the library computes ACCU NSUM as BSUM"),
    WEIGHT_BEFORE_ACTIVATION("FCL-X203", "the library folds a weight into the rule's degree before an ACT other than PROD"),
    COGS_PER_RULE("FCL-X204", "the library's CoGS counts each rule, not each term"),
    FIRST_BLOCK_ONLY("FCL-X205", "the library builds only the first function block"),
    IGNORED_BY_LIBRARY("FCL-X206", "a setting the library ignores or replaces by its own"),
    LEFT_OUT("FCL-X207", "a part without effect on evaluation that the library's FCL has no place for, left out"),
    NOT_LOADED("FCL-X208", "a construct the library is known not to load"),
    VERTICAL_EDGE("FCL-X209", "the library gives a vertical edge of a term another degree at its x"),
    TSUKAMOTO_INVERSE("FCL-X210", "the library inverts a term otherwise in Tsukamoto's method (fuzzylite 6.0: SShape,"
            + " ZShape, Concave; pyfuzzylite 8: a Sigmoid at degree 1 or 0)"),
    NOT_A_POSITION("FCL-X211", "the library's defuzzification returns something other than a position on the output's"
            + " range (the Octave fuzzy-logic-toolkit 0.4.6's bisector: the number of a sample)"),
    SHAPE_FORMULA("FCL-X212", "the library computes a named shape by another formula (the Octave toolkit 0.4.6's dsigmf:"
            + " 0 where fuzzylite takes the absolute difference)");

    private final Entry entry;

    /**
     * A loss (X1nn) is an error (a warning with --allow-lossy), a library's deviation (X2nn) a warning; the
     * libraries' constructs are Open Level features (Table 10), as for the conversion codes.
     */
    WriterCode(String code, String meaning) {
        this.entry = new Entry(code, code.startsWith("FCL-X1") ? Severity.ERROR : Severity.WARNING, "Table 10", meaning);
    }

    @Override
    public Entry entry() {
        return entry;
    }

    /** X1nn codes are losses of meaning; X2nn codes are the library's own deviations. */
    public boolean lossOfMeaning() {
        return severity() == Severity.ERROR;
    }
}
