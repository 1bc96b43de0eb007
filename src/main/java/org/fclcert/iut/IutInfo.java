package org.fclcert.iut;

import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * What an implementation reports about itself.
 *
 * @param name           the implementation's name, as it gives it
 * @param version        its version, as it gives it
 * @param command        how fclcert reached it (the spec given to {@link Iuts#open})
 * @param claims         the feature ids (B-…, E-…, O-…) it says it realises; the report compares
 *                       them with what was measured
 * @param declaredLimits limits it declares, by Table 11 id (for example {@code max-rules-per-block}; the prober
 *                       compares only those ids, see {@code docs/data-check-list.md}), other names kept as given
 */
public record IutInfo(
        String name, String version, String command, List<String> claims, Map<String, Long> declaredLimits) {
    public IutInfo {
        // what the implementation says of itself is kept as IutText keeps any of its strings
        name = IutText.kept(Objects.requireNonNull(name, "name"));
        version = IutText.kept(Objects.requireNonNull(version, "version"));
        Objects.requireNonNull(command, "command");
        claims = claims.stream().map(IutText::kept).toList();
        declaredLimits = Map.copyOf(declaredLimits);
    }
}
