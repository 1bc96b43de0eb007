package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.fclcert.model.Literal;
import org.fclcert.model.ShapeKind;
import org.junit.jupiter.api.Test;

/** The writers' side of the shape table is the inverse of the readers' side, for both libraries and every kind. */
class ShapeNamesTest {
    private static List<Literal> parameters(int n) {
        List<Literal> p = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            p.add(Literal.of(1.5 + 2 * i)); // distinct, so that a wrong order shows
        }
        return p;
    }

    private static List<Double> values(List<Literal> l) {
        return l.stream().map(Literal::value).toList();
    }

    @Test
    void whatTheWritersWriteTheReadersReadBack() {
        for (ShapeKind k : ShapeKind.values()) {
            List<Literal> p = parameters(k.arity());
            ShapeNames.Written f = ShapeNames.fuzzylite(k, p);
            assertEquals(k, ShapeNames.FUZZYLITE.kind(f.name()).orElseThrow());
            assertEquals(values(p), values(ShapeNames.FUZZYLITE.canonical(k, f.parameters())), k.name());
            ShapeNames.jfuzzylogic(k, p).ifPresent(j -> {
                assertEquals(k, ShapeNames.JFUZZYLOGIC.kind(j.name()).orElseThrow());
                assertEquals(values(p), values(ShapeNames.JFUZZYLOGIC.canonical(k, j.parameters())), k.name());
            });
        }
    }

    @Test
    void jfuzzylogicsOrdersAndCosineScaleAreWritten() {
        // by hand, from jFuzzyLogic's grammar: 'cosine halfWidth center', 'sigm gain center'
        ShapeNames.Written cosine = ShapeNames.jfuzzylogic(ShapeKind.COSINE, List.of(Literal.of(3), Literal.of(8)))
                .orElseThrow();
        assertEquals("cosine", cosine.name());
        assertEquals(List.of(4.0, 3.0), values(cosine.parameters())); // half the support 8, then the centre 3
        ShapeNames.Written sigm = ShapeNames.jfuzzylogic(ShapeKind.SIGMOID, List.of(Literal.of(2), Literal.of(5)))
                .orElseThrow();
        assertEquals("sigm", sigm.name());
        assertEquals(List.of(5.0, 2.0), values(sigm.parameters()));
        assertTrue(ShapeNames.jfuzzylogic(ShapeKind.RAMP, parameters(2)).isEmpty(), "jFuzzyLogic has no ramp");
    }
}
