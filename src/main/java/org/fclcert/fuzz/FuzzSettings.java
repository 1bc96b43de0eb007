package org.fclcert.fuzz;

import java.util.EnumSet;
import java.util.Set;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;

/**
 * What the generator may use: features up to {@code level}, and the features to favour ({@code focus}; empty
 * = no preference). A focused feature is used in most programs; the others stay possible, less often, so that
 * a defect in the combination still shows.
 */
public record FuzzSettings(ConformanceLevel level, Set<Feature> focus) {
    public FuzzSettings {
        focus = focus.isEmpty() ? Set.of() : Set.copyOf(EnumSet.copyOf(focus));
    }

    /** Everything the reference evaluates, no preference. */
    public static FuzzSettings open() {
        return new FuzzSettings(ConformanceLevel.OPEN, Set.of());
    }

    /** True when programs of these settings may use the feature. */
    public boolean allows(Feature f) {
        return f.level().compareTo(level) <= 0 && !f.dialectSyntax();
    }

    /**
     * How likely a program is to use {@code f} where it could: {@code base} without a focus; with a focus,
     * 0.85 for a focused feature and a third of {@code base} for the others; 0 for a feature above the level.
     */
    public double weight(Feature f, double base) {
        if (!allows(f)) {
            return 0;
        }
        if (focus.isEmpty()) {
            return base;
        }
        return focus.contains(f) ? 0.85 : base / 3;
    }

    /** The features a generated program can carry (standard syntax plus the Open Level methods). */
    public static Set<Feature> generatable() {
        Set<Feature> out = EnumSet.noneOf(Feature.class);
        for (Feature f : Feature.values()) {
            if (!f.dialectSyntax()) {
                out.add(f);
            }
        }
        return out;
    }
}
