package org.fclcert.iut;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import com.fasterxml.jackson.core.json.JsonWriteFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
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

    private final ObjectMapper json;
    private final ImplementationUnderTest vendor;

    private JavaBridge(ObjectMapper json, ImplementationUnderTest vendor) {
        this.json = json;
        this.vendor = vendor;
    }

    /** Reads requests from standard input until {@code bye} or its end; one reply line per request. */
    public static void main(String[] args) throws IOException {
        PrintStream protocol = new PrintStream(new FileOutputStream(FileDescriptor.out), false, StandardCharsets.UTF_8);
        System.setOut(new PrintStream(new FileOutputStream(FileDescriptor.err), true, StandardCharsets.UTF_8));
        JsonFactory factory = JsonFactory.builder().enable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS)
                .disable(JsonWriteFeature.WRITE_NAN_AS_STRINGS).build();
        ObjectMapper json = new ObjectMapper(factory);
        String className = args.length == 1 ? args[0] : "";
        ImplementationUnderTest vendor = null;
        String openFailure = null;
        try {
            IutOptions options = IutOptions.defaults().withTimeout(NO_TIMEOUT).withInProcess(true);
            vendor = JavaIut.open("java:" + className, className, options);
        } catch (IutException e) {
            openFailure = e.getMessage();
        }
        JavaBridge bridge = new JavaBridge(json, vendor);
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            if (line.isBlank()) {
                continue;
            }
            ObjectNode reply;
            String op = "";
            JsonNode request = null;
            try {
                request = json.readTree(line);
                op = request.path("op").asText();
                reply = openFailure != null && !op.equals("bye") ? bridge.error("crash", openFailure)
                        : bridge.answer(op, request);
            } catch (IOException e) {
                reply = bridge.error("error", "the request is not JSON: " + e.getMessage());
            }
            if (request != null && request.has("id")) {
                reply.set("id", request.get("id"));
            }
            protocol.println(json.writeValueAsString(reply));
            protocol.flush();
            if (op.equals("bye")) {
                break;
            }
        }
        protocol.flush();
        if (vendor != null) {
            vendor.close();
        }
        // the vendor's threads must not keep this JVM alive once fclcert said bye or closed the pipe
        Runtime.getRuntime().halt(0);
    }

    private ObjectNode answer(String op, JsonNode request) {
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
            ObjectNode reply = error("rejected", rejected.message());
            rejected.line().ifPresent(n -> ((ObjectNode) reply.get("error")).put("line", n));
            return reply;
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
        return json.createObjectNode().put("ok", true);
    }

    private ObjectNode error(String kind, String message) {
        ObjectNode reply = json.createObjectNode().put("ok", false);
        reply.putObject("error").put("kind", kind).put("message", message);
        return reply;
    }
}
