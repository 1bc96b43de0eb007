package org.fclcert.corpus;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One step of a case: the inputs to set, then the outputs expected after one evaluation. Both maps keep
 * the order in which the case file lists the names.
 */
public record Vector(Map<String, Double> in, Map<String, Double> out) {
    public Vector {
        in = Collections.unmodifiableMap(new LinkedHashMap<>(in));
        out = Collections.unmodifiableMap(new LinkedHashMap<>(out));
    }
}
