package org.fclcert.iut;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The child-JVM side of {@code java:CLASS} (without {@code --in-process}, {@link JavaProcessIut}): loads the vendor's
 * class from its own class path, drives it through the SPI exactly as {@link JavaIut} does in process, and answers
 * fclcert's JSON-lines protocol ({@code docs/iut-protocol.md}) on standard output. Whatever the vendor's code
 * prints goes to standard error ({@code System.out} is redirected there before the class is touched), so standard
 * output carries replies only. Timeouts, CPU limits and restarts are the parent's ({@link ProcessIut}): a vendor call
 * that hangs is ended by killing this JVM, one that calls {@code System.exit} ends only this JVM.
 *
 * <p>Arguments: the vendor's class name.
 */
public final class JavaBridge {
    /** Inside the child, no call is abandoned: the parent's timeout kills the whole JVM instead. */
    private static final Duration NO_TIMEOUT = Duration.ofDays(365);

    private final BridgeLoop loop;
    private final ImplementationUnderTest vendor;
    private final String openFailure;

    private JavaBridge(BridgeLoop loop, ImplementationUnderTest vendor, String openFailure) {
        this.loop = loop;
        this.vendor = vendor;
        this.openFailure = openFailure;
    }

    /** Reads requests from standard input until {@code bye} or its end; one reply line per request. */
    public static void main(String[] args) throws IOException {
        BridgeLoop loop = new BridgeLoop();
        System.setOut(new PrintStream(new FileOutputStream(FileDescriptor.err), true, StandardCharsets.UTF_8));
        String className = args.length == 1 ? args[0] : "";
        ImplementationUnderTest vendor = null;
        String openFailure = null;
        try {
            IutOptions options = IutOptions.defaults().withTimeout(NO_TIMEOUT).withInProcess(true);
            vendor = JavaIut.open("java:" + className, className, options);
        } catch (IutException e) {
            openFailure = e.getMessage();
        }
        loop.serve(new JavaBridge(loop, vendor, openFailure)::answer);
        if (vendor != null) {
            vendor.close();
        }
        // the vendor's threads must not keep this JVM alive once fclcert said bye or closed the pipe
        Runtime.getRuntime().halt(0);
    }

    private ObjectNode answer(String op, JsonNode request) {
        if (openFailure != null && !op.equals("bye")) {
            return error("crash", openFailure);
        }
        try {
            return switch (op) {
                case "hello" -> hello(vendor.hello());
                case "load" -> load(vendor.load(request.path("fcl").asText()));
                case "eval" -> eval(request.hasNonNull("block") ? request.get("block").asText() : null,
                        request.path("inputs"));
                case "reset" -> {
                    vendor.reset();
                    yield ok();
                }
                case "export" -> export(vendor.export());
                case "bye" -> ok();
                default -> error("error", "unknown op '" + op + "'");
            };
        } catch (IutException e) {
            // a refusal to evaluate is the vendor's answer; anything else the vendor did is a failure inside it
            return error(e.kind() == IutException.Kind.EVAL_ERROR ? "error" : "crash", e.getMessage());
        } catch (RuntimeException | Error e) {
            return error("crash", e.getClass().getName() + (e.getMessage() == null ? "" : ": " + e.getMessage()));
        }
    }

    private ObjectNode hello(IutInfo info) {
        ObjectNode reply = ok();
        ObjectNode implementation = reply.putObject("implementation");
        implementation.put("name", info.name());
        implementation.put("version", info.version());
        info.claims().forEach(implementation.putArray("claims")::add);
        ObjectNode limits = implementation.putObject("limits");
        info.declaredLimits().forEach(limits::put);
        return reply;
    }

    private ObjectNode load(LoadOutcome outcome) {
        if (outcome instanceof LoadOutcome.Rejected rejected) {
            return loop.rejected(rejected.message(), rejected.line());
        }
        ObjectNode reply = ok();
        ((LoadOutcome.Loaded) outcome).blocks().forEach(reply.putArray("blocks")::add);
        return reply;
    }

    private ObjectNode eval(String block, JsonNode inputs) throws IutException {
        Map<String, Double> values = new LinkedHashMap<>();
        for (Map.Entry<String, JsonNode> input : inputs.properties()) {
            values.put(input.getKey(), input.getValue().asDouble());
        }
        ObjectNode reply = ok();
        ObjectNode outputs = reply.putObject("outputs");
        vendor.eval(block, values).forEach((name, value) -> {
            if (value == null) {
                outputs.putNull(name);
            } else {
                outputs.put(name, value.doubleValue());
            }
        });
        return reply;
    }

    private ObjectNode export(Optional<String> text) {
        if (text.isEmpty()) {
            return error("unsupported", "the implementation does not export FCL");
        }
        return ok().put("fcl", text.get());
    }

    private ObjectNode ok() {
        return loop.ok();
    }

    private ObjectNode error(String kind, String message) {
        return loop.error(kind, message);
    }
}
