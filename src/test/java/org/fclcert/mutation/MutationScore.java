package org.fclcert.mutation;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.SAXException;

/**
 * The score of the corpus as a mutation test (issue 25), printed by {@code mvn -P mutation verify} after PIT:
 * of the mutants the corpus reaches and that are not argued equivalent, how many it kills.
 *
 * <p>PIT's own figure counts every surviving mutant against the corpus; many cannot change any output (the double
 * path is a filter in front of the exact one, a bound only decides which path runs). Those are argued, one row
 * each, in {@code conformance/equivalent-mutants.tsv}, by category; the categories' meanings and the arguments
 * are in {@code conformance/EQUIVALENT-MUTANTS.md}. A row names its mutant by class, method, mutator, PIT's
 * description and the text of the mutated source line (not its number, which moves with every edit above it): a
 * survivor whose line was edited since it was argued has no row any more, and counts as not argued until someone
 * checks the argument again. A row of category {@code U} is a survivor known not to be argued (a missing case),
 * one of category {@code K} a mutant a case was written to kill (surviving again, it counts as not argued).
 *
 * <p>Score = detected / (reached − argued equivalent), detected as PIT counts it (killed, timed out, memory
 * error, run error). The run fails when the score is below {@link #REQUIRED_PERCENT}; survivors without a row are
 * listed so that each can be argued or given a case.
 */
public final class MutationScore {
    /** Issue 25's bar: at least this share of the non-equivalent reached mutants killed by the corpus alone. */
    static final double REQUIRED_PERCENT = 95.0;

    private static final int LISTED = 40;

    /** One mutant of PIT's {@code mutations.xml}. */
    record Mutant(String status, String mutatedClass, String method, String sourceFile, int line, String mutator,
            String description) {
        boolean reached() {
            return !status.equals("NO_COVERAGE") && !status.equals("NON_VIABLE");
        }

        boolean detected() {
            return switch (status) {
                case "KILLED", "TIMED_OUT", "MEMORY_ERROR", "RUN_ERROR" -> true;
                default -> false;
            };
        }

        /** The class's name without the package, nested classes included ({@code KernelCompiler$1}). */
        String simpleClass() {
            return mutatedClass.substring(mutatedClass.lastIndexOf('.') + 1);
        }

        /** The mutator's name without PIT's package ({@code RemoveConditionalMutator_ORDER_ELSE}). */
        String simpleMutator() {
            return mutator.substring(mutator.lastIndexOf('.') + 1);
        }
    }

    /** A row of the argued list: which mutant, and its category (E… argued equivalent, U not argued). */
    record Argued(String mutatedClass, String method, String mutator, String description, String source,
            String category) {
        /**
         * An argued category: E… (the table of EQUIVALENT-MUTANTS.md), or the exact path's own F… and X… tables there.
         * U (not argued) and K (once killed by a case: a survivor matching it is a regression) count against the score.
         */
        boolean equivalent() {
            return category.matches("[EFX]\\d+[a-z]?");
        }

        String key() {
            return MutationScore.key(mutatedClass, method, mutator, description, source);
        }
    }

    /** The figures of one run. */
    record Score(int mutants, int reached, int detected, int equivalent, int notArgued, int withoutRow,
            Map<String, int[]> perClass, List<String> unlisted, List<String> unreachedClasses,
            Map<String, Integer> byCategory, int staleRows) {
        int nonEquivalent() {
            return reached - equivalent;
        }

        double percent() {
            return nonEquivalent() == 0 ? 100.0 : 100.0 * detected / nonEquivalent();
        }
    }

    private MutationScore() {
    }

    static String key(String mutatedClass, String method, String mutator, String description, String source) {
        return String.join("\u0000", mutatedClass, method, mutator, description, normalise(source));
    }

    private static String normalise(String source) {
        return source.strip().replaceAll("\\s+", " ");
    }

