package org.fclcert.iut;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalLong;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.sandbox.Isolation;
import org.fclcert.sandbox.Sandbox;

/**
 * An IUT that is a separate process speaking JSON lines ({@code docs/iut-protocol.md}).
 *
 * <p>The process is started on the first request and greeted with {@code hello}. After a crash, a
 * timeout or a protocol fault it is killed (with its child processes) and the failing request throws;
 * the next request starts it again, greets it, and — unless that request is itself a {@code load} —
 * replays the last program it had accepted. A breakdown costs only the request that caused it; the
 * {@link RestartPolicy} says when the implementation is given up instead, after which every request fails
 * with {@link Kind#GAVE_UP}.
 */
final class ProcessIut implements ImplementationUnderTest {
    private static final long STDERR_WAIT_MILLIS = 500;
    private static final Duration BYE_WAIT = Duration.ofSeconds(1);
    /** A fresh process gets at least this long for its first reply: interpreters and JVMs start slowly. */
    static final Duration STARTUP_TIMEOUT = Duration.ofSeconds(10);

    private final String spec;
    private final List<String> command;
    private final IutOptions options;
    private final ObjectMapper mapper = Protocol.mapper();
    private final Sandbox sandbox;
    /** CPU time of the process tree at the last reply (or start): what one request's CPU is counted from. */
    private Duration cpuMark = Duration.ZERO;

    private ProcessSession session;
    private final RestartPolicy policy;
    private IutInfo info;
    private String acceptedProgram;
    private long nextId;
    private long peakRss = -1;
    private OptionalDouble lastElapsed = OptionalDouble.empty();

    ProcessIut(String spec, List<String> command, IutOptions options) {
        this.spec = spec;
        this.command = List.copyOf(command);
        this.options = options;
        this.sandbox = Sandbox.of(options.sandbox());
        this.policy = new RestartPolicy(options.restartBudget());
    }

    @Override
    public Isolation isolation() {
        return sandbox.isolation();
    }

    @Override
    public IutInfo hello() throws IutException {
        try {
            ensureRunning(false);
        } catch (IutException e) {
            throw counted(e);
        }
        return info;
    }

    @Override
    public IutHealth health() {
        return policy.health();
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        acceptedProgram = null;
        LoadOutcome outcome = call(Protocol.load(fcl), Protocol::loadOutcome, false);
        if (outcome instanceof LoadOutcome.Loaded) {
            acceptedProgram = fcl;
        }
        return outcome;
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        lastElapsed = OptionalDouble.empty();
        return call(Protocol.eval(block, inputs), reply -> {
            JsonNode elapsed = reply.path("elapsedMs");
            if (elapsed.isNumber() && Double.isFinite(elapsed.asDouble()) && elapsed.asDouble() >= 0) {
                lastElapsed = OptionalDouble.of(elapsed.asDouble());
            }
            return Protocol.outputs(reply);
        }, true);
    }

    @Override
    public OptionalDouble lastEvalMillis() {
        return lastElapsed;
    }

    @Override
    public void reset() throws IutException {
        call(Protocol.request("reset"), reply -> {
            Protocol.plain(reply, "reset");
            return null;
        }, true);
    }

    @Override
    public Optional<String> export() throws IutException {
        JsonNode reply = call(Protocol.request("export"), r -> r, true);
        try {
            return Protocol.exported(reply);
        } catch (IutException e) {
            // a well-formed reply with our id but without 'fcl': the process is still in step, so it is not
            // killed (a restart would spend the restart budget on a missing optional feature)
            throw new IutException(e.kind(), e.getMessage(), stderrTail());
        }
    }

    @Override
    public OptionalLong peakMemoryBytes() {
        sampleMemory();
        return peakRss < 0 ? OptionalLong.empty() : OptionalLong.of(peakRss);
    }

    /** The end of the current process's standard error (empty when none runs). */
    String stderrTail() {
        return session == null ? "" : session.stderrTail(0);
    }

    @Override
    public void close() {
        if (session == null) {
            return;
        }
        try {
            sampleMemory();
            if (session.isAlive()) {
                sayBye();
            }
        } catch (RuntimeException e) {
            // closing must not fail: the kill below ends whatever is left
        } finally {
            session.kill();
            session = null;
        }
    }

