package org.fclcert.harness;

import com.fasterxml.jackson.annotation.JsonCreator;
import com.fasterxml.jackson.annotation.JsonValue;
import java.util.Locale;

/**
 * What became of one case. Only {@link #PASSED} counts as evidence that a feature is realised; a skipped
 * case never counts as passed, and an errored case (crash, timeout, protocol fault) is kept apart from a
 * failed one (wrong numbers, wrongly accepted or rejected program).
 */
public enum CaseStatus {
    PASSED,
    FAILED,
    ERRORED,
    SKIPPED;

    @JsonValue
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    @JsonCreator
    public static CaseStatus byWord(String word) {
        return valueOf(word.toUpperCase(Locale.ROOT));
    }
}
