package org.fclcert.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.fclcert.check.Analysis;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;
import org.fclcert.write.CanonicalWriter;
import org.junit.jupiter.api.Test;

/**
 * The screen in front of the exact judge never passes a step the exact judge calls a knife edge: on generated
 * programs and their candidate steps (breakpoints, plateaus, midpoints, outside, anywhere — and each of those one
 * ulp off, where a jump sits right beside the input), every step the screen passes is fair by the exact judge
 * alone. The screen must also pass most steps (else it saves nothing), and the candidates must hold knife edges
 * (else the test could not fail). {@code -Dfclcert.screen.programs=N} runs it on N programs (default 150; it was
 * run on 6000 when the screen was written).
 */
class ScreenedFairnessTest {
    private static final CanonicalWriter WRITER = new CanonicalWriter();

    @Test
    void everyStepTheScreenPassesIsFairByTheExactJudge() {
        ProgramGenerator generator = new ProgramGenerator(FuzzSettings.open());
        VectorGenerator candidates = new VectorGenerator((p, before, step) -> true);
        ExactFairness exact = new ExactFairness();
        int passed = 0;
        int steps = 0;
        int knifeEdges = 0;
        List<String> wrong = new ArrayList<>();
        long programs = Long.getLong("fclcert.screen.programs", 150);
        for (long seed = 0; seed < programs; seed++) {
            Program generated = generator.generate(Fuzzer.programSeed(11, seed));
            Program program = Analysis.analyze(StrictReader.openLevel(), "fuzz.fcl", WRITER.write(generated)).program()
                    .orElseThrow();
            ReferenceProgram ref = new ReferenceProgram(program);
            Random r = new Random(seed);
            List<Map<String, Double>> before = new ArrayList<>();
            for (Map<String, Double> step : candidates.steps(ref, r)) {
                for (Map<String, Double> s : List.of(step, oneUlpOff(step, r))) {
                    List<Map<String, Double>> sequence = new ArrayList<>(ref.stateful() ? before : List.of());
                    sequence.add(s);
                    boolean screen = ScreenedFairness.passes(ref, sequence);
                    boolean fair = exact.fair(ref, before, s);
                    steps++;
                    passed += screen ? 1 : 0;
                    knifeEdges += fair ? 0 : 1;
                    if (screen && !fair) {
                        wrong.add("seed " + seed + ", steps " + before + " then " + s + "\n" + WRITER.write(program));
                    }
                }
                before.add(step);
            }
        }
        System.out.printf("screen: %d programs, %d steps, %d passed by the screen, %d knife edges%n", programs, steps,
                passed, knifeEdges);
        assertEquals(List.of(), wrong.stream().limit(3).toList(), wrong.size() + " steps passed by the screen are knife edges");
        assertTrue(passed > steps / 2, "the screen passed only " + passed + " of " + steps + " steps");
        assertTrue(knifeEdges > programs / 30, "the candidates held only " + knifeEdges + " knife edges: the test cannot tell");
    }

    /** The step with one of its inputs moved by one ulp: beside a breakpoint, a tie or a foot instead of on it. */
    static Map<String, Double> oneUlpOff(Map<String, Double> step, Random r) {
        Map<String, Double> out = new LinkedHashMap<>(step);
        List<String> names = new ArrayList<>(step.keySet());
        if (!names.isEmpty()) {
            String name = names.get(r.nextInt(names.size()));
            double v = step.get(name);
            out.put(name, r.nextBoolean() ? Math.nextUp(v) : Math.nextDown(v));
        }
        return out;
    }
}
