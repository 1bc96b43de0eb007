package org.fclcert.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class BlockIndexTest {
    private static final SourceLocation AT = SourceLocation.of("t.fcl", 1, 1);

    private static Variable variable(String name, VariableKind kind) {
        return new Variable(name, kind, DataType.REAL, Optional.empty(), AT);
    }

    @Test
    void findsWhatTheWalksOfTheBlockFindFirstDeclarationWinningIgnoringCase() {
        Variable x = variable("Temp", VariableKind.INPUT);
        Variable xAgain = variable("TEMP", VariableKind.INPUT);
        Variable y = variable("valve", VariableKind.OUTPUT);
        Fuzzification f = new Fuzzification("temp", List.of(), AT, Optional.empty());
        Fuzzification fAgain = new Fuzzification("Temp", List.of(), AT, Optional.empty());
        Defuzzification d = new Defuzzification("VALVE", Optional.empty(), List.of(), Optional.empty(),
                Optional.empty(), AT);
        FunctionBlock fb = new FunctionBlock("b", List.of(x, xAgain, y), List.of(f, fAgain), List.of(d), List.of(),
                List.of(), AT);
        BlockIndex index = BlockIndex.of(fb);
        for (String name : List.of("temp", "TEMP", "Temp", "valve", "Valve", "pressure")) {
            assertEquals(fb.variable(name), index.variable(name), name);
            assertEquals(fb.fuzzification(name), index.fuzzification(name), name);
            assertEquals(fb.defuzzification(name), index.defuzzification(name), name);
        }
        assertSame(x, index.variable("tEmP").orElseThrow());
        assertSame(f, index.fuzzification("TEMP").orElseThrow());
        assertSame(d, index.defuzzification("valve").orElseThrow());
        assertTrue(index.variable("pressure").isEmpty());
    }
}
