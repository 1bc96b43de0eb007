package org.fclcert.probe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.fclcert.iut.IutOptions;
import org.fclcert.iut.Iuts;
import org.fclcert.iut.StopSignal;
import org.junit.jupiter.api.Test;

/**
 * The prober on the reference (which must reach every cap or its documented natural bound) and on fakes
 * with known limits, each of which must be measured exactly.
 */
class ProberTest {
    private static final Path FAKES = Path.of("src/test/resources/iut").toAbsolutePath();

    private static Map<String, DataCheckEntry> probe(Prober.IutSource source, long cap, Table11... rows)
            throws Exception {
        Set<Table11> selected = rows.length == 0 ? Set.of() : EnumSet.of(rows[0], rows);
        List<DataCheckEntry> list = Prober.probe(source, new Prober.Options(cap, Duration.ofMinutes(2), selected),
                Prober.Listener.NONE);
        assertEquals(Table11.values().length, list.size(), "one entry per row, always");
        for (int i = 0; i < list.size(); i++) {
            assertEquals(Table11.values()[i].id(), list.get(i).id(), "rows in the order of Table 11");
        }
        return list.stream().collect(Collectors.toMap(DataCheckEntry::id, e -> e));
    }

    @Test
    void theReferenceReachesEveryCap() throws Exception {
        long start = System.nanoTime();
        Map<String, DataCheckEntry> rows = probe(() -> Iuts.open("reference", IutOptions.defaults()), 64);
        double seconds = (System.nanoTime() - start) / 1e9;
        assertTrue(seconds < 30, "the reference's probe at cap 64 is quick: " + seconds + " s");
        for (Table11 row : Table11.values()) {
            DataCheckEntry e = rows.get(row.id());
            if (row.isLimit() && row != Table11.IDENTIFIER_LENGTH) {
                assertEquals("64", e.value(), row.id() + ": " + e.note());
                assertEquals(DataCheckEntry.AT_LEAST, e.bound(), row.id());
                assertTrue(e.note().contains("reached the cap of 64"), e.note());
            }
        }
        assertEquals("64 accepted, distinct up to 64", rows.get("identifier-length").value());
        assertTrue(rows.get("identifier-length").note().startsWith("identifiers are case-insensitive"));
        assertEquals(String.join(", ", Prober.DATA_TYPES), rows.get("data-types").value());
        assertEquals("YES: (* *) on one line, (* *) across lines, (* *) after a statement",
                rows.get("line-comments").value());
        assertTrue(rows.get("line-comments").note().startsWith("// not accepted: rejected cleanly ('FCL-S001"),
                rows.get("line-comments").note());
        assertEquals("continuous (double)", rows.get("degree-resolution").value());
        assertTrue(rows.get("execution-time-ms").value().matches("median \\d+\\.\\d+ ms, p95 \\d+\\.\\d+ ms"),
                rows.get("execution-time-ms").value());
        assertTrue(Long.parseLong(rows.get("memory-kb").value()) >= 0);
        assertTrue(rows.get("memory-kb").note().startsWith("approximate"));
    }

    @Test
    void theReferenceNestsParenthesesToItsDocumentedLimit() throws Exception {
        DataCheckEntry e = probe(() -> Iuts.open("reference", IutOptions.defaults()), 4096, Table11.NESTING)
                .get("max-nesting-depth");
        assertEquals("1000", e.value(), e.note());     // Limits.MAX_NESTING_DEPTH, docs/performance.md
        assertEquals(DataCheckEntry.EXACT, e.bound());
        assertTrue(e.note().startsWith("at 1001: rejected cleanly ('FCL-S008"), e.note());
    }

