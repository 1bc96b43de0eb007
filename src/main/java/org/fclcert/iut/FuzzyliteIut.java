package org.fclcert.iut;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.OptionalLong;
import java.util.stream.Stream;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.model.Names;
import org.fclcert.sandbox.Isolation;
import org.fclcert.sandbox.Sandbox;

/**
 * fuzzylite 6.0 (GPL-3, C++) as an implementation under test, driven through its command line as a
 * separate process and never linked. It gets the program text exactly as sent — no translation into its
 * dialect — so the certification measures what the tool does with standard FCL.
 *
 * <p>The command line always exits with 0 and writes its errors to standard output; {@link #load} therefore
 * imports the program and exports it as FLL, and counts any message (or a missing FLL file) as a rejection,
 * with the line the message names. fuzzylite keeps no session: each {@link #eval} is one launch that
 * evaluates every input row given since the last load or reset, in order, on one engine, and answers with
 * the last row — the engine's own state (such as {@code NC}, its "lock previous value") then carries over
 * exactly as on one instance. Inputs a step does not set keep their previous value (at first 0, the
 * initial value of a REAL). See {@code docs/iut-protocol.md}, "fuzzylite".
 */
final class FuzzyliteIut implements ImplementationUnderTest {
    static final String SPEC = "fuzzylite";
    static final String DEFAULT_BINARY = "fuzzylite";
    /** Decimals fuzzylite writes after the point: enough for 1e-9 relative agreement at any magnitude in use. */
    private static final String DECIMALS = "17";

    private final String spec;
    private final String binary;
    private final IutOptions options;
    private final Sandbox sandbox;

    private IutInfo info;
    private Boolean measureMemory;
    private Path workDir;
    private String program;
    private FuzzyliteText.Engine engine;
    private double[] current;
    private final List<double[]> history = new ArrayList<>();
    private long peakRss = -1;
    private int timeouts;

    FuzzyliteIut(String spec, String binary, IutOptions options) {
        this.spec = spec;
        this.binary = binary;
        this.options = options;
        this.sandbox = Sandbox.of(options.sandbox());
    }

    @Override
    public Isolation isolation() {
        return sandbox.isolation();
    }

    /** {@code fuzzylite} or {@code fuzzylite:PATH}. */
    static FuzzyliteIut open(String spec, IutOptions options) throws IutException {
        String rest = spec.substring(SPEC.length());
        if (rest.isEmpty()) {
            return new FuzzyliteIut(spec, DEFAULT_BINARY, options);
        }
        String path = rest.startsWith(":") ? rest.substring(1).strip() : "";
        if (path.isEmpty()) {
            throw new IutException(Kind.INFRA, "malformed implementation under test '" + spec
                    + "': use fuzzylite or fuzzylite:PATH-TO-BINARY");
        }
        return new FuzzyliteIut(spec, path, options);
    }

    @Override
    public IutInfo hello() throws IutException {
        if (info == null) {
            FuzzyliteProcess.Run run = launch(List.of(binary, "--help"), false);
            String banner = run.stdout() + run.stderr();
            String version = FuzzyliteText.version(banner).orElseThrow(() -> new IutException(Kind.INFRA,
                    binary + " --help does not name a version ('version: …'); is it fuzzylite? It printed: "
                            + quote(FuzzyliteText.firstMessage(banner))));
            info = new IutInfo("fuzzylite", version, spec, List.of(), Map.of());
        }
        return info;
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        hello();
        program = null;
        engine = null;
        history.clear();
        Path source = file("program.fcl");
        Path fll = file("program.fll");
        write(source, fcl);
        delete(fll);
        FuzzyliteProcess.Run run = launch(List.of(binary, "-i", source.toString(), "-if", "fcl",
                "-of", "fll", "-o", fll.toString()), true);
        crashCheck(run, "loading");
        String message = FuzzyliteText.firstMessage(run.stdout());
        String exported = Files.exists(fll) ? read(fll) : "";
        if (!message.isEmpty() || exported.isBlank()) {
            if (message.isEmpty()) {
                message = "fuzzylite gave no message but built no engine";
            }
            return new LoadOutcome.Rejected("fuzzylite: " + message, FuzzyliteText.line(message, fcl));
        }
        FuzzyliteText.Engine built = FuzzyliteText.engine(exported);
        program = fcl;
        engine = built;
        current = new double[built.inputs().size()];
        return new LoadOutcome.Loaded(List.of(built.name()));
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        requireProgram();
        if (block != null && !Names.same(block, engine.name())) {
            throw new IutException(Kind.EVAL_ERROR, "fuzzylite built only function block '" + engine.name()
                    + "' (it reads the first function block of a program), not '" + block + "'");
        }
        double[] row = current.clone();
        for (Map.Entry<String, Double> input : inputs.entrySet()) {
            int k = indexOf(engine.inputs(), input.getKey());
            if (k < 0) {
                throw new IutException(Kind.EVAL_ERROR, "'" + input.getKey() + "' is not an input of the engine "
                        + "fuzzylite built (its inputs: " + org.fclcert.model.Names.listed(engine.inputs()) + ")");
            }
            row[k] = input.getValue();
        }
        current = row;
        history.add(row);
        FuzzyliteText.Table table = evaluate();
        double[] last = table.rows().get(table.rows().size() - 1);
        Map<String, Double> outputs = new LinkedHashMap<>();
        for (int c = 0; c < last.length; c++) {
            outputs.put(table.names().get(c), last[c]);
        }
        return outputs;
    }

