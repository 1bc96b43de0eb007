package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * Coverage-guided fuzzing (Jazzer) of the protocol reply reader: the bytes are what a process IUT writes to its
 * standard output. {@link ReplyReader} frames them into lines (a line beyond the cap is reported as too long,
 * never kept), and each line is read as the reply to every request ({@link Protocol#reply} and the reading of
 * that request's reply). Properties: one event per newline (and "too long" for a last line beyond the cap that
 * has none), no line longer than the cap; a reply is read or is
 * an {@link IutException} of the kinds a reply can cause, never another exception; whatever is kept of the
 * IUT's strings is well-formed UTF-16 (so results can always be written) and within {@link IutText#MAX_KEPT_BYTES}
 * (plus the truncation marker); output names are distinct but for case. docs/fuzzing-readers.md says how to
 * fuzz for a budget.
 */
class ReplyFuzzTest {
    /** A small cap, so that the fuzzer reaches "too long" with short inputs; the real one is 16 MiB. */
    private static final int CAP = 2048;
    private static final ObjectMapper MAPPER = Protocol.mapper();
    private static final long ID = 7;

    @FuzzTest(maxDuration = "10m")
    void replyReader(byte[] stdout) throws Exception {
        ReplyReader reader = new ReplyReader(new ByteArrayInputStream(stdout), CAP, "fuzz-stdout");
        int newlines = 0;
        int tail = 0;   // bytes after the last newline
        for (byte b : stdout) {
            newlines += b == '\n' ? 1 : 0;
            tail = b == '\n' ? 0 : tail + 1;
        }
        int framed = 0;
        while (true) {
            ReplyReader.Event event = reader.next(TimeUnit.SECONDS.toNanos(10));
            assertNotNull(event, "the reader hands over every line and then the end of the stream");
            if (event instanceof ReplyReader.EndOfStream) {
                break;
            }
            framed++;
            if (event instanceof ReplyReader.Line line) {
                assertFalse(line.text().indexOf('\n') >= 0, "a line is one line");
                assertTrue(line.text().length() <= CAP, "a kept line is within the cap");
                readAsEveryReply(line.text());
            } else {
                assertEquals(new ReplyReader.TooLong(CAP), event);
            }
        }
        // a last line without its newline is not a reply (the IUT never finished writing it), unless it is already
        // too long: that is said at once, so that the IUT can be killed without waiting for the rest
        assertEquals(newlines + (tail > CAP ? 1 : 0), framed, "one line or 'too long' per newline");
    }

    private static void readAsEveryReply(String text) {
        for (String op : List.of("hello", "load", "eval", "reset", "export")) {
            try {
                JsonNode reply = Protocol.reply(MAPPER, text, op, ID);
                assertTrue(reply.isObject() && reply.get("ok").isBoolean());
                switch (op) {
                    case "hello" -> {
                        IutInfo info = Protocol.info(reply, "fuzz");
                        kept(info.name());
                        kept(info.version());
                        info.claims().forEach(ReplyFuzzTest::kept);
                        info.declaredLimits().keySet().forEach(ReplyFuzzTest::kept);
                    }
                    case "load" -> {
                        LoadOutcome outcome = Protocol.loadOutcome(reply);
                        if (outcome instanceof LoadOutcome.Loaded l) {
                            l.blocks().forEach(ReplyFuzzTest::kept);
                        } else if (outcome instanceof LoadOutcome.Rejected r) {
                            kept(r.message());
                            r.line().ifPresent(n -> assertTrue(n >= 1));
                        }
                    }
                    case "eval" -> {
                        Map<String, Double> outputs = Protocol.outputs(reply);
                        Set<String> names = new HashSet<>();
                        for (String name : outputs.keySet()) {
                            kept(name);
                            assertTrue(names.add(name.toLowerCase(Locale.ROOT)), "output names distinct but for case");
                        }
                    }
                    case "reset" -> Protocol.plain(reply, "reset");
                    default -> Protocol.exported(reply).ifPresent(ReplyFuzzTest::wellFormed);
                }
            } catch (IutException e) {
                assertTrue(e.kind() == IutException.Kind.PROTOCOL || e.kind() == IutException.Kind.EVAL_ERROR
                        || e.kind() == IutException.Kind.CRASH, e.kind() + ": " + e.getMessage());
                kept(e.getMessage());
            }
        }
    }

    private static void kept(String s) {
        wellFormed(s);
        assertTrue(s.getBytes(StandardCharsets.UTF_8).length <= IutText.MAX_KEPT_BYTES + 64,
                () -> "kept text beyond the cap: " + s.length() + " characters");
    }

    private static void wellFormed(String s) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (Character.isHighSurrogate(c)) {
                assertTrue(i + 1 < s.length() && Character.isLowSurrogate(s.charAt(i + 1)), "a lone high surrogate");
                i++;
            } else {
                assertFalse(Character.isLowSurrogate(c), "a lone low surrogate");
            }
        }
    }
}
