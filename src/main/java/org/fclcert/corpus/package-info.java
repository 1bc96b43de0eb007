/**
 * The conformance corpus: loading the case files of {@code conformance/}, the tolerance classes used to
 * compare an implementation's outputs with the expected ones, and the lint that keeps the corpus and the
 * toolkit in agreement. The case format is described in {@code conformance/README.md}.
 */
package org.fclcert.corpus;
