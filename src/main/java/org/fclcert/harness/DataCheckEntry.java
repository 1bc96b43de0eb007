package org.fclcert.harness;

/**
 * One row of the Table 11 data check list, as measured on the implementation: a stable {@code id}, the
 * {@code item} in words, the measured {@code value} and its {@code unit}, {@code bound} ({@code exact},
 * {@code at-least} or {@code not-measured}), how it was measured and a note. Filled by the probes, which
 * hand the list to {@link ResultSink#dataCheckList} so that {@code results.jsonl} carries it too.
 */
public record DataCheckEntry(String id, String item, String value, String bound, String unit, String method,
        String note) {
}
