package org.fclcert.model;

/**
 * {@code OPTIONS ... END_OPTIONS} (5.2.5): manufacturer-specific parameters for the Open Level. The
 * text between the keywords is kept verbatim (leading and trailing white space trimmed).
 */
public record OptionsBlock(String content, SourceLocation location) {
}