    @Test
    void threePointsPerTermAreMeasuredExactly() throws Exception {
        Map<String, DataCheckEntry> rows = probe(ProbeFakes.MaxThreePoints::new, 64, Table11.POINTS_PER_INPUT_TERM,
                Table11.POINTS_PER_OUTPUT_TERM, Table11.POINTS_ALL_INPUT_TERMS, Table11.TERMS_PER_INPUT);
        DataCheckEntry in = rows.get("max-points-per-input-term");
        assertEquals("3", in.value(), in.note());
        assertEquals(DataCheckEntry.EXACT, in.bound());
        assertEquals("at 4: rejected cleanly ('at most 3 points per term')", in.note());
        assertEquals("3", rows.get("max-points-per-output-term").value());
        // terms of 3 points each make up the total: 64 points need 22 terms of at most 3 points
        assertEquals("64", rows.get("max-points-all-input-terms").value(), rows.get("max-points-all-input-terms").note());
        assertEquals("64", rows.get("max-terms-per-input").value(), "triangles have 3 points");
    }

    @Test
    void tenRulesPerBlockAreMeasuredExactlyAndTheTotalSpreadsOverBlocks() throws Exception {
        Map<String, DataCheckEntry> rows = probe(ProbeFakes.MaxTenRulesPerBlock::new, 64, Table11.RULES_PER_BLOCK,
                Table11.RULE_BLOCKS, Table11.RULES_TOTAL);
        DataCheckEntry perBlock = rows.get("max-rules-per-block");
        assertEquals("10", perBlock.value());
        assertEquals(DataCheckEntry.EXACT, perBlock.bound());
        assertEquals("10", perBlock.declared());
        assertTrue(perBlock.note().startsWith("at 11: rejected cleanly ('at most 10 rules per rule block')"),
                perBlock.note());
        assertTrue(perBlock.note().endsWith("declared 10: met"), perBlock.note());
        assertEquals("64", rows.get("max-rules-total").value(), "64 rules in 7 blocks of at most 10");
        assertEquals("64", rows.get("max-rule-blocks").value());
        assertEquals("500", rows.get("max-rule-blocks").declared());
        assertTrue(rows.get("max-rule-blocks").note().contains("declared 500, not reached"));
    }

    @Test
    void aDeclaredLimitThatIsNotMetIsFlagged() throws Exception {
        class Overclaims extends ProbeFakes.MaxThreePoints {
            @Override
            public org.fclcert.iut.IutInfo hello() {
                return new org.fclcert.iut.IutInfo("overclaims", "1", "java:x", List.of(),
                        Map.of("max-points-per-input-term", 8L));
            }
        }
        DataCheckEntry e = probe(Overclaims::new, 64, Table11.POINTS_PER_INPUT_TERM).get("max-points-per-input-term");
        assertEquals("3", e.value());
        assertEquals("8", e.declared());
        assertTrue(e.note().startsWith("DECLARED LIMIT NOT MET: the implementation declares 8 but works only up to 3"),
                e.note());
    }

    @Test
    void aWorkloadRejectedAtLoadIsSaidSoAndMemoryNotMeasuredGivesThatReason() throws Exception {
        // the real jfuzzylite (a test dependency) rejects the standard's 'METHOD: CoGS;' of the workload
        Map<String, DataCheckEntry> rows = probe(() -> org.fclcert.iut.Iuts.open("jfuzzylite",
                org.fclcert.iut.IutOptions.defaults()), 16, Table11.EXECUTION_TIME, Table11.MEMORY);
        DataCheckEntry time = rows.get("execution-time-ms");
        assertEquals(DataCheckEntry.NOT_MEASURED, time.bound());
        assertEquals("the workload failed: rejected at load (jfuzzylite: [syntax error] unexpected token <METHOD:>)",
                time.note());
        DataCheckEntry memory = rows.get("memory-kb");
        assertEquals(DataCheckEntry.NOT_MEASURED, memory.bound());
        assertEquals(time.note(), memory.note());
    }

    @Test
    void silentlyDroppedRulesAreCalledOut() throws Exception {
        DataCheckEntry e = probe(ProbeFakes.DropsRulesAfterTen::new, 64, Table11.RULES_PER_BLOCK)
                .get("max-rules-per-block");
        // the last rule is always one of the sampled rules, so dropping it shows from 11 rules on
        assertEquals("10", e.value(), e.note());
        assertTrue(e.note().startsWith("at 11: SILENTLY WRONG RESULT"), e.note());
    }

