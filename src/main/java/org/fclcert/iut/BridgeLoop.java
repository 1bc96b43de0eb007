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
import java.util.OptionalInt;

/**
 * The child side of fclcert's JSON-lines protocol ({@code docs/iut-protocol.md}) as the Java bridges
 * ({@link JavaBridge}, {@link JFuzzyLogicBridge}) run it: one request per line on standard input, one reply line
 * per request on the real standard output (taken before the library can redirect {@code System.out}), the
 * request's {@code id} echoed, a line that is not JSON answered with an error, and the loop ended by {@code bye}
 * or the end of input. What each request means is the bridge's {@link Answers}.
 */
final class BridgeLoop {
    /** What a bridge answers to one request; it never throws: a failure is an error reply. */
    interface Answers {
        ObjectNode answer(String op, JsonNode request);
    }

    private final ObjectMapper json;
    private final PrintStream protocol;

    /** Takes the process's standard output for the protocol; call before the library is touched. */
    BridgeLoop() {
        this.protocol = new PrintStream(new FileOutputStream(FileDescriptor.out), false, StandardCharsets.UTF_8);
        // NaN and infinities travel as the bare words the protocol allows, in both directions
        JsonFactory factory = JsonFactory.builder().enable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS)
                .disable(JsonWriteFeature.WRITE_NAN_AS_STRINGS).build();
        this.json = new ObjectMapper(factory);
    }

    ObjectMapper json() {
        return json;
    }

    /** Answers requests from standard input until {@code bye} or its end. */
    void serve(Answers answers) throws IOException {
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
                reply = answers.answer(op, request);
            } catch (IOException e) {
                reply = error("error", "the request is not JSON: " + e.getMessage());
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
    }

    ObjectNode ok() {
        return json.createObjectNode().put("ok", true);
    }

    ObjectNode error(String kind, String message) {
        ObjectNode reply = json.createObjectNode().put("ok", false);
        reply.putObject("error").put("kind", kind).put("message", message);
        return reply;
    }

    /** A refusal of the program, with the line the library named when it named one. */
    ObjectNode rejected(String message, OptionalInt line) {
        ObjectNode reply = error("rejected", message);
        line.ifPresent(n -> ((ObjectNode) reply.get("error")).put("line", n));
        return reply;
    }
}
