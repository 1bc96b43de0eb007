package org.fclcert.fuzz;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fclcert.corpus.OutputScales;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.ExactInstance;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.eval.Trace;
import org.fclcert.model.DefaultValue;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Program;
import org.fclcert.model.VariableKind;

/**
 * A checked program loaded on the reference evaluator, with what the fuzzer needs about it: the output
 * scales of the tolerance classes and whether its steps depend on each other (DEFAULT NC, local variables).
 */
public final class ReferenceProgram {
    private final Program program;
    private final FunctionBlock block;
    private final LoadedProgram loaded;
    private final OutputScales scales;
    private final boolean stateful;

    /** One evaluated step: the inputs set, the reference's outputs and its trace. */
    public record Step(Map<String, Double> inputs, Map<String, Double> outputs, Trace trace) {
    }

    public ReferenceProgram(Program checkedProgram) {
        this.program = checkedProgram;
        this.block = checkedProgram.functionBlocks().get(0);
        this.loaded = Evaluator.load(checkedProgram);
        this.scales = OutputScales.of(block);
        this.stateful = block.defuzzifications().stream()
                .anyMatch(d -> d.defaultValue().orElse(null) instanceof DefaultValue.NoChange)
                || !block.variables(VariableKind.LOCAL).isEmpty();
    }

    public Program program() {
        return program;
    }

    public FunctionBlock block() {
        return block;
    }

    /** The program as the reference evaluator loaded it. */
    public LoadedProgram loaded() {
        return loaded;
    }

    public OutputScales scales() {
        return scales;
    }

    /** True when a step's outputs can depend on the steps before it. */
    public boolean stateful() {
        return stateful;
    }

    /**
     * Runs the steps in order on one fresh instance of the exact judging path (the expected values) and of
     * the fast path (its trace, for the derivation).
     */
    public List<Step> run(List<Map<String, Double>> steps) throws EvaluationException {
        FunctionBlockInstance instance = loaded.newInstance();
        ExactInstance exact = loaded.newExactInstance();
        List<Step> out = new ArrayList<>();
        for (Map<String, Double> in : steps) {
            Step fast = step(instance, in, true);
            for (Map.Entry<String, Double> e : in.entrySet()) {
                exact.set(e.getKey(), e.getValue());
            }
            exact.evaluate();
            out.add(new Step(in, new LinkedHashMap<>(exact.outputs()), fast.trace()));
        }
        return out;
    }

    /** The outputs of the last of {@code steps}, run in order on a fresh instance (no trace). */
    public Map<String, Double> last(List<Map<String, Double>> steps) throws EvaluationException {
        FunctionBlockInstance instance = loaded.newInstance();
        Map<String, Double> last = Map.of();
        int from = stateful ? 0 : steps.size() - 1;
        for (int i = Math.max(0, from); i < steps.size(); i++) {
            last = step(instance, steps.get(i), false).outputs();
        }
        return last;
    }

    private static Step step(FunctionBlockInstance instance, Map<String, Double> in, boolean traced)
            throws EvaluationException {
        for (Map.Entry<String, Double> e : in.entrySet()) {
            instance.set(e.getKey(), e.getValue());
        }
        Trace trace = traced ? new Trace() : null;
        instance.evaluate(trace);
        return new Step(in, new LinkedHashMap<>(instance.outputs()), trace);
    }
}
