package org.fclcert.model;

/** A setting together with where it was written, e.g. {@code METHOD: CoG;} or {@code ACCU: MAX;}. */
public record Located<T>(T value, SourceLocation location) {
}
