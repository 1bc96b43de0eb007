package org.fclcert.harness;

import com.fasterxml.jackson.annotation.JsonCreator;
import com.fasterxml.jackson.annotation.JsonValue;
import java.util.Locale;

/**
 * Outcome of the export check of clause 6 e) (FCL must be an output format too). Reported per case and
 * never counted in the case status.
 */
public enum ExportStatus {
    /** The exported text reads back strictly and evaluates like the original on the case's vectors. */
    PASSED,
    /** The exported text does not read back, or evaluates differently. */
    FAILED,
    /** The implementation does not export. */
    UNSUPPORTED,
    /** Not checked: a negative case, or the program did not load, or the implementation broke down. */
    NOT_RUN;

    @JsonValue
    public String word() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    @JsonCreator
    public static ExportStatus byWord(String word) {
        return valueOf(word.toUpperCase(Locale.ROOT).replace('-', '_'));
    }
}
