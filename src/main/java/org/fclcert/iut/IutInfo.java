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
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(version, "version");
        Objects.requireNonNull(command, "command");
        claims = List.copyOf(claims);
        declaredLimits = Map.copyOf(declaredLimits);
    }
}
