package org.fclcert.model;

/** {@code ACCU:} algorithms (Table 5). */
public enum AccumulationMethod {
    MAX,
    BSUM,
    NSUM
}
