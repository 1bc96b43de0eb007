package org.fclcert.harness;

import java.util.List;
import java.util.Map;

/**
 * The first line of {@code results.jsonl}: everything a report needs besides the case results — which
 * implementation, which toolkit, which corpus, which selection.
 */
public record RunHeader(Iut iut, Toolkit toolkit, CorpusInfo corpus, Selection selection, String startedAt,
        @com.fasterxml.jackson.annotation.JsonInclude(com.fasterxml.jackson.annotation.JsonInclude.Include.NON_NULL)
        String presentAs,
        @com.fasterxml.jackson.annotation.JsonInclude(com.fasterxml.jackson.annotation.JsonInclude.Include.NON_NULL)
        Provenance provenance) {

    /** A header of a run on the language axis only. */
    public RunHeader(Iut iut, Toolkit toolkit, CorpusInfo corpus, Selection selection, String startedAt) {
        this(iut, toolkit, corpus, selection, startedAt, null, null);
    }

    /** A header without provenance (a run made without a seed: no fresh vectors, no disguise). */
    public RunHeader(Iut iut, Toolkit toolkit, CorpusInfo corpus, Selection selection, String startedAt,
            String presentAs) {
        this(iut, toolkit, corpus, selection, startedAt, presentAs, null);
    }

    /** The same header, the positive cases also presented in {@code dialect}'s layout (null: not presented). */
    public RunHeader presentedAs(String dialect) {
        return new RunHeader(iut, toolkit, corpus, selection, startedAt, dialect, provenance);
    }

    /** The same header with the run's provenance (its seed among it). */
    public RunHeader withProvenance(Provenance value) {
        return new RunHeader(iut, toolkit, corpus, selection, startedAt, presentAs, value);
    }

    /**
     * The implementation as it introduced itself, and the {@code --iut} spec (with {@code --classpath}, if
     * one was given) that reaches it again.
     */
    public record Iut(String name, String version, String command, String spec, String classpath,
            List<String> claims, Map<String, Long> declaredLimits,
            @com.fasterxml.jackson.annotation.JsonInclude(com.fasterxml.jackson.annotation.JsonInclude.Include.NON_NULL)
            org.fclcert.sandbox.Isolation isolation) {
        public Iut {
            claims = claims == null ? List.of() : List.copyOf(claims);
            declaredLimits = declaredLimits == null ? Map.of()
                    : java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(declaredLimits));
        }

        /** An implementation whose isolation is not recorded (results written before fclcert recorded it). */
        public Iut(String name, String version, String command, String spec, String classpath, List<String> claims,
                Map<String, Long> declaredLimits) {
            this(name, version, command, spec, classpath, claims, declaredLimits, null);
        }
    }

    /** The same header, recording the isolation the implementation ran under. */
    public RunHeader withIsolation(org.fclcert.sandbox.Isolation isolation) {
        return new RunHeader(new Iut(iut.name(), iut.version(), iut.command(), iut.spec(), iut.classpath(),
                iut.claims(), iut.declaredLimits(), isolation), toolkit, corpus, selection, startedAt, presentAs, provenance);
    }

    /**
     * fclcert itself: its version, and {@code rerun}, the command that reruns one case of this run with
     * {@value #CASE} standing for the case id, when the front end that ran it has its own ({@code mvn verify
     * -Dfclcert.cases={case}} from the Maven plugin); null: the command line's {@code ./fclcert certify ... --case}.
     */
    @com.fasterxml.jackson.annotation.JsonInclude(com.fasterxml.jackson.annotation.JsonInclude.Include.NON_NULL)
    public record Toolkit(String version, String rerun) {
        /** What {@code rerun} has where the case id goes. */
        public static final String CASE = "{case}";

        public Toolkit(String version) {
            this(version, null);
        }
    }

    /**
     * The corpus: its directory as given, the number of cases in it, the sha256 over the sorted case
     * files' bytes, and how many Basic Level cases (not flagged interpretation) it holds — the Basic
     * verdict needs them all. {@code rowCases}: for each feature row, how many cases (not flagged
     * interpretation) of the row's level or below name it in their {@code tests} — what that row's verdict needs
     * to have run; empty in a header written before it existed.
     */
    public record CorpusInfo(String dir, int cases, String sha256, int basicCases,
            @com.fasterxml.jackson.annotation.JsonInclude(com.fasterxml.jackson.annotation.JsonInclude.Include.NON_EMPTY)
            Map<String, Integer> rowCases) {
        public CorpusInfo {
            // in the order given (feature order, and the file's order when read back): Map.copyOf's order changes per JVM
            rowCases = rowCases == null ? Map.of() : java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(rowCases));
        }

        public CorpusInfo(String dir, int cases, String sha256, int basicCases) {
            this(dir, cases, sha256, basicCases, Map.of());
        }
    }

    /** The filters of the run and the cases they selected, in run order. */
    public record Selection(List<String> levels, List<String> features, List<String> cases,
            List<PlannedCase> planned) {
        public Selection {
            levels = List.copyOf(levels);
            features = List.copyOf(features);
            cases = List.copyOf(cases);
            planned = List.copyOf(planned);
        }

        /** True when no filter narrowed the corpus. */
        public boolean whole() {
            return levels.isEmpty() && features.isEmpty() && cases.isEmpty();
        }
    }
}
