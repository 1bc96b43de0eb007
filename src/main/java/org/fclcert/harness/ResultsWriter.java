package org.fclcert.harness;

import org.fclcert.probe.DataCheckEntry;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedWriter;
import java.io.Closeable;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Writes {@code results.jsonl}: a {@code "type":"run"} header line, then one {@code "type":"case"} line per
 * finished case (and a {@code "type":"dataCheckList"} line when probes ran), each flushed at once so that a
 * killed run leaves every finished case on disk.
 */
public final class ResultsWriter implements ResultSink, Closeable {
    /** The name of the results file in a run's output directory. */
    public static final String FILE_NAME = "results.jsonl";

    private final BufferedWriter out;
    private final ResultsChain chain = new ResultsChain();
    private ResultsChain.Seal seal;

    private ResultsWriter(BufferedWriter out) {
        this.out = out;
    }

    public static ResultsWriter create(Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        return new ResultsWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8));
    }

    @Override
    public void header(RunHeader header) throws IOException {
        write("run", header);
    }

    @Override
    public void accept(CaseResult result) throws IOException {
        write("case", result);
    }

    @Override
    public void dataCheckList(List<DataCheckEntry> entries) throws IOException {
        write("dataCheckList", new DataCheckLine(entries));
    }

    /** The body of a {@code "type":"dataCheckList"} line. */
    record DataCheckLine(List<DataCheckEntry> entries) {
    }

    private void write(String type, Object value) throws IOException {
        ObjectNode line = Json.mapper().createObjectNode();
        line.put("type", type);
        line.setAll((ObjectNode) Json.mapper().valueToTree(value));
        writeChained(line);
    }

    /** Writes a line carrying the hash of the line before it ({@link ResultsChain}). */
    private void writeChained(ObjectNode line) throws IOException {
        if (seal != null) {
            throw new IOException("the results are sealed: the run's end line is written");
        }
        line.put("prev", chain.head());
        String text = Json.mapper().writeValueAsString(line);
        out.write(text);
        out.write('\n');
        out.flush();
        chain.append(text);
    }

    /**
     * Writes the run's end line, {@code {"type":"end", "digest":…, "endedAt":…}}, and returns the seal; nothing can
     * be written after it. Called once every case (and the probes) finished; a run cut short has no end line.
     */
    public ResultsChain.Seal finish(String endedAt) throws IOException {
        ResultsChain.Seal s = chain.seal(endedAt);
        ObjectNode line = Json.mapper().createObjectNode();
        line.put("type", ResultsChain.END);
        line.put("digest", s.digest());
        line.put("endedAt", endedAt);
        writeChained(line);
        seal = s;
        return s;
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}
