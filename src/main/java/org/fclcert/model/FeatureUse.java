package org.fclcert.model;

/** A place in a program that needs a conformance feature. */
public record FeatureUse(Feature feature, SourceLocation location) {
}
