package org.fclcert.model;

/**
 * A hedge before a term in a subcondition ({@code x is very small}), as fuzzylite writes them: outside
 * the standard (Open Level, Table 10). A hedge maps the term's degree μ to another degree; several
 * hedges apply from the one nearest the term outwards. fclcert uses fuzzylite's definitions, the
 * dialect the words come from (docs/semantics.md, "Named shapes, hedges and other dialect accumulations").
 */
public enum Hedge {
    /** μ². */
    VERY("very", "O-HEDGE-VERY"),
    /** √μ. */
    SOMEWHAT("somewhat", "O-HEDGE-SOMEWHAT"),
    /** Contrast intensification: 2μ² for μ ≤ 0.5, else 1 − 2(1 − μ)². */
    EXTREMELY("extremely", "O-HEDGE-EXTREMELY"),
    /** Its inverse, contrast dilution: √(μ/2) for μ ≤ 0.5, else 1 − √((1 − μ)/2). */
    SELDOM("seldom", "O-HEDGE-SELDOM"),
    /** 1 whatever the input; {@code x is any} names no term. */
    ANY("any", "O-HEDGE-ANY"),
    /** 1 − μ, where it is not the standard's {@code IS NOT} (e.g. {@code very not small}). */
    NOT("not", "O-HEDGE-NOT");

    private final String word;
    private final String featureId;

    Hedge(String word, String featureId) {
        this.word = word;
        this.featureId = featureId;
    }

    /** The word as fuzzylite writes it. */
    public String word() {
        return word;
    }

    public String featureId() {
        return featureId;
    }

    public double apply(double mu) {
        return switch (this) {
            case VERY -> mu * mu;
            case SOMEWHAT -> Math.sqrt(mu);
            case EXTREMELY -> mu <= 0.5 ? 2 * mu * mu : 1 - 2 * (1 - mu) * (1 - mu);
            case SELDOM -> mu <= 0.5 ? Math.sqrt(mu / 2) : 1 - Math.sqrt((1 - mu) / 2);
            case ANY -> 1.0;
            case NOT -> 1.0 - mu;
        };
    }

    /** Applies hedges as written before a term: the last (nearest the term) first. */
    public static double applyAll(java.util.List<Hedge> hedges, double mu) {
        double d = mu;
        for (int i = hedges.size() - 1; i >= 0; i--) {
            d = hedges.get(i).apply(d);
        }
        return d;
    }
}
