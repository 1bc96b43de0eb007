package org.fclcert.model;

/** The IEC 61131-3 declaration section a variable comes from (5.2.1). */
public enum VariableKind {
    INPUT("VAR_INPUT"),
    OUTPUT("VAR_OUTPUT"),
    LOCAL("VAR");

    private final String keyword;

    VariableKind(String keyword) {
        this.keyword = keyword;
    }

    /** The section keyword: {@code VAR_INPUT}, {@code VAR_OUTPUT} or {@code VAR}. */
    public String keyword() {
        return keyword;
    }
}
