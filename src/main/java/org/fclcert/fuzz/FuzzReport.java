package org.fclcert.fuzz;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.fclcert.eval.EvaluationException;
import org.fclcert.model.Feature;

/**
 * The files of a fuzz run in its output directory: one corpus case file per distinct finding (named by the
 * feature it isolates, numbered per prefix: {@code E-ACCU-NSUM-001.fcl}), {@code fuzz.json} (the machine
 * summary) and {@code fuzz.md} (the same for people).
 */
public final class FuzzReport {
    public static final String JSON = "fuzz.json";
    public static final String MARKDOWN = "fuzz.md";

    /** A finding as written: its case id and file. */
    public record Written(Finding finding, String id, Path file, int programLines) {
    }

    private FuzzReport() {
    }

    /**
     * Writes everything; returns the case files in finding order. When the run presented programs in a library's
     * layout, each case's text as sent goes to {@code as-<layout>/<id>.fcl} beside it (a subdirectory, so that
     * {@code fclcert corpus add DIR/*.fcl} takes only the standard cases).
     */
    public static List<Written> write(Fuzzer.Result result, Path dir) throws IOException {
        Files.createDirectories(dir);
        List<Written> written = new ArrayList<>();
        Map<String, Integer> numbers = new HashMap<>();
        Presentation presentation = new Presentation(result.options().layout());
        for (Finding f : result.findings()) {
            String prefix = CaseFiles.prefix(f);
            int n = numbers.merge(prefix, 1, Integer::sum);
            String id = prefix + String.format(Locale.ROOT, "-%03d", n);
            Path file = dir.resolve(id + ".fcl");
            try {
                Optional<Presentation.Sent> sent = result.options().layout().isEmpty() ? Optional.empty()
                        : presentation.present(f.minimal().program(), new ReferenceProgram(f.minimal().program())
                                .run(f.minimal().steps())).sent();
                Optional<String> sentAs = Optional.empty();
                if (sent.isPresent()) {
                    String layout = sent.get().layout().orElseThrow().cliName();
                    Path as = dir.resolve("as-" + layout).resolve(id + ".fcl");
                    Files.createDirectories(as.getParent());
                    Files.writeString(as, sent.get().text(), StandardCharsets.UTF_8);
                    sentAs = Optional.of(dir.relativize(as).toString());
                }
                Files.writeString(file, CaseFiles.text(f, id, result.iut().name(), sent, sentAs), StandardCharsets.UTF_8);
            } catch (EvaluationException e) {
                throw new IllegalStateException("the reference cannot evaluate a case it judged before: " + e.getMessage(), e);
            }
            written.add(new Written(f, id, file, CaseFiles.programLines(f.minimal().program())));
        }
        ObjectMapper mapper = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
        Files.writeString(dir.resolve(JSON), mapper.writeValueAsString(json(mapper, result, written)) + "\n");
        Files.writeString(dir.resolve(MARKDOWN), markdown(result, written));
        return written;
    }

    static ObjectNode json(ObjectMapper mapper, Fuzzer.Result r, List<Written> written) {
        ObjectNode root = mapper.createObjectNode();
        ObjectNode iut = root.putObject("iut");
        iut.put("name", r.iut().name());
        iut.put("version", r.iut().version());
        iut.put("command", r.iut().command());
        ObjectNode run = root.putObject("run");
        run.put("seed", r.options().seed());
        run.put("budgetSeconds", r.options().budget().toMillis() / 1000.0);
        if (r.options().maxPrograms() > 0) {
            run.put("maxPrograms", r.options().maxPrograms());
        }
        run.put("level", r.options().settings().level().word());
        ArrayNode focus = run.putArray("features");
        r.options().settings().focus().stream().map(Feature::id).sorted().forEach(focus::add);
        run.put("jobs", r.options().jobs());
        run.put("presentAs", r.options().layout().map(l -> l.cliName()).orElse("none"));
        run.put("started", r.started().toString());
        Fuzzer.Progress p = r.progress();
        run.put("elapsedSeconds", p.elapsedMillis() / 1000.0);
        r.stopped().ifPresent(why -> run.put("stopped", why));
        ObjectNode counts = root.putObject("counts");
        counts.put("programs", p.programs());
        counts.put("vectors", p.vectors());
        counts.put("programsPerSecond", Math.round(p.programsPerSecond() * 10) / 10.0);
        counts.put("vectorsPerSecond", Math.round(p.vectorsPerSecond() * 10) / 10.0);
        counts.put("disagreements", p.disagreements());
        counts.put("findings", written.size());
        counts.put("unexplainedDisagreements", r.unexplained());
        counts.put("unfairStepsDropped", p.unfairSteps());
        counts.put("programsWithoutFairSteps", p.programsWithoutSteps());
        counts.put("restarts", p.restarts());
        counts.put("generatorBugs", p.generatorBugs());
        counts.put("notPresentable", p.notPresentable());
        ObjectNode time = root.putObject("time");
        time.put("referenceSeconds", p.referenceMillis() / 1000.0);
        time.put("implementationSeconds", p.implementationMillis() / 1000.0);
        time.put("shrinkSeconds", p.shrinkMillis() / 1000.0);
        ObjectNode why = root.putObject("notPresentable");
        r.notPresentable().forEach(why::put);
        ArrayNode list = root.putArray("findings");
        for (Written w : written) {
            Finding f = w.finding();
            ObjectNode o = list.addObject();
            o.put("id", w.id());
            o.put("file", w.file().getFileName().toString());
            o.put("feature", f.feature().id());
            o.put("kind", f.kind().word());
            o.put("message", f.deviation().message());
            o.put("firstSeen", f.original().message());
            o.put("programIndex", f.programIndex());
            o.put("programSeed", f.programSeed());
            o.put("originalLines", f.originalLines());
            o.put("programLines", w.programLines());
            o.put("shrinkTrials", f.shrinkTrials());
            o.put("foundAfterSeconds", f.foundAfterMillis() / 1000.0);
            o.put("shrinkSeconds", f.shrinkMillis() / 1000.0);
            o.put("duplicates", f.duplicates());
        }
        ArrayNode bugs = root.putArray("generatorBugs");
        r.generatorBugs().forEach(bugs::add);
        ArrayNode infra = root.putArray("infrastructureErrors");
        r.infrastructureErrors().forEach(infra::add);
        ArrayNode faults = root.putArray("presentationFaults");
        r.presentationFaults().forEach(faults::add);
        return root;
    }

