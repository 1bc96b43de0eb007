package org.fclcert.harness;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.LoadOutcome;

/**
 * A test implementation whose every answer is scripted: what {@code load} says and how {@code eval} maps
 * inputs to outputs. It records the calls it receives so tests can assert what the runner asked.
 */
public class ScriptedIut implements ImplementationUnderTest {
    /** How an evaluation answers; may throw to simulate errors, crashes and timeouts. */
    public interface Evaluation {
        Map<String, Double> apply(int call, Map<String, Double> inputs) throws IutException;
    }

    /** How a load answers. */
    public interface Loading {
        LoadOutcome apply(String fcl) throws IutException;
    }

    public final List<String> calls = new ArrayList<>();
    private final Loading loading;
    private final Evaluation evaluation;
    private Optional<String> exported = Optional.empty();
    private int evals;

    public ScriptedIut(Loading loading, Evaluation evaluation) {
        this.loading = loading;
        this.evaluation = evaluation;
    }

    public static ScriptedIut loading(Evaluation evaluation) {
        return new ScriptedIut(fcl -> new LoadOutcome.Loaded(List.of("fb")), evaluation);
    }

    public ScriptedIut exporting(String text) {
        exported = Optional.of(text);
        return this;
    }

    @Override
    public IutInfo hello() {
        return new IutInfo("scripted", "1", "in-process", List.of(), Map.of());
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        calls.add("load");
        evals = 0;
        return loading.apply(fcl);
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        calls.add("eval " + inputs);
        return evaluation.apply(++evals, inputs);
    }

    @Override
    public void reset() {
        calls.add("reset");
    }

    @Override
    public Optional<String> export() {
        calls.add("export");
        return exported;
    }

    @Override
    public void close() {
    }
}
