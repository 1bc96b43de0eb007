/**
 * The immutable semantic model of FCL programs (records), built once from a parse tree by a reader in
 * {@code org.fclcert.syntax} and used by everything else; plus the vocabulary shared across the
 * toolkit: diagnostics, source locations and the conformance feature catalogue of clause 6.
 * Nothing here depends on ANTLR.
 */
package org.fclcert.model;