    private void sayBye() {
        ObjectNode bye = Protocol.request("bye").put("id", ++nextId);
        session.send(write(bye));
        try {
            session.next(BYE_WAIT.toNanos());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        session.closeInput();
        session.exitCode(BYE_WAIT.toMillis());
    }

    private interface Reading<T> {
        T read(JsonNode reply) throws IutException;
    }

    private <T> T call(ObjectNode request, Reading<T> reading, boolean replay) throws IutException {
        try {
            ensureRunning(replay);
            JsonNode reply = exchange(request);
            T value;
            try {
                value = reading.read(reply);
            } catch (IutException e) {
                if (e.kind() == Kind.PROTOCOL) {
                    throw fail(Kind.PROTOCOL, e.getMessage());
                }
                policy.answered();
                throw new IutException(e.kind(), e.getMessage(), stderrTail());
            }
            policy.answered();
            return value;
        } catch (IutException e) {
            throw counted(e);
        }
    }

    /** Counts a request that broke the implementation down (its process was killed) for the restart policy. */
    private IutException counted(IutException e) {
        if (e.kind() == Kind.CRASH || e.kind() == Kind.TIMEOUT || e.kind() == Kind.PROTOCOL) {
            policy.brokeDown(e.getMessage());
        }
        return e;
    }

    /** Starts the process if none runs (greeting it, and replaying the accepted program if asked). */
    private void ensureRunning(boolean replay) throws IutException {
        if (policy.gaveUp() != null) {
            throw new IutException(Kind.GAVE_UP, "given up: " + policy.gaveUp());
        }
        if (session != null && session.isAlive()) {
            return;
        }
        if (session != null) {
            // an exit between requests is no request's fault: the restart below is counted, not a crash
            session.kill();
            session = null;
        }
        start();
        try {
            info = greet();
        } catch (IutException e) {
            policy.helloFailed(e.getMessage());
            throw e;
        }
        policy.helloAnswered();
        if (replay && acceptedProgram != null) {
            exchange(Protocol.load(acceptedProgram));
        }
    }

    private void start() throws IutException {
        IutHealth before = policy.health();
        try {
            session = ProcessSession.start(command, sandbox, options, before.restarts() + 1);
            cpuMark = Duration.ZERO;
        } catch (IOException e) {
            throw new IutException(Kind.INFRA, "could not start " + command + ": " + e.getMessage());
        }
        policy.started();
    }

    private IutInfo greet() throws IutException {
        Duration patience = options.timeout().compareTo(STARTUP_TIMEOUT) > 0 ? options.timeout() : STARTUP_TIMEOUT;
        JsonNode reply = exchange(Protocol.request("hello"), patience);
        try {
            return Protocol.info(reply, spec);
        } catch (IutException e) {
            throw fail(Kind.PROTOCOL, e.getMessage());
        }
    }

    /** Sends one request and waits for its reply line: a JSON object with a boolean {@code ok} and our id. */
    private JsonNode exchange(ObjectNode request) throws IutException {
        return exchange(request, options.timeout());
    }

    private JsonNode exchange(ObjectNode request, Duration timeout) throws IutException {
        long id = ++nextId;
        String op = request.get("op").asText();
        long sentAt = System.nanoTime();
        session.send(write(request.put("id", id)));
        long deadline = sentAt + timeout.toNanos();
        while (true) {
            ReplyReader.Event event = nextEvent(deadline, op, timeout);
            if (event instanceof ReplyReader.Line line && !line.text().isBlank()) {
                if (line.readAt() < sentAt) {
                    // a reply written before the question (say an eval answer sent along with the load reply) is no
                    // answer: read from the pipe before the request went out, whether or not it was handed over yet
                    throw fail(Kind.PROTOCOL, "the IUT wrote a line before '" + op + "' was sent, unasked: "
                            + Protocol.quote(line.text()));
                }
                checkCpu(op);
                return parse(line.text(), op, id);
            }
            if (event instanceof ReplyReader.EndOfStream) {
                throw fail(Kind.CRASH, "the IUT exited while answering '" + op + "'" + exitNote(session.exitCode(1000)));
            }
            if (event instanceof ReplyReader.WriteFailed failed) {
                throw fail(Kind.CRASH, "could not send '" + op + "' to the IUT (" + failed.reason() + ")"
                        + exitNote(session.exitCode(1000)));
            }
            if (event instanceof ReplyReader.TooLong tooLong) {
                throw fail(Kind.PROTOCOL, "the reply to '" + op + "' is longer than " + tooLong.limit() + " bytes");
            }
        }
    }

    private ReplyReader.Event nextEvent(long deadline, String op, Duration timeout) throws IutException {
        long left = deadline - System.nanoTime();
        try {
            ReplyReader.Event event = left > 0 ? session.next(left) : null;
            if (event == null) {
                throw fail(Kind.TIMEOUT, "no reply to '" + op + "' within " + timeout.toMillis() + " ms");
            }
            return event;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw fail(Kind.INFRA, "interrupted while waiting for the reply to '" + op + "'");
        }
    }

    private JsonNode parse(String text, String op, long id) throws IutException {
        try {
            return Protocol.reply(mapper, text, op, id);
        } catch (IutException e) {
            throw fail(e.kind(), e.getMessage());
        }
    }

    /** Kills the process after a failure and builds the exception, with the end of its stderr. */
    private IutException fail(Kind kind, String message) {
        String tail = "";
        if (session != null) {
            sampleMemory();
            session.kill();
            tail = session.stderrTail(STDERR_WAIT_MILLIS);
            session = null;
        }
        return new IutException(kind, message, tail);
    }

    private void sampleMemory() {
        if (session != null && session.isAlive()) {
            session.peakRss().ifPresent(rss -> peakRss = Math.max(peakRss, rss));
        }
    }

    private String write(ObjectNode request) {
        try {
            return mapper.writeValueAsString(request);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a request tree always serialises", e);
        }
    }

    private String exitNote(OptionalLong exitCode) {
        if (exitCode.isEmpty()) {
            return "";
        }
        return " (" + ExitStatus.describe(exitCode.getAsLong()) + sandbox.limitHit(exitCode.getAsLong())
                .map(s -> ": " + s).orElse("") + ")";
    }

    /**
     * The CPU time the process tree spent since the last reply (this request, and whatever ran between requests)
     * against the sandbox's per-request limit; over it, the IUT is killed like one that timed out.
     */
    private void checkCpu(String op) throws IutException {
        if (!sandbox.active()) {
            return;
        }
        Duration now = session.cpuTime();
        Duration used = now.minus(cpuMark);
        cpuMark = now;
        if (used.compareTo(sandbox.limits().cpuPerRequest()) > 0) {
            throw fail(Kind.TIMEOUT, "the IUT used " + used.toMillis() + " ms of CPU time on '" + op
                    + "', more than the sandbox's limit of " + sandbox.limits().cpuPerRequest().toMillis()
                    + " ms per request");
        }
    }

}
