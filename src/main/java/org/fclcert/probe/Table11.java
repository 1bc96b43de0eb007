package org.fclcert.probe;

/** The rows of Table 11 (clause 6.2) in the standard's order, with their stable ids and units. */
public enum Table11 {
    DATA_TYPES("data-types", "data types of function block inputs and outputs", "types"),
    LINE_COMMENTS("line-comments", "line comments in the FCL program", "forms"),
    EXECUTION_TIME("execution-time-ms", "execution time of the reference workload", "ms"),
    MEMORY("memory-kb", "memory requirements", "kB"),
    DEGREE_RESOLUTION("degree-resolution", "mapping of membership degrees 0.0 … 1.0 onto integers", "step"),
    IDENTIFIER_LENGTH("identifier-length", "length of identifiers", "characters"),
    INPUTS("max-input-variables", "max. number of input variables for fuzzification", "inputs"),
    TERMS_PER_INPUT("max-terms-per-input", "max. number of membership function terms per input variable", "terms"),
    TERMS_ALL_INPUTS("max-terms-all-inputs", "max. total number of membership function terms for all input variables",
            "terms"),
    POINTS_PER_INPUT_TERM("max-points-per-input-term", "max. number of points of the membership function of an input"
            + " term", "points"),
    POINTS_ALL_INPUT_TERMS("max-points-all-input-terms", "max. total number of points of all input terms", "points"),
    OUTPUTS("max-output-variables", "max. number of output variables for defuzzification", "outputs"),
    TERMS_PER_OUTPUT("max-terms-per-output", "max. number of membership function terms per output variable", "terms"),
    TERMS_ALL_OUTPUTS("max-terms-all-outputs", "max. total number of membership function terms for all output"
            + " variables", "terms"),
    POINTS_PER_OUTPUT_TERM("max-points-per-output-term", "max. number of points of the membership function of an"
            + " output term", "points"),
    POINTS_ALL_OUTPUT_TERMS("max-points-all-output-terms", "max. total number of points of all output terms", "points"),
    RULE_BLOCKS("max-rule-blocks", "max. number of rule blocks", "rule blocks"),
    RULES_PER_BLOCK("max-rules-per-block", "max. number of rules per block", "rules"),
    SUBCONDITIONS("max-subconditions-per-rule", "max. number of subconditions per rule", "subconditions"),
    RULES_TOTAL("max-rules-total", "max. number of all rules", "rules"),
    SUBCONCLUSIONS("max-subconclusions-per-rule", "max. number of subconclusions per rule", "subconclusions"),
    NESTING("max-nesting-depth", "nesting depth of ()", "levels");

    private final String id;
    private final String item;
    private final String unit;

    Table11(String id, String item, String unit) {
        this.id = id;
        this.item = item;
        this.unit = unit;
    }

    public String id() {
        return id;
    }

    public String item() {
        return item;
    }

    public String unit() {
        return unit;
    }

    /** Whether the row is a "maximum number of" row (or identifier length), measured by growing sizes. */
    boolean isLimit() {
        return ordinal() >= IDENTIFIER_LENGTH.ordinal();
    }
}
