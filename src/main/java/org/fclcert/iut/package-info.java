/**
 * Implementations under test: the one interface the harness drives ({@link
 * org.fclcert.iut.ImplementationUnderTest}), opened from a spec by {@link org.fclcert.iut.Iuts#open}, with
 * four adapters — fclcert's reference evaluator in process, a Java class implementing the vendor SPI
 * ({@link org.fclcert.iut.spi}), a separate process speaking the JSON-lines protocol of
 * {@code docs/iut-protocol.md}, and the fuzzylite 6.0 command line driven from outside
 * ({@code FuzzyliteIut}).
 */
package org.fclcert.iut;