    @Test
    void caseSensitiveIdentifiersAreANonConformance() throws Exception {
        DataCheckEntry e = probe(ProbeFakes.CaseSensitive::new, 16, Table11.IDENTIFIER_LENGTH).get("identifier-length");
        assertEquals("16 accepted, distinct up to 16", e.value());
        assertTrue(e.note().startsWith("NON-CONFORMANT: identifiers are case-sensitive"), e.note());
    }

    @Test
    void degreesQuantisedTo1Over200AreDetected() throws Exception {
        DataCheckEntry e = probe(ProbeFakes.QuantisedDegrees::new, 16, Table11.DEGREE_RESOLUTION)
                .get("degree-resolution");
        assertEquals("≈ 1/200", e.value(), e.note());
        // 201 levels 0, 1/200, …, 1; the sweep's x = k/2000 hits every one of them
        assertTrue(e.note().startsWith("201 distinct degrees"), e.note());
    }

    @Test
    void commentFormsAreMeasuredEachOnItsOwn() throws Exception {
        DataCheckEntry e = probe(ProbeFakes.SlashCommentsOnly::new, 16, Table11.LINE_COMMENTS).get("line-comments");
        assertEquals("YES: //", e.value());
        assertTrue(e.note().startsWith("(* *) on one line not accepted: rejected cleanly"), e.note());
    }

    @Test
    void aProcessThatCrashesAt1000RulesIsRestartedAndMeasuredExactly() throws Exception {
        String spec = "process:python3 '" + FAKES.resolve("crash_at_1000_rules.py") + "'";
        java.util.concurrent.atomic.AtomicInteger opened = new java.util.concurrent.atomic.AtomicInteger();
        Map<String, DataCheckEntry> rows = probe(() -> {
            opened.incrementAndGet();
            // the script imports the example implementation beside it: that directory is bound read-only too
            return Iuts.open(spec, IutOptions.defaults().withSandbox(org.fclcert.sandbox.SandboxSettings.defaults()
                    .withReadOnly(List.of(Path.of("examples/iut").toAbsolutePath()))));
        }, 2048,
                Table11.RULES_PER_BLOCK, Table11.RULES_TOTAL, Table11.MEMORY);
        DataCheckEntry perBlock = rows.get("max-rules-per-block");
        assertEquals("999", perBlock.value(), perBlock.note());
        assertEquals(DataCheckEntry.EXACT, perBlock.bound());
        assertTrue(perBlock.note().startsWith("at 1000: crashed (the IUT exited while answering 'load' (exit code 9))"),
                perBlock.note());
        // 1000 rules in two blocks of at most 999 crash it too: the count is over the whole program
        DataCheckEntry total = rows.get("max-rules-total");
        assertEquals("999", total.value(), total.note());
        assertTrue(total.note().startsWith("at 1000: crashed"), total.note());
        // 1024, 1008 and 1000 crash in each row, each followed by a size that loads: a crash costs only its request,
        // so one session (restarted after each crash) serves the whole probe
        assertEquals(1, opened.get(), "sessions opened");
        long kb = Long.parseLong(rows.get("memory-kb").value());
        assertTrue(kb > 1000 && kb < 1_000_000, "a Python process's peak RSS in kB: " + kb);
    }

