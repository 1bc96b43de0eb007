package org.fclcert.syntax;

/**
 * Reads FCL source text into the semantic model. The strict reader implements the standard; dialect
 * readers (FFLL, jFuzzyLogic, fuzzylite) implement the same interface and produce the same model.
 * A reader never throws on bad input and never prints: everything it finds is a diagnostic.
 */
public interface FclReader {
    /**
     * @param sourceName the name diagnostics use for this text (usually the file path as given)
     * @param text       the whole source text
     */
    ReadResult read(String sourceName, String text);
}
