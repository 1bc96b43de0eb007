package org.fclcert.fuzz;

import org.fclcert.model.Feature;

/**
 * One distinct finding: the feature its minimal case isolates and the kind of deviation (together its
 * identity for deduplication), the minimal case and its deviation, where it was first seen, and how many
 * later disagreements turned out to be the same.
 *
 * @param programIndex the index of the generated program it was first seen on ({@code --seed} and this
 *                     index regenerate that program)
 * @param originalLines lines of the program it was first seen on
 * @param foundAfterMillis time from the start of the run to the disagreement
 * @param shrinkMillis  time spent shrinking it
 */
public record Finding(Feature feature, DeviationKind kind, Shrinker.Case minimal, Deviation deviation,
        Deviation original, long programIndex, long programSeed, int originalLines, int shrinkTrials, int duplicates,
        long foundAfterMillis, long shrinkMillis) {

    /** The deduplication key, e.g. {@code E-ACCU-NSUM/wrong-value}. */
    public String key() {
        return feature.id() + "/" + kind.word();
    }

    Finding withDuplicate() {
        return new Finding(feature, kind, minimal, deviation, original, programIndex, programSeed, originalLines,
                shrinkTrials, duplicates + 1, foundAfterMillis, shrinkMillis);
    }
}
