/**
 * The certification flow, above the packages it uses: {@link org.fclcert.orchestration.Certification} selects
 * the cases, starts the implementation, runs the cases through {@code org.fclcert.harness} (streaming
 * {@code results.jsonl}), measures the Table 11 data check list with {@code org.fclcert.probe} when asked,
 * and builds and writes the reports with {@code org.fclcert.report}. The front ends ({@code org.fclcert.cli}
 * and the Maven plugin in {@code org.fclcert.maven}) only turn their options into a request and present
 * the outcome. Library code: nothing here prints or exits.
 */
package org.fclcert.orchestration;
