/**
 * The language server of {@code fclcert lsp} (Language Server Protocol over stdio, Eclipse LSP4J): the checker's
 * findings as an editor's diagnostics, hover, navigation, outline, completion, formatting and quick fixes.
 * A front end like {@code cli}, which starts it; it reads with {@code syntax}, judges with {@code check}, formats
 * with {@code write} and never prints: everything it has to say goes to the client (docs/lsp.md).
 */
package org.fclcert.lsp;
