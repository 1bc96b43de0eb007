package org.fclcert.report;

import com.fasterxml.jackson.annotation.JsonCreator;
import com.fasterxml.jackson.annotation.JsonValue;
import java.util.Locale;

/**
 * Verdict on one feature row: all its cases passed, some did, none did, not all the cases it needs were run (or
 * those that ran failed for other rows' reasons), or no case of it was run.
 */
public enum FeatureStatus {
    REALISED,
    PARTIAL,
    NOT_REALISED,
    NOT_TESTED,
    NOT_DETERMINED;

    @JsonValue
    public String word() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /** For people: "realised", "partial", "not realised", "not tested". */
    public String label() {
        return word().replace('-', ' ');
    }

    @JsonCreator
    public static FeatureStatus byWord(String word) {
        return valueOf(word.toUpperCase(Locale.ROOT).replace('-', '_'));
    }

    static FeatureStatus of(int passed, int counted) {
        if (counted == 0) {
            return NOT_TESTED;
        }
        return passed == counted ? REALISED : passed == 0 ? NOT_REALISED : PARTIAL;
    }
}
