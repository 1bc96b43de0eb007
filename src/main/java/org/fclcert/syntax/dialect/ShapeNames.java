package org.fclcert.syntax.dialect;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.fclcert.model.Literal;
import org.fclcert.model.ShapeKind;

/**
 * The one table of membership-function names the libraries write: for each library, its name of each
 * {@link ShapeKind} and the order it writes the parameters in. The readers read shapes from it and the
 * auto-detection counts its names as giveaways, so both always agree. jFuzzyLogic's names are matched
 * in any case ({@code TRIAN}, {@code GAUSS} are common in its users' files); fuzzylite's as written. The
 * writers write shapes from it too ({@link #jfuzzylogic}, {@link #fuzzylite}): a name or an order is kept once.
 */
public final class ShapeNames {
    /** A shape as a library writes it: its name, then its parameters in the library's order and scale. */
    public record Written(String name, List<Literal> parameters) {
    }

    /**
     * One library's shape names.
     *
     * @param shapes        name (key as matched) to kind
     * @param reorder       kind to the written position of each canonical parameter; absent: written canonically
     * @param scale         kind to the factor each canonical parameter is the written one times; absent: 1
     * @param ignoreCase    whether names match in any case
     * @param otherNames    names the library defines that are not a {@link ShapeKind} (read by special forms,
     *                      or Takagi–Sugeno terms); they count as giveaways too
     */
    record Table(Map<String, ShapeKind> shapes, Map<ShapeKind, int[]> reorder, Map<ShapeKind, double[]> scale,
            boolean ignoreCase, Set<String> otherNames) {
        Table {
            // the writers need one name per kind
            if (Set.copyOf(shapes.values()).size() != shapes.size()) {
                throw new IllegalArgumentException("two names for one shape kind: " + shapes);
            }
        }

        Optional<ShapeKind> kind(String word) {
            return Optional.ofNullable(shapes.get(ignoreCase ? word.toLowerCase(Locale.ROOT) : word));
        }

        /** True for any name of the library's own shape vocabulary. */
        boolean known(String word) {
            String w = ignoreCase ? word.toLowerCase(Locale.ROOT) : word;
            return shapes.containsKey(w) || otherNames.contains(w);
        }

        /** The parameters as written, in canonical order; a wrong count is kept as written (FCL-C040 reports it). */
        List<Literal> canonical(ShapeKind kind, List<Literal> written) {
            int[] order = reorder.get(kind);
            double[] factor = scale.get(kind);
            if (order == null && factor == null || written.size() != kind.arity()) {
                return written;
            }
            Literal[] out = new Literal[written.size()];
            for (int i = 0; i < out.length; i++) {
                Literal l = written.get(order == null ? i : order[i]);
                out[i] = factor == null || factor[i] == 1 ? l
                        : new Literal(factor[i] * l.value(), l.integral() && factor[i] == Math.rint(factor[i]), l.location());
            }
            return List.of(out);
        }

        /** The inverse of {@link #canonical}: the library's name and written parameters; empty for a kind it lacks. */
        Optional<Written> written(ShapeKind kind, List<Literal> canonical) {
            Optional<String> name = shapes.entrySet().stream().filter(e -> e.getValue() == kind).map(Map.Entry::getKey)
                    .findFirst();
            if (name.isEmpty()) {
                return Optional.empty();
            }
            int[] order = reorder.get(kind);
            double[] factor = scale.get(kind);
            if (order == null && factor == null || canonical.size() != kind.arity()) {
                return Optional.of(new Written(name.get(), canonical));
            }
            Literal[] out = new Literal[canonical.size()];
            for (int i = 0; i < out.length; i++) {
                Literal l = canonical.get(i);
                out[order == null ? i : order[i]] = factor == null || factor[i] == 1 ? l : Literal.of(l.value() / factor[i]);
            }
            return Optional.of(new Written(name.get(), List.of(out)));
        }
    }

    /** jFuzzyLogic's writing of a shape given in canonical order; empty for a kind jFuzzyLogic has no name for. */
    public static Optional<Written> jfuzzylogic(ShapeKind kind, List<Literal> canonical) {
        return JFUZZYLOGIC.written(kind, canonical);
    }

    /** fuzzylite's writing of a shape given in canonical order (fuzzylite names every kind, in fclcert's order). */
    public static Written fuzzylite(ShapeKind kind, List<Literal> canonical) {
        return FUZZYLITE.written(kind, canonical).orElseThrow(() -> new IllegalStateException("no fuzzylite name for "
                + kind));
    }

    private ShapeNames() {
    }

    /**
     * jFuzzyLogic: {@code trian a b c}, {@code trape a b c d}, {@code gauss mean sd}, {@code gauss2 ...},
     * {@code gbell width slope center}, {@code sigm gain center}, {@code dsigm gain1 center1 gain2 center2},
     * {@code cosine halfWidth center} (its support is center ± halfWidth); {@code singletons}, {@code singleton}, {@code piece_wise_linear},
     * {@code freeform} and {@code function} are its special forms.
     */
    static final Table JFUZZYLOGIC = new Table(Map.of(
            "trian", ShapeKind.TRIANGLE, "trape", ShapeKind.TRAPEZOID, "gauss", ShapeKind.GAUSSIAN,
            "gauss2", ShapeKind.GAUSSIAN_PRODUCT, "gbell", ShapeKind.BELL, "sigm", ShapeKind.SIGMOID,
            "dsigm", ShapeKind.SIGMOID_DIFFERENCE, "cosine", ShapeKind.COSINE),
            Map.of(ShapeKind.BELL, new int[] {2, 0, 1}, ShapeKind.SIGMOID, new int[] {1, 0},
                    ShapeKind.SIGMOID_DIFFERENCE, new int[] {1, 0, 2, 3}, ShapeKind.COSINE, new int[] {1, 0}),
            // its cosine's first parameter is half the support (measured with its jar: 'cosine 4 3' is 0.31 at 0.5
            // and 5.5, 0 only beyond -1 and 7); fclcert's width is the whole support
            Map.of(ShapeKind.COSINE, new double[] {1, 2}),
            true, Set.of("singletons", "singleton", "function", "piece_wise_linear", "freeform"));

    /** fuzzylite: its class names, parameters in the canonical order (fclcert's order is fuzzylite's). */
    static final Table FUZZYLITE = new Table(Map.ofEntries(
            Map.entry("Triangle", ShapeKind.TRIANGLE), Map.entry("Trapezoid", ShapeKind.TRAPEZOID),
            Map.entry("Rectangle", ShapeKind.RECTANGLE), Map.entry("Ramp", ShapeKind.RAMP),
            Map.entry("Gaussian", ShapeKind.GAUSSIAN), Map.entry("GaussianProduct", ShapeKind.GAUSSIAN_PRODUCT),
            Map.entry("Bell", ShapeKind.BELL), Map.entry("Sigmoid", ShapeKind.SIGMOID),
            Map.entry("SigmoidDifference", ShapeKind.SIGMOID_DIFFERENCE),
            Map.entry("SigmoidProduct", ShapeKind.SIGMOID_PRODUCT), Map.entry("Cosine", ShapeKind.COSINE),
            Map.entry("SShape", ShapeKind.S_SHAPE), Map.entry("ZShape", ShapeKind.Z_SHAPE),
            Map.entry("PiShape", ShapeKind.PI_SHAPE), Map.entry("Concave", ShapeKind.CONCAVE),
            Map.entry("Spike", ShapeKind.SPIKE)),
            Map.of(), Map.of(), false, Set.of("Discrete", "Constant", "Linear", "Function", "Binary", "Aggregated",
                    "Activated"));
}
