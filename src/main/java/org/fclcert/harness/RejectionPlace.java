package org.fclcert.harness;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * Where an implementation placed its rejection of a negative case. Only a rejection at the error's line
 * shows that the implementation found this case's error; one elsewhere, or without a line, shows only
 * that it refused the program, perhaps for a construct it does not support. The verdict counts all three
 * as rejections (the standard asks for no line numbers); the reports say how many were located.
 */
public enum RejectionPlace {
    AT_ERROR_LINE("at-error-line"),
    OTHER_LINE("other-line"),
    UNLOCATED("unlocated");

    private final String word;

    RejectionPlace(String word) {
        this.word = word;
    }

    @JsonValue
    public String word() {
        return word;
    }
}
