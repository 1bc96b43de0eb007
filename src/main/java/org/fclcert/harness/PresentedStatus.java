package org.fclcert.harness;

import com.fasterxml.jackson.annotation.JsonCreator;
import com.fasterxml.jackson.annotation.JsonValue;
import java.util.Locale;

/**
 * What became of a case on the semantic axis: as {@link CaseStatus}, plus {@link #NOT_PRESENTABLE} for a
 * program the library's layout cannot say (it counts against no semantic verdict).
 */
public enum PresentedStatus {
    PASSED,
    FAILED,
    ERRORED,
    SKIPPED,
    NOT_PRESENTABLE;

    @JsonValue
    public String word() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    @JsonCreator
    public static PresentedStatus byWord(String word) {
        return valueOf(word.toUpperCase(Locale.ROOT).replace('-', '_'));
    }

    static PresentedStatus of(CaseStatus status) {
        return valueOf(status.name());
    }
}
