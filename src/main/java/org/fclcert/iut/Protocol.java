package org.fclcert.iut;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.exc.StreamReadException;
import com.fasterxml.jackson.core.StreamReadFeature;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.Set;

/**
 * The JSON-lines messages of {@code docs/iut-protocol.md}: building requests and reading replies. A
 * reply of the wrong shape is a {@link IutException.Kind#PROTOCOL} fault; a well-formed
 * {@code ok:false} is the IUT's own answer.
 */
final class Protocol {
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private Protocol() {}

    /**
     * Python's json module writes NaN and Infinity; they are read (and then fail as wrong numbers). A key
     * given twice in one object makes the reply ambiguous ({@code {"y":1,"y":2}}): Jackson would keep the
     * last, another reader the first, so it is a protocol fault ({@link #caseCollision} adds keys that
     * differ only in case, since FCL names are case-insensitive).
     */
    static ObjectMapper mapper() {
        JsonFactory factory = JsonFactory.builder().enable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS)
                .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION).build();
        return new ObjectMapper(factory).enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS);
    }

    /** How much of an offending reply a fault quotes. */
    private static final int QUOTE_CHARS = 200;

    /**
     * Reads one reply line to request {@code id} ({@code op}): a JSON object with a boolean {@code ok}, no key given
     * twice (nor twice but for case), and, when it carries an {@code id}, ours. Anything else is a
     * {@link IutException.Kind#PROTOCOL} fault quoting the line.
     */
    static JsonNode reply(ObjectMapper mapper, String text, String op, long id) throws IutException {
        if (text.startsWith(BYTE_ORDER_MARK)) {
            // a UTF-8 byte-order mark (some runtimes write one before their first output) is no part of the reply
            text = text.substring(1);
        }
        JsonNode reply;
        try {
            reply = mapper.readTree(text);
        } catch (StreamReadException e) {
            if (e.getMessage() != null && e.getMessage().startsWith("Duplicate field")) {
                throw protocol("the reply to '" + op + "' is ambiguous: it gives a key twice in one object: "
                        + quote(text));
            }
            throw protocol("the reply to '" + op + "' is not JSON: " + quote(text));
        } catch (JsonProcessingException e) {
            throw protocol("the reply to '" + op + "' is not JSON: " + quote(text));
        }
        if (reply == null || !reply.isObject() || !reply.path("ok").isBoolean()) {
            throw protocol("the reply to '" + op + "' is not an object with a boolean 'ok': " + quote(text));
        }
        Optional<String> collision = caseCollision(reply);
        if (collision.isPresent()) {
            throw protocol("the reply to '" + op + "' is ambiguous: key '" + IutText.kept(collision.get())
                    + "' differs from another key of the same object only in case: " + quote(text));
        }
        JsonNode echoed = reply.get("id");
        if (echoed != null && !(echoed.canConvertToExactIntegral() && echoed.asLong() == id)) {
            throw protocol("the reply to '" + op + "' carries id " + quote(echoed.toString()) + " where " + id
                    + " was sent");
        }
        return reply;
    }

    /** U+FEFF, which UTF-8 writes as EF BB BF: skipped before a reply. */
    static final String BYTE_ORDER_MARK = "\uFEFF";

    /**
     * The start of an offending line, well-formed and in visible form, for a fault's message: a byte-order mark,
     * control characters and other invisible ones are written as {@code <U+FEFF>}, {@code <U+001B>}, so that what
     * was received can be seen (and no terminal or report interprets it).
     */
    static String quote(String text) {
        String shown = IutText.wellFormed(text);
        String cut = shown.length() <= QUOTE_CHARS ? shown
                : shown.substring(0, Character.isHighSurrogate(shown.charAt(QUOTE_CHARS - 1)) ? QUOTE_CHARS - 1
                        : QUOTE_CHARS) + "…";
        StringBuilder out = new StringBuilder(cut.length());
        cut.codePoints().forEach(cp -> {
            int type = Character.getType(cp);
            boolean invisible = type == Character.CONTROL || type == Character.FORMAT || type == Character.UNASSIGNED
                    || type == Character.LINE_SEPARATOR || type == Character.PARAGRAPH_SEPARATOR;
            if (invisible) {
                out.append(String.format("<U+%04X>", cp));
            } else {
                out.appendCodePoint(cp);
            }
        });
        return out.toString();
    }

    static ObjectNode request(String op) {
        return NODES.objectNode().put("op", op);
    }

    static ObjectNode load(String fcl) {
        return request("load").put("fcl", fcl);
    }

    static ObjectNode eval(String block, Map<String, Double> inputs) throws IutException {
        ObjectNode request = request("eval");
        if (block != null) {
            request.put("block", block);
        }
        ObjectNode values = request.putObject("inputs");
        for (Map.Entry<String, Double> input : inputs.entrySet()) {
            if (input.getValue() == null || !Double.isFinite(input.getValue())) {
                throw new IutException(IutException.Kind.INFRA,
                        "input " + input.getKey() + " = " + input.getValue() + " cannot be sent as a JSON number");
            }
            values.put(input.getKey(), input.getValue());
        }
        return request;
    }

    static IutInfo info(JsonNode reply, String command) throws IutException {
        requireOk(reply, "hello");
        JsonNode impl = reply.path("implementation");
        String name = text(impl, "name", "hello");
        String version = text(impl, "version", "hello");
        List<String> claims = new ArrayList<>();
        for (JsonNode claim : arrayOrEmpty(impl.path("claims"), "implementation.claims")) {
            if (!claim.isTextual()) {
                throw protocol("implementation.claims must be a list of feature ids");
            }
            claims.add(claim.asText());
        }
        return new IutInfo(name, version, command, claims, limits(impl.path("limits")));
    }

    private static Map<String, Long> limits(JsonNode limits) throws IutException {
        Map<String, Long> out = new LinkedHashMap<>();
        if (limits.isMissingNode() || limits.isNull()) {
            return out;
        }
        if (!limits.isObject()) {
            throw protocol("implementation.limits must be an object of integers");
        }
        for (Map.Entry<String, JsonNode> limit : limits.properties()) {
            if (!limit.getValue().canConvertToExactIntegral() || !limit.getValue().canConvertToLong()) {
                throw protocol("implementation.limits." + limit.getKey() + " must be an integer");
            }
            out.put(limit.getKey(), limit.getValue().asLong());
        }
        return out;
    }

    static LoadOutcome loadOutcome(JsonNode reply) throws IutException {
        if (reply.get("ok").asBoolean()) {
            List<String> blocks = new ArrayList<>();
            for (JsonNode block : array(reply.path("blocks"), "blocks")) {
                if (!block.isTextual()) {
                    throw protocol("blocks must be a list of function block names");
                }
                blocks.add(block.asText());
            }
            return new LoadOutcome.Loaded(blocks);
        }
        JsonNode error = error(reply, "load");
        internalFailure(error, "load");
        if (!"rejected".equals(error.path("kind").asText())) {
            throw protocol("a failed load must have error kind 'rejected', not '" + error.path("kind").asText() + "'");
        }
        return new LoadOutcome.Rejected(message(error), line(error.path("line")));
    }

    private static OptionalInt line(JsonNode line) throws IutException {
        if (line.isMissingNode() || line.isNull()) {
            return OptionalInt.empty();
        }
        if (!line.canConvertToExactIntegral() || !line.canConvertToInt() || line.asInt() < 1) {
            throw protocol("error.line must be a positive integer, not " + line);
        }
        return OptionalInt.of(line.asInt());
    }

    static Map<String, Double> outputs(JsonNode reply) throws IutException {
        failOnError(reply, "eval");
        JsonNode outputs = reply.path("outputs");
        if (!outputs.isObject()) {
            throw protocol("the reply to 'eval' has no 'outputs' object");
        }
        Map<String, Double> values = new LinkedHashMap<>();
        Set<String> seen = new java.util.HashSet<>();
        for (Map.Entry<String, JsonNode> output : outputs.properties()) {
            String name = IutText.kept(output.getKey());
            if (!output.getValue().isNumber()) {
                throw protocol("output " + name + " is not a number: " + IutText.kept(output.getValue().toString()));
            }
            if (!seen.add(name.toLowerCase(Locale.ROOT))) {
                // two names longer than what is kept, alike in what is kept: which value is which is unknowable
                throw protocol("the reply to 'eval' is ambiguous: two output names are the same as kept: " + name);
            }
            values.put(name, output.getValue().asDouble());
        }
        return values;
    }

    static void plain(JsonNode reply, String op) throws IutException {
        failOnError(reply, op);
    }

    static Optional<String> exported(JsonNode reply) throws IutException {
        if (!reply.get("ok").asBoolean() && "unsupported".equals(error(reply, "export").path("kind").asText())) {
            return Optional.empty();
        }
        failOnError(reply, "export");
        return Optional.of(IutText.wellFormed(text(reply, "fcl", "export")));
    }

    /**
     * The first key of an object in the reply (at any depth) that equals an earlier key of the same object
     * but for case, as in {@code {"y":60,"Y":12345}}: FCL names are case-insensitive, so the reply names
     * one output twice. Exact duplicates are already refused by the parser ({@link #mapper}).
     */
    static Optional<String> caseCollision(JsonNode node) {
        if (node.isObject()) {
            Set<String> seen = new java.util.HashSet<>();
            for (Map.Entry<String, JsonNode> field : node.properties()) {
                if (!seen.add(field.getKey().toLowerCase(Locale.ROOT))) {
                    return Optional.of(field.getKey());
                }
                Optional<String> inner = caseCollision(field.getValue());
                if (inner.isPresent()) {
                    return inner;
                }
            }
        } else if (node.isArray()) {
            for (JsonNode item : node) {
                Optional<String> inner = caseCollision(item);
                if (inner.isPresent()) {
                    return inner;
                }
            }
        }
        return Optional.empty();
    }

    /** An {@code ok:false} reply of kind {@code error} becomes an evaluation error; other kinds are faults. */
    private static void failOnError(JsonNode reply, String op) throws IutException {
        if (reply.get("ok").asBoolean()) {
            return;
        }
        JsonNode error = error(reply, op);
        internalFailure(error, op);
        String kind = error.path("kind").asText();
        if (!"error".equals(kind)) {
            throw protocol("a failed '" + op + "' must have error kind 'error', not '" + kind + "'");
        }
        throw new IutException(IutException.Kind.EVAL_ERROR, "the IUT reported an error on '" + op + "': " + message(error));
    }

    /**
     * Kind {@code crash}, for any request: the implementation failed inside (an adapter caught an exception
     * that is a bug of the library, not a refusal). Recorded as a crash; the session goes on.
     */
    private static void internalFailure(JsonNode error, String op) throws IutException {
        if ("crash".equals(error.path("kind").asText())) {
            throw new IutException(IutException.Kind.CRASH, "the implementation failed internally on '" + op + "': "
                    + message(error));
        }
    }

    private static void requireOk(JsonNode reply, String op) throws IutException {
        if (!reply.get("ok").asBoolean()) {
            throw protocol("the IUT refused '" + op + "': " + message(reply.path("error")));
        }
    }

    private static JsonNode error(JsonNode reply, String op) throws IutException {
        JsonNode error = reply.path("error");
        if (!error.isObject() || !error.path("kind").isTextual()) {
            throw protocol("a failed '" + op + "' must carry an error object with a 'kind'");
        }
        return error;
    }

    private static String message(JsonNode error) {
        JsonNode message = error.path("message");
        return message.isTextual() ? message.asText() : "(no message)";   // kept where it lands (Rejected, IutException)
    }

    private static String text(JsonNode node, String field, String op) throws IutException {
        JsonNode value = node.path(field);
        if (!value.isTextual()) {
            throw protocol("the reply to '" + op + "' has no text field '" + field + "'");
        }
        return value.asText();
    }

    private static Iterable<JsonNode> array(JsonNode node, String field) throws IutException {
        if (!node.isArray()) {
            throw protocol("'" + field + "' must be a list");
        }
        return node;
    }

    private static Iterable<JsonNode> arrayOrEmpty(JsonNode node, String field) throws IutException {
        return node.isMissingNode() || node.isNull() ? List.of() : array(node, field);
    }

    static IutException protocol(String message) {
        return new IutException(IutException.Kind.PROTOCOL, message);
    }
}
