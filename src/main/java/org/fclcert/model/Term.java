package org.fclcert.model;

/** A linguistic term: {@code TERM name := membership_function;} (5.2.2, 5.2.3). */
public record Term(String name, MembershipFunction function, SourceLocation location) {
}
