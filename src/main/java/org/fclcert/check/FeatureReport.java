package org.fclcert.check;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.fclcert.model.ConformanceLevel;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;

/**
 * The conformance features a program uses.
 *
 * @param level the lowest conformance level that can run the program: the highest level among its
 *              features ({@link ConformanceLevel#BASIC} when it uses only Table 8 rows, or none)
 * @param uses  every use of a feature with the place that needs it, sorted by location
 */
public record FeatureReport(ConformanceLevel level, List<FeatureUse> uses) {
    public FeatureReport {
        uses = List.copyOf(uses);
    }

    /** The distinct features used, in order of first use. */
    public Set<Feature> features() {
        Set<Feature> out = new LinkedHashSet<>();
        uses.forEach(u -> out.add(u.feature()));
        return out;
    }
}
