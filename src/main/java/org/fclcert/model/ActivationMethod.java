package org.fclcert.model;

/** {@code ACT:} algorithms (Table 4). */
public enum ActivationMethod {
    MIN,
    PROD
}
