package org.fclcert.harness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.fclcert.model.ConformanceLevel;
import org.junit.jupiter.api.Test;

class CaseSelectionTest {
    private static final RunCase COGS = TestCases.positive("B-COGS-001", ConformanceLevel.BASIC, List.of("B-COGS"),
            List.of(), List.of());
    private static final RunCase NSUM = TestCases.positive("E-ACCU-NSUM-003", ConformanceLevel.EXTENSION,
            List.of("E-ACCU-NSUM", "E-COG"), List.of(), List.of());

    @Test
    void globsMatchWholeIdsCaseInsensitively() {
        assertTrue(CaseSelection.matches("B-COGS-*", "B-COGS-001"));
        assertTrue(CaseSelection.matches("b-cogs-00?", "B-COGS-001"));
        assertFalse(CaseSelection.matches("COGS", "B-COGS-001"));
        assertFalse(CaseSelection.matches("B-COGS-00?", "B-COGS-0010"));
        assertTrue(CaseSelection.matches("E-ACCU-N+", "E-ACCU-N+"), "regex characters are literal");
    }

    @Test
    void everyGivenFilterMustHold() {
        List<RunCase> both = List.of(COGS, NSUM);
        assertEquals(both, CaseSelection.all().apply(both));
        assertEquals(List.of(NSUM), new CaseSelection(Set.of(ConformanceLevel.EXTENSION), Set.of(), List.of()).apply(both));
        assertEquals(List.of(NSUM), new CaseSelection(Set.of(), Set.of("e-cog"), List.of()).apply(both));
        assertEquals(List.of(COGS), new CaseSelection(Set.of(), Set.of(), List.of("B-*", "X-*")).apply(both));
        assertEquals(List.of(), new CaseSelection(Set.of(ConformanceLevel.BASIC), Set.of("E-COG"), List.of()).apply(both));
    }
}