    /** Reasons for not presenting, most frequent first: {@code FCL-X104 812, FCL-X102 97}. */
    public static String reasons(Map<String, Long> byReason) {
        return byReason.entrySet().stream().sorted(Map.Entry.<String, Long>comparingByValue().reversed()
                .thenComparing(Map.Entry.comparingByKey())).map(e -> e.getKey() + " " + e.getValue())
                .collect(java.util.stream.Collectors.joining(", "));
    }

    static String markdown(Fuzzer.Result r, List<Written> written) {
        Fuzzer.Progress p = r.progress();
        StringBuilder md = new StringBuilder("# fclcert fuzz: ").append(r.iut().name()).append(' ').append(r.iut().version()).append("\n\n");
        md.append(String.format(Locale.ROOT, "Seed %d, level %s%s, %d job(s), %.1f s: **%d programs, %d vectors** "
                + "(%.1f programs/s, %.1f vectors/s), %d disagreement(s), **%d distinct finding(s)**.%n%n",
                r.options().seed(), r.options().settings().level().word(),
                r.options().settings().focus().isEmpty() ? "" : ", features " + r.options().settings().focus().stream()
                        .map(Feature::id).sorted().toList(),
                r.options().jobs(), p.elapsedMillis() / 1000.0, p.programs(), p.vectors(), p.programsPerSecond(),
                p.vectorsPerSecond(), p.disagreements(), written.size()));
        r.stopped().ifPresent(why -> md.append("**The run was stopped** (").append(why).append(") before its budget"
                + " ran out: these are the findings up to then; a finding being shrunk then is as small as it had got.\n\n"));
        md.append(String.format(Locale.ROOT, "Time of the jobs (summed): %.1f s on the reference side (generating, "
                + "checking, judging and evaluating steps), %.1f s waiting for the implementation, %.1f s on "
                + "disagreements (deduplicating, shrinking).%n%n", p.referenceMillis() / 1000.0,
                p.implementationMillis() / 1000.0, p.shrinkMillis() / 1000.0));
        r.options().layout().ifPresent(l -> md.append("Programs were sent in ").append(l.displayName())
                .append("'s layout (`--present-as ").append(l.cliName()).append("`); ").append(p.notPresentable())
                .append(" generated program(s) were not presentable").append(r.notPresentable().isEmpty() ? ""
                        : " (" + reasons(r.notPresentable()) + ")").append(". Each case's text as sent is in `as-")
                .append(l.cliName()).append("/`.\n\n"));
        if (!written.isEmpty()) {
            md.append("| case | feature | kind | first seen | lines (original → minimal) | same finding again |\n");
            md.append("|---|---|---|---|---|---|\n");
            for (Written w : written) {
                Finding f = w.finding();
                md.append("| [").append(w.id()).append("](").append(w.file().getFileName()).append(") | ")
                        .append(f.feature().id()).append(" | ").append(f.kind().word()).append(" | program ")
                        .append(f.programIndex()).append(" | ").append(f.originalLines()).append(" → ").append(w.programLines())
                        .append(" | ").append(f.duplicates()).append(" |\n");
            }
            md.append('\n');
            for (Written w : written) {
                md.append("- **").append(w.id()).append("**: ").append(w.finding().deviation().message().replace("|", "\\|")).append('\n');
            }
            md.append("\nEach case file is in the corpus format; review its derivation, then `fclcert corpus add FILE` "
                    + "lints it and places it in the corpus under the next free id.\n");
        }
        if (r.unexplained() > 0) {
            md.append("\n").append(r.unexplained()).append(" further disagreement(s) were not shrunk (shrink limit reached).\n");
        }
        md.append(String.format(Locale.ROOT, "%nSteps judged unfair (knife edges) and not sent: %d. Restarts of the "
                + "implementation: %d. Generator bugs: %d.%n", p.unfairSteps(), p.restarts(), p.generatorBugs()));
        r.infrastructureErrors().forEach(e -> md.append("\nInfrastructure: ").append(e).append('\n'));
        r.presentationFaults().forEach(e -> md.append("\nA written text fclcert cannot vouch for (a fault of fclcert's"
                + " writer or reader): ").append(e.lines().findFirst().orElse("")).append('\n'));
        return md.toString();
    }
}