    /**
     * The budget on a simulated clock: loading costs 10 µs of it per character, so sizes get dearer as they
     * grow. No row may start an attempt it cannot finish in its share, none overruns the budget, and a row
     * left with little time still measures its smallest size rather than reporting 0.
     */
    @Test
    void theBudgetIsSharedAndNeverOverrun() throws Exception {
        long[] now = {0};
        Prober.IutSource slowLoads = () -> new org.fclcert.harness.fakes.EvaluatorIut() {
            @Override
            public org.fclcert.iut.LoadOutcome load(String fcl) {
                now[0] += fcl.length() * 10_000L;
                return super.load(fcl);
            }
        };
        Duration budget = Duration.ofSeconds(4);
        List<DataCheckEntry> list = Prober.probe(slowLoads, new Prober.Options(100_000, budget,
                EnumSet.of(Table11.INPUTS, Table11.RULES_PER_BLOCK, Table11.NESTING)), Prober.Listener.NONE,
                () -> now[0]);
        Map<String, DataCheckEntry> rows = list.stream().collect(Collectors.toMap(DataCheckEntry::id, e -> e));
        assertTrue(now[0] <= budget.toNanos(), "simulated time used: " + now[0] / 1e9 + " s of " + budget);
        // a third of 4 s each, at 10 µs a character: some 130 000 characters of program per row
        for (Table11 row : List.of(Table11.INPUTS, Table11.RULES_PER_BLOCK)) {
            DataCheckEntry e = rows.get(row.id());
            assertEquals(DataCheckEntry.AT_LEAST, e.bound(), row.id());
            assertTrue(e.note().startsWith("probe budget ran out for this row"), row.id() + ": " + e.note());
            assertTrue(Long.parseLong(e.value()) >= 64, row.id() + " measured only " + e.value());
        }
        // the last row still gets its share: nesting programs are short, so it reaches the reference's 1000
        assertEquals("1000", rows.get("max-nesting-depth").value(), rows.get("max-nesting-depth").note());
        assertEquals(DataCheckEntry.EXACT, rows.get("max-nesting-depth").bound());
        assertEquals(DataCheckEntry.NOT_MEASURED, rows.get("max-rule-blocks").bound(), "not selected");

        // one row alone: doubling sizes on a linear cost, the size that would end past the budget is not started
        now[0] = 0;
        Prober.probe(slowLoads, new Prober.Options(100_000, budget, EnumSet.of(Table11.RULES_PER_BLOCK)),
                Prober.Listener.NONE, () -> now[0]);
        assertTrue(now[0] <= budget.toNanos(), "simulated time used: " + now[0] / 1e9 + " s of " + budget);
    }
    @Test
    void aStopKeepsWhatTheRowUnderWayEstablishedAndMeasuresNoMore() throws Exception {
        // stopped from inside the third load of the inputs row: sizes 1 and 2 worked, size 4 was cut short
        StopSignal stop = new StopSignal();
        boolean[] inInputs = {false};
        int[] loads = {0};
        Prober.IutSource source = () -> new org.fclcert.harness.fakes.EvaluatorIut() {
            @Override
            protected java.util.Optional<org.fclcert.iut.LoadOutcome> veto(String fcl, org.fclcert.check.Analysis a) {
                if (inInputs[0] && ++loads[0] == 3) {
                    stop.stop("stopped by the test");
                }
                return java.util.Optional.empty();
            }
        };
        Prober.Listener listener = (row, index, total) -> inInputs[0] = row == Table11.INPUTS;
        List<DataCheckEntry> list = Prober.probe(source, new Prober.Options(64, Duration.ofMinutes(2),
                EnumSet.of(Table11.DATA_TYPES, Table11.INPUTS, Table11.OUTPUTS)), listener, stop);
        Map<String, DataCheckEntry> rows = list.stream().collect(Collectors.toMap(DataCheckEntry::id, e -> e));
        assertEquals(String.join(", ", Prober.DATA_TYPES), rows.get("data-types").value(), "measured before the stop");
        DataCheckEntry inputs = rows.get("max-input-variables");
        assertEquals("2", inputs.value());
        assertEquals(DataCheckEntry.AT_LEAST, inputs.bound());
        assertTrue(inputs.note().startsWith("the probe was stopped: stopped by the test, during this row"), inputs.note());
        DataCheckEntry outputs = rows.get("max-output-variables");
        assertEquals(DataCheckEntry.NOT_MEASURED, outputs.bound());
        assertEquals("not measured: the probe was stopped: stopped by the test", outputs.note());
        assertEquals("not selected for this run", rows.get("max-nesting-depth").note());
    }
}
