/**
 * Certification reports: the verdicts of clause 6.1 (Basic Level, the Table 9 Standard Extensions realised,
 * the Table 10 Open Level features) built from case results, and their renderings as {@code report.json},
 * {@code report.md}, {@code report.html} and {@code junit.xml}.
 */
package org.fclcert.report;
