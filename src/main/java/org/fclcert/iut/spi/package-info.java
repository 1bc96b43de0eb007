/**
 * The vendor SPI: what a Java FCL implementation provides so that fclcert can certify it in process
 * ({@code fclcert certify --iut java:com.example.MyFcl --classpath my-fcl.jar}).
 *
 * <p>A vendor writes one public class with a public no-argument constructor implementing
 * {@link org.fclcert.iut.spi.FclImplementation}, and ships it in its own jar, compiled against this
 * package only. fclcert then:
 * <ol>
 *   <li>calls {@code load} with the text of one conformance case (line numbers as in the corpus file);</li>
 *   <li>on a loaded program, creates an instance of a function block, and for each test vector calls
 *       {@code set} for every input, {@code evaluate} once, and {@code get} for every output;</li>
 *   <li>calls {@code reset} between runs on the same instance, and {@code export} once per case.</li>
 * </ol>
 * Every call runs under a timeout on a worker thread; an exception thrown by vendor code is reported
 * against the case (as an evaluation error from {@code set}/{@code evaluate}/{@code get}, as a crash
 * elsewhere), never propagated. This package is kept small and stable: it depends on nothing but the
 * JDK.
 */
package org.fclcert.iut.spi;
