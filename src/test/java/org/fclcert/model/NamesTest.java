package org.fclcert.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class NamesTest {
    @Test
    void distanceCountsInsertionsDeletionsSubstitutionsAndSwaps() {
        assertEquals(0, Names.distance("LOW", "LOW"));
        assertEquals(1, Names.distance("LWO", "LOW"));      // one swap of neighbours
        assertEquals(1, Names.distance("LO", "LOW"));       // one insertion
        assertEquals(1, Names.distance("LOWW", "LOW"));     // one deletion
        assertEquals(1, Names.distance("LAW", "LOW"));      // one substitution
        assertEquals(4, Names.distance("HIGH", "LOW"));     // no letter in common: the longer length
    }

    @Test
    void closestIsTheOneNearNameAndOnlyWhenItIsUnambiguous() {
        assertEquals(Optional.of("low"), Names.closest("lwo", List.of("low", "high")));
        assertEquals(Optional.of("temp"), Names.closest("TMEP", List.of("temp", "power")));
        assertEquals(Optional.empty(), Names.closest("lukewarm", List.of("cold", "hot")));
        assertEquals(Optional.empty(), Names.closest("low", List.of("LOW", "lot")));   // exists: no typo
        assertEquals(Optional.empty(), Names.closest("lo", List.of("low", "lot")));    // two equally near
        assertEquals(Optional.empty(), Names.closest("a", List.of("b")));              // all letters differ
    }
}
