package org.fclcert.iut;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * An implementation that writes down, as the JSON-lines protocol's requests, every call made to the one it
 * wraps. A case's transcript ({@link #transcript()}, from {@code hello} to {@code bye}) can then be piped
 * into a process IUT by hand to replay exactly what the harness asked ({@code docs/iut-protocol.md}), whatever
 * kind of implementation was certified.
 */
public final class RecordingIut extends ForwardingIut {
    private final ObjectMapper mapper = Protocol.mapper();
    private final List<ObjectNode> requests = new ArrayList<>();

    public RecordingIut(ImplementationUnderTest inner) {
        super(inner);
    }

    /** Forgets what was recorded (a new case starts). */
    public void clear() {
        requests.clear();
    }

    /**
     * The requests recorded since the last {@link #clear()}, framed as a session: {@code hello} first,
     * {@code bye} last, ids growing from 1; one JSON object per line, each ended by {@code \n}.
     */
    public String transcript() {
        List<ObjectNode> session = new ArrayList<>();
        session.add(Protocol.request("hello"));
        session.addAll(requests);
        session.add(Protocol.request("bye"));
        StringBuilder text = new StringBuilder();
        int id = 0;
        for (ObjectNode request : session) {
            ObjectNode framed = Protocol.request(request.get("op").asText()).put("id", ++id);
            request.fields().forEachRemaining(f -> {
                if (!f.getKey().equals("op") && !f.getKey().equals("id")) {
                    framed.set(f.getKey(), f.getValue());
                }
            });
            try {
                text.append(mapper.writeValueAsString(framed)).append('\n');
            } catch (JsonProcessingException e) {
                throw new IllegalStateException("a request built from JSON nodes always writes", e);
            }
        }
        return text.toString();
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        requests.add(Protocol.load(fcl));
        return delegate().load(fcl);
    }

    @Override
    public LoadOutcome loadWritten(String text, org.fclcert.syntax.dialect.Dialect layout) throws IutException {
        requests.add(Protocol.load(text));
        return delegate().loadWritten(text, layout);   // the reference reads a written text in its layout
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        try {
            requests.add(Protocol.eval(block, inputs));
        } catch (IutException e) {
            // an input that is no JSON number is not sent over the protocol either; the inner IUT decides
        }
        return delegate().eval(block, inputs);
    }

    @Override
    public void reset() throws IutException {
        requests.add(Protocol.request("reset"));
        delegate().reset();
    }

    @Override
    public Optional<String> export() throws IutException {
        requests.add(Protocol.request("export"));
        return delegate().export();
    }
}