    /** Evaluates every row since the last load or reset in one launch; the table has one row per step. */
    private FuzzyliteText.Table evaluate() throws IutException {
        Path data = file("inputs.fld");
        Path out = file("outputs.fld");
        StringBuilder text = new StringBuilder(String.join(" ", engine.inputs())).append('\n');
        for (double[] row : history) {
            text.append(String.join(" ", Arrays.stream(row).mapToObj(Double::toString).toList())).append('\n');
        }
        write(data, text.toString());
        delete(out);
        FuzzyliteProcess.Run run = launch(List.of(binary, "-i", file("program.fcl").toString(), "-if", "fcl",
                "-of", "fld", "-d", data.toString(), "-o", out.toString(), "-decimals", DECIMALS,
                "-dheader", "true", "-dinputs", "false"), true);
        crashCheck(run, "evaluating");
        String message = FuzzyliteText.firstMessage(run.stdout());
        if (!message.isEmpty()) {
            throw new IutException(Kind.EVAL_ERROR, "fuzzylite: " + message, run.stderr());
        }
        String written = Files.exists(out) ? read(out) : "";
        FuzzyliteText.Table table;
        try {
            table = FuzzyliteText.table(written);
        } catch (IllegalArgumentException e) {
            throw new IutException(Kind.PROTOCOL, "fuzzylite's output table cannot be read: " + e.getMessage()
                    + " (" + quote(written) + ")", run.stderr());
        }
        if (table.rows().size() != history.size()) {
            throw new IutException(Kind.PROTOCOL, "fuzzylite wrote " + table.rows().size() + " result rows for "
                    + history.size() + " input rows, without an error message", run.stderr());
        }
        return table;
    }

    @Override
    public void reset() throws IutException {
        requireProgram();
        history.clear();
        current = new double[engine.inputs().size()];
    }

    @Override
    public Optional<String> export() throws IutException {
        requireProgram();
        Path out = file("export.fcl");
        delete(out);
        FuzzyliteProcess.Run run = launch(List.of(binary, "-i", file("program.fcl").toString(), "-if", "fcl",
                "-of", "fcl", "-o", out.toString(), "-decimals", DECIMALS), true);
        crashCheck(run, "exporting");
        String message = FuzzyliteText.firstMessage(run.stdout());
        if (!message.isEmpty()) {
            throw new IutException(Kind.EVAL_ERROR, "fuzzylite: " + message, run.stderr());
        }
        String text = Files.exists(out) ? read(out) : "";
        if (text.isBlank()) {
            throw new IutException(Kind.EVAL_ERROR, "fuzzylite wrote no FCL and gave no message", run.stderr());
        }
        return Optional.of(text);
    }

    @Override
    public OptionalLong peakMemoryBytes() {
        return peakRss < 0 ? OptionalLong.empty() : OptionalLong.of(peakRss);
    }

