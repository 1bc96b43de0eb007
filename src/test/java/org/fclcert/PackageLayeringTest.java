package org.fclcert;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.Dependency;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Keeps the main packages layered: no cycle between any two packages, and every dependency pointing down
 * the list below. It reads the compiled main classes (every use of another class counts: imports, fully
 * qualified names, field and method types, annotations), not the test classes.
 *
 * <p>The allowed layering, top to bottom. A package may use the packages of the layers below its own; it may
 * use nothing of its own layer and nothing above. A subpackage belongs to the layer of its nearest listed
 * ancestor (so {@code syntax.dialect.something} is in the layer of {@code syntax.dialect}); a new top-level
 * package must be given a layer here (and in {@code docs/architecture.md}).
 *
 * <pre>
 *   front ends        cli, maven           the command line; the Maven plugin
 *   editor            lsp                  the language server, which the command line starts (fclcert lsp)
 *   flows             orchestration, fuzz  one whole job each: certify (corpus, probes, reports); fuzz
 *   reports           report               verdicts of clause 6.1 and their renderings, from case results
 *   harness           harness              runs corpus cases against an implementation, results.jsonl
 *   probe             probe                measures the Table 11 data check list
 *   inputs            corpus, iut          the conformance corpus; implementations under test
 *   isolation         sandbox              launching implementation processes in a bubblewrap sandbox
 *   writers           write                programs written back as text (canonical FCL, dialects)
 *   meaning           eval, check          the reference evaluator; the check rules and feature detector
 *   dialect readers   syntax.dialect       other libraries' FCL dialects, read into the same model
 *   reader            syntax               the strict reader of 5.4
 *   model             model                the immutable semantic model, diagnostics, features
 *   vendor SPI        iut.spi              what a vendor implements; depends on nothing of fclcert
 * </pre>
 */
class PackageLayeringTest {
    private static final String ROOT = "org.fclcert";

    /** The layers, top to bottom (package names relative to {@code org.fclcert}). */
    static final List<List<String>> LAYERS = List.of(
            List.of("cli", "maven"),
            List.of("lsp"),
            List.of("orchestration", "fuzz"),
            List.of("report"),
            List.of("harness"),
            List.of("probe"),
            List.of("corpus", "iut"),
            List.of("sandbox"),
            List.of("write", "plot"),
            List.of("eval", "check"),
            List.of("syntax.dialect"),
            List.of("syntax"),
            List.of("model"),
            List.of("iut.spi"));

    private static JavaClasses classes;

