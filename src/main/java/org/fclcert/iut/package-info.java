/**
 * Implementations under test: the one interface the harness drives ({@link
 * org.fclcert.iut.ImplementationUnderTest}), opened from a spec by {@link org.fclcert.iut.Iuts#open}, with
 * three adapters — fclcert's reference evaluator in process, a Java class implementing the vendor SPI
 * ({@link org.fclcert.iut.spi}), and a separate process speaking the JSON-lines protocol of
 * {@code docs/iut-protocol.md}.
 */
package org.fclcert.iut;