    /** Reads PIT's XML report. */
    static List<Mutant> readMutations(Path xml) throws IOException {
        Document doc;
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            DocumentBuilder b = f.newDocumentBuilder();
            doc = b.parse(xml.toFile());
        } catch (ParserConfigurationException | SAXException e) {
            throw new IOException(xml + ": not a PIT mutations report: " + e.getMessage(), e);
        }
        List<Mutant> out = new ArrayList<>();
        NodeList nodes = doc.getElementsByTagName("mutation");
        for (int i = 0; i < nodes.getLength(); i++) {
            Element m = (Element) nodes.item(i);
            String line = text(m, "lineNumber");
            try {
                out.add(new Mutant(m.getAttribute("status"), text(m, "mutatedClass"), text(m, "mutatedMethod"),
                        text(m, "sourceFile"), Integer.parseInt(line), text(m, "mutator"), text(m, "description")));
            } catch (NumberFormatException e) {
                throw new IOException(xml + ": mutation " + (i + 1) + " has line number '" + line + "'", e);
            }
        }
        return out;
    }

    private static String text(Element parent, String tag) {
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(tag)) {
                return e.getTextContent();
            }
        }
        return "";
    }

    /** Reads the argued list: tab-separated, {@code #} starts a comment line, six or seven columns. */
    static List<Argued> readArgued(Path tsv) throws IOException {
        List<Argued> out = new ArrayList<>();
        List<String> lines = Files.readAllLines(tsv, StandardCharsets.UTF_8);
        for (int i = 0; i < lines.size(); i++) {
            String l = lines.get(i);
            if (l.isBlank() || l.startsWith("#")) {
                continue;
            }
            String[] c = l.split("\t", -1);
            if (c.length < 6 || c[5].isBlank()) {
                throw new IOException(tsv + ":" + (i + 1) + ": expected class, method, mutator, description, source"
                        + " line and category separated by tabs");
            }
            out.add(new Argued(c[0], c[1], c[2], c[3], c[4], c[5].strip()));
        }
        return out;
    }

    /** The text of a mutant's line in its source file under {@code sources}, or "" where there is none. */
    static String sourceLine(Path sources, Mutant m, Map<Path, List<String>> cache) throws IOException {
        String pkg = m.mutatedClass().contains(".")
                ? m.mutatedClass().substring(0, m.mutatedClass().lastIndexOf('.')).replace('.', '/') : "";
        Path file = sources.resolve(pkg).resolve(m.sourceFile());
        List<String> lines = cache.get(file);
        if (lines == null) {
            try {
                lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            } catch (NoSuchFileException e) {
                lines = List.of();
            }
            cache.put(file, lines);
        }
        return m.line() >= 1 && m.line() <= lines.size() ? lines.get(m.line() - 1) : "";
    }

    static Score score(List<Mutant> mutants, List<Argued> argued, Path sources) throws IOException {
        Map<String, List<Argued>> rows = new HashMap<>();
        for (Argued a : argued) {
            rows.computeIfAbsent(a.key(), k -> new ArrayList<>()).add(a);
        }
        Map<Path, List<String>> cache = new HashMap<>();
        Map<String, int[]> perClass = new TreeMap<>(); // reached, detected, equivalent, not argued, mutants
        Map<String, Integer> byCategory = new TreeMap<>();
        List<String> unlisted = new ArrayList<>();
        int reached = 0;
        int detected = 0;
        int equivalent = 0;
        int notArgued = 0;
        int withoutRow = 0;
        for (Mutant m : mutants) {
            int[] c = perClass.computeIfAbsent(m.simpleClass(), k -> new int[5]);
            c[4]++;
            if (!m.reached()) {
                continue;
            }
            reached++;
            c[0]++;
            if (m.detected()) {
                detected++;
                c[1]++;
                continue;
            }
            String src = sourceLine(sources, m, cache);
            List<Argued> candidates = rows.get(key(m.simpleClass(), m.method(), m.simpleMutator(), m.description(), src));
            Argued row = candidates == null || candidates.isEmpty() ? null : candidates.remove(0);
            if (row != null && row.equivalent()) {
                equivalent++;
                c[2]++;
                byCategory.merge(row.category(), 1, Integer::sum);
            } else {
                notArgued++;
                c[3]++;
                if (row == null) {
                    withoutRow++;
                    unlisted.add(m.simpleClass() + ":" + m.line() + " " + m.method() + " " + m.simpleMutator() + " ("
                            + m.description() + "): " + normalise(src));
                } else {
                    byCategory.merge(row.category(), 1, Integer::sum);
                }
            }
        }
        int stale = 0;
        for (List<Argued> left : rows.values()) {
            stale += left.size();
        }
        List<String> unreached = new ArrayList<>();
        perClass.forEach((k, c) -> {
            if (c[0] == 0) {
                unreached.add(k + " (" + c[4] + ")");
            }
        });
        return new Score(mutants.size(), reached, detected, equivalent, notArgued, withoutRow, perClass, unlisted,
                unreached, byCategory, stale);
    }

    /** Prints the score; returns the exit status (0 when the score reaches {@link #REQUIRED_PERCENT}). */
    static int run(Path xml, Path tsv, Path sources, PrintStream out) throws IOException {
        Score s = score(readMutations(xml), readArgued(tsv), sources);
        out.println();
        out.println("The corpus as a mutation test (" + xml + ", argued equivalents from " + tsv + ")");
        out.printf(Locale.ROOT, "%-28s %8s %8s %10s %10s %8s%n", "class", "reached", "detected", "equivalent",
                "not argued", "score");
        s.perClass().forEach((k, c) -> {
            if (c[0] > 0) {
                int ne = c[0] - c[2];
                out.printf(Locale.ROOT, "%-28s %8d %8d %10d %10d %7.1f%%%n", k, c[0], c[1], c[2], c[3],
                        ne == 0 ? 100.0 : 100.0 * c[1] / ne);
            }
        });
        out.println("Not reached by any case (mutants): " + (s.unreachedClasses().isEmpty() ? "none"
                : String.join(", ", s.unreachedClasses())));
        out.println("Argued equivalent, and not argued (U), by category: " + s.byCategory());
        if (!s.unlisted().isEmpty()) {
            out.println(s.withoutRow() + " surviving mutants have no row in " + tsv
                    + " (not argued; counted against the score):");
            s.unlisted().stream().limit(LISTED).forEach(u -> out.println("  " + u));
            if (s.unlisted().size() > LISTED) {
                out.println("  … and " + (s.unlisted().size() - LISTED) + " more");
            }
        }
        if (s.staleRows() > 0) {
            out.println(s.staleRows() + " rows of " + tsv + " match no surviving mutant of this run (killed now, not"
                    + " in this run's classes, or their line was edited)");
        }
        out.printf(Locale.ROOT, "MUTATION SCORE: %d of %d reached non-equivalent mutants killed by the corpus alone:"
                + " %.1f %% (%d mutants, %d reached, %d argued equivalent, %d survivors not argued, %d of them"
                + " without a row)%n", s.detected(), s.nonEquivalent(), s.percent(), s.mutants(), s.reached(),
                s.equivalent(), s.notArgued(), s.withoutRow());
        if (s.percent() < REQUIRED_PERCENT) {
            out.printf(Locale.ROOT, "below the required %.0f %%: write the missing cases (CONTRIBUTING.md)%n",
                    REQUIRED_PERCENT);
            return 1;
        }
        return 0;
    }

    /** {@code MutationScore mutations.xml equivalent-mutants.tsv src/main/java}. */
    public static void main(String[] args) {
        if (args.length != 3) {
            System.err.println("usage: MutationScore <mutations.xml> <equivalent-mutants.tsv> <source directory>");
            System.exit(2);
        }
        int status;
        try {
            status = run(Path.of(args[0]), Path.of(args[1]), Path.of(args[2]), System.out);
        } catch (NoSuchFileException e) {
            System.err.println("mutation score: " + e.getFile() + ": no such file (did PIT run?)");
            status = 2;
        } catch (IOException e) {
            System.err.println("mutation score: " + e.getMessage());
            status = 2;
        }
        System.exit(status);
    }

    /** For the test: a score's figures as one line. */
    static String summary(Score s) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("mutants", s.mutants());
        m.put("reached", s.reached());
        m.put("detected", s.detected());
        m.put("equivalent", s.equivalent());
        m.put("notArgued", s.notArgued());
        m.put("withoutRow", s.withoutRow());
        m.put("stale", s.staleRows());
        return m.toString();
    }
}
