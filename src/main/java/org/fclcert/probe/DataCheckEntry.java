package org.fclcert.probe;

/**
 * One row of the Table 11 data check list (clause 6.2), as measured on the implementation: a stable
 * {@code id}, the {@code item} in words, the measured {@code value} and its {@code unit}, {@code bound}
 * ({@code exact}, {@code at-least} or {@code not-measured}), how it was measured, a note (what happened
 * just above the limit, a budget that ran out, a declared limit not met) and the limit the
 * implementation declared in its {@code hello} for this id (empty when it declared none).
 */
public record DataCheckEntry(String id, String item, String value, String bound, String unit, String method,
        String note, String declared) {
    public static final String EXACT = "exact";
    public static final String AT_LEAST = "at-least";
    public static final String NOT_MEASURED = "not-measured";

    public DataCheckEntry {
        declared = declared == null ? "" : declared;
        note = note == null ? "" : note;
    }

    /** A row without a declared limit. */
    public DataCheckEntry(String id, String item, String value, String bound, String unit, String method,
            String note) {
        this(id, item, value, bound, unit, method, note, "");
    }
}
