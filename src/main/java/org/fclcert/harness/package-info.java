/**
 * Runs the conformance corpus against an implementation under test: selects cases, loads each program,
 * evaluates its vectors, checks rejections, state leaks and the FCL export of clause 6 e), and streams one
 * {@link org.fclcert.harness.CaseResult} per case. Verdicts and reports are built from those results by
 * {@code org.fclcert.report}. Library code: reports progress through {@link org.fclcert.harness.RunListener},
 * never prints.
 */
package org.fclcert.harness;