    @BeforeAll
    static void importMainClasses() {
        classes = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_JARS).importPackages(ROOT);
    }

    @Test
    void everyPackageHasALayer() {
        Set<String> unplaced = new TreeSet<>();
        for (JavaClass c : classes) {
            if (unit(c.getPackageName()).isEmpty()) {
                unplaced.add(c.getPackageName());
            }
        }
        assertEquals(Set.of(), unplaced, "packages without a layer: give them one in PackageLayeringTest.LAYERS");
    }

    @Test
    void dependenciesPointDownTheLayers() {
        List<String> wrong = new ArrayList<>();
        for (Map.Entry<String, Set<String>> e : edges().entrySet()) {
            String[] fromTo = e.getKey().split(" -> ");
            Optional<String> from = unit(fromTo[0]);
            Optional<String> to = unit(fromTo[1]);
            if (from.isEmpty() || to.isEmpty() || from.equals(to)) {
                continue;
            }
            if (layer(from.get()) >= layer(to.get())) {
                wrong.add(e.getKey() + " (" + (layer(from.get()) == layer(to.get()) ? "same layer" : "upwards")
                        + "), e.g. " + e.getValue().iterator().next());
            }
        }
        assertTrue(wrong.isEmpty(), "dependencies against the layering:\n  " + String.join("\n  ", wrong));
    }

    @Test
    void noCycleBetweenPackages() {
        Map<String, Set<String>> graph = new TreeMap<>();
        for (String edge : edges().keySet()) {
            String[] fromTo = edge.split(" -> ");
            graph.computeIfAbsent(fromTo[0], k -> new TreeSet<>()).add(fromTo[1]);
        }
        List<String> cycles = new ArrayList<>();
        for (String start : graph.keySet()) {
            findCycle(graph, start, new ArrayList<>(List.of(start))).ifPresent(cycles::add);
        }
        assertTrue(cycles.isEmpty(), "package cycles:\n  " + String.join("\n  ", new TreeSet<>(cycles)));
    }

    /** The cycle through {@code path}'s first package, if there is one (depth first, each package once). */
    private static Optional<String> findCycle(Map<String, Set<String>> graph, String start, List<String> path) {
        String last = path.get(path.size() - 1);
        for (String next : graph.getOrDefault(last, Set.of())) {
            if (next.equals(start)) {
                return Optional.of(String.join(" -> ", path) + " -> " + start);
            }
            if (!path.contains(next) && next.compareTo(start) > 0) {
                path.add(next);
                Optional<String> found = findCycle(graph, start, path);
                path.remove(path.size() - 1);
                if (found.isPresent()) {
                    return found;
                }
            }
        }
        return Optional.empty();
    }

    @Test
    void theHarnessDoesNotKnowTheReports() {
        // the cycle this test was written against: harness.Certification used report, report uses harness
        assertTrue(edges().keySet().stream().noneMatch(e -> e.startsWith(ROOT + ".harness -> " + ROOT + ".report")));
        assertTrue(edges().containsKey(ROOT + ".report -> " + ROOT + ".harness"), "the test sees dependencies");
    }

    @Test
    void theLayeringItselfIsConsistent() {
        Set<String> seen = new TreeSet<>();
        LAYERS.forEach(l -> l.forEach(p -> assertTrue(seen.add(p), p + " is in two layers")));
        assertEquals(layer("syntax.dialect"), layer(unit(ROOT + ".syntax.dialect.somelibrary").orElseThrow()));
        assertEquals(Optional.empty(), unit(ROOT + ".nowhere"));
        Map<String, Set<String>> cyclic = Map.of("a", Set.of("b"), "b", Set.of("c"), "c", Set.of("a", "d"));
        assertEquals(Optional.of("a -> b -> c -> a"), findCycle(cyclic, "a", new ArrayList<>(List.of("a"))));
        assertEquals(Optional.empty(), findCycle(Map.of("a", Set.of("b"), "b", Set.of("c")), "a",
                new ArrayList<>(List.of("a"))));
    }

    /** Package-to-package dependencies of the main classes, each with one class-level example. */
    private static Map<String, Set<String>> edges() {
        Map<String, Set<String>> edges = new TreeMap<>();
        for (JavaClass c : classes) {
            for (Dependency d : c.getDirectDependenciesFromSelf()) {
                String from = d.getOriginClass().getPackageName();
                String to = d.getTargetClass().getPackageName();
                if (!from.equals(to) && to.startsWith(ROOT + ".")) {
                    edges.computeIfAbsent(from + " -> " + to, k -> new TreeSet<>())
                            .add(simpleName(d.getOriginClass()) + " uses " + simpleName(d.getTargetClass()));
                }
            }
        }
        return edges;
    }

    private static String simpleName(JavaClass c) {
        return c.getName().substring(c.getPackageName().length() + 1);
    }

    /** The listed package a package belongs to: itself or its nearest listed ancestor. */
    private static Optional<String> unit(String packageName) {
        if (!packageName.startsWith(ROOT + ".")) {
            return Optional.empty();
        }
        String relative = packageName.substring(ROOT.length() + 1);
        while (true) {
            if (layerOrMinus(relative) >= 0) {
                return Optional.of(relative);
            }
            int dot = relative.lastIndexOf('.');
            if (dot < 0) {
                return Optional.empty();
            }
            relative = relative.substring(0, dot);
        }
    }

    private static int layer(String unit) {
        int i = layerOrMinus(unit);
        if (i < 0) {
            throw new IllegalArgumentException(unit);
        }
        return i;
    }

    private static int layerOrMinus(String relative) {
        for (int i = 0; i < LAYERS.size(); i++) {
            if (LAYERS.get(i).contains(relative)) {
                return i;
            }
        }
        return -1;
    }
}
