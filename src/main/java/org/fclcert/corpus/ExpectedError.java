package org.fclcert.corpus;

/** The single error a negative case must produce: its diagnostic code and its 1-based line in the file. */
public record ExpectedError(String code, int line) {
}
