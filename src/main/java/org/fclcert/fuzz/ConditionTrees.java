package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;
import org.fclcert.model.Condition;
import org.fclcert.model.SourceLocation;

/** Small operations on the (shallow) condition trees the generator makes and the shrinker edits. */
final class ConditionTrees {
    private static final SourceLocation AT = SourceLocation.UNKNOWN;

    private ConditionTrees() {
    }

    /** Every node, root first. */
    static List<Condition> nodes(Condition root) {
        List<Condition> out = new ArrayList<>();
        collect(root, out);
        return out;
    }

    private static void collect(Condition c, List<Condition> out) {
        out.add(c);
        for (Condition child : children(c)) {
            collect(child, out);
        }
    }

    static List<Condition> children(Condition c) {
        if (c instanceof Condition.And a) {
            return a.operands();
        }
        if (c instanceof Condition.Or o) {
            return o.operands();
        }
        if (c instanceof Condition.Not n) {
            return List.of(n.operand());
        }
        if (c instanceof Condition.Parenthesized p) {
            return List.of(p.inner());
        }
        return List.of();
    }

    /** The condition without the leaves {@code drop} selects; empty when nothing is left. */
    static Optional<Condition> prune(Condition c, Predicate<Condition> drop) {
        if (c instanceof Condition.And a) {
            List<Condition> kept = a.operands().stream().map(o -> prune(o, drop)).flatMap(Optional::stream).toList();
            return kept.isEmpty() ? Optional.empty() : Optional.of(kept.size() == 1 ? kept.get(0) : new Condition.And(kept, AT));
        }
        if (c instanceof Condition.Or o) {
            List<Condition> kept = o.operands().stream().map(x -> prune(x, drop)).flatMap(Optional::stream).toList();
            return kept.isEmpty() ? Optional.empty() : Optional.of(kept.size() == 1 ? kept.get(0) : new Condition.Or(kept, AT));
        }
        if (c instanceof Condition.Not n) {
            return prune(n.operand(), drop).map(x -> new Condition.Not(x, AT));
        }
        if (c instanceof Condition.Parenthesized p) {
            return prune(p.inner(), drop).map(x -> new Condition.Parenthesized(x, AT));
        }
        return drop.test(c) ? Optional.empty() : Optional.of(c);
    }

    /** The condition with node {@code index} (in {@link #nodes} order) replaced. */
    static Condition replace(Condition root, int index, Condition with) {
        int[] counter = {0};
        return replace(root, index, with, counter);
    }

    private static Condition replace(Condition c, int index, Condition with, int[] counter) {
        if (counter[0]++ == index) {
            return with;
        }
        if (c instanceof Condition.And a) {
            return new Condition.And(a.operands().stream().map(o -> replace(o, index, with, counter)).toList(), a.location());
        }
        if (c instanceof Condition.Or o) {
            return new Condition.Or(o.operands().stream().map(x -> replace(x, index, with, counter)).toList(), o.location());
        }
        if (c instanceof Condition.Not n) {
            return new Condition.Not(replace(n.operand(), index, with, counter), n.location());
        }
        if (c instanceof Condition.Parenthesized p) {
            return new Condition.Parenthesized(replace(p.inner(), index, with, counter), p.location());
        }
        return c;
    }
}