    @Override
    public void close() {
        if (workDir == null) {
            return;
        }
        try (Stream<Path> files = Files.walk(workDir)) {
            files.sorted(Comparator.reverseOrder()).forEach(FuzzyliteIut::delete);
        } catch (IOException | RuntimeException e) {
            // a temporary directory left behind is harmless
        }
        workDir = null;
    }

    private void requireProgram() throws IutException {
        if (engine == null) {
            throw new IutException(Kind.EVAL_ERROR, "no program is loaded");
        }
    }

    /**
     * One launch under the per-request timeout. A timeout counts against the restart budget: once more
     * launches than the budget allows have timed out, every request fails at once, so a hanging tool cannot
     * stall the run.
     */
    private FuzzyliteProcess.Run launch(List<String> command, boolean measure) throws IutException {
        if (timeouts > options.restartBudget()) {
            throw new IutException(Kind.GAVE_UP, timeouts + " launches of fuzzylite timed out (the restart budget is "
                    + options.restartBudget() + ")");
        }
        Path rss = measure && memoryMeasurable() ? file("rss.txt") : null;
        try {
            List<Path> writable = workDir == null ? List.of() : List.of(workDir);
            FuzzyliteProcess.Run run = FuzzyliteProcess.run(command, rss, options.timeout(), options.stderrTailBytes(),
                    sandbox, writable);
            run.peakRssBytes().ifPresent(bytes -> peakRss = Math.max(peakRss, bytes));
            return run;
        } catch (IutException e) {
            if (e.kind() == Kind.TIMEOUT) {
                timeouts++;
            }
            throw e;
        }
    }

    private boolean memoryMeasurable() {
        if (measureMemory == null) {
            measureMemory = FuzzyliteProcess.gnuTimeAvailable(options.timeout());
        }
        return measureMemory;
    }

    /** A non-zero exit is a crash (fuzzylite itself always exits with 0, even after an error). */
    private void crashCheck(FuzzyliteProcess.Run run, String what) throws IutException {
        if (run.exitCode() != 0) {
            String said = FuzzyliteText.firstMessage(run.stdout());
            throw new IutException(Kind.CRASH, "fuzzylite exited with code " + run.exitCode() + " while " + what
                    + (run.exitCode() > 128 ? " (killed by signal " + (run.exitCode() - 128) + ")" : "")
                    + sandbox.limitHit(run.exitCode()).map(s -> "; " + s).orElse("")
                    + (said.isEmpty() ? "" : "; it wrote: " + quote(said)), run.stderr());
        }
    }

    private static int indexOf(List<String> names, String name) {
        for (int k = 0; k < names.size(); k++) {
            if (Names.same(names.get(k), name)) {
                return k;
            }
        }
        return -1;
    }

    private Path file(String name) throws IutException {
        if (workDir == null) {
            try {
                workDir = Files.createTempDirectory("fclcert-fuzzylite-");
                sandbox.grantWrite(workDir);
            } catch (IOException e) {
                throw new IutException(Kind.INFRA, "cannot create a temporary directory for fuzzylite's files: "
                        + e.getMessage());
            }
        }
        return workDir.resolve(name);
    }

    private static void write(Path path, String text) throws IutException {
        try {
            Files.writeString(path, text, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IutException(Kind.INFRA, "cannot write " + path + " for fuzzylite: " + e.getMessage());
        }
    }

    /** A file fuzzylite wrote, at most {@link IutOptions#maxReplyBytes()} long, as a process IUT's reply line is. */
    private String read(Path path) throws IutException {
        try (java.io.InputStream in = Files.newInputStream(path)) {
            byte[] bytes = in.readNBytes(options.maxReplyBytes() + 1);
            if (bytes.length > options.maxReplyBytes()) {
                throw new IutException(Kind.PROTOCOL, "fuzzylite wrote more than " + options.maxReplyBytes()
                        + " bytes to " + path.getFileName() + " (IutOptions.maxReplyBytes)");
            }
            return new String(bytes, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IutException(Kind.INFRA, "cannot read " + path + " written by fuzzylite: " + e.getMessage());
        }
    }

    private static void delete(Path path) {
        try {
            Files.deleteIfExists(path);
        } catch (IOException e) {
            // overwritten or reported missing on the next use
        }
    }

    private static String quote(String text) {
        String oneLine = text.strip();
        return oneLine.length() <= 200 ? oneLine : oneLine.substring(0, 200) + "…";
    }
}
