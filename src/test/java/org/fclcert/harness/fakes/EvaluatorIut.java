package org.fclcert.harness.fakes;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.eval.Trace;
import org.fclcert.iut.ImplementationUnderTest;
import org.fclcert.iut.IutException;
import org.fclcert.iut.IutInfo;
import org.fclcert.iut.LoadOutcome;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Program;
import org.fclcert.syntax.StrictReader;

/**
 * A test implementation built on fclcert's strict reader, checks and reference evaluator, with three hooks
 * through which each fake brings in exactly one known defect: {@link #veto} (load decisions),
 * {@link #transform} (the program as the fake understands it) and {@link #adjust} (outputs, seen with the
 * evaluation's trace). With no hook overridden it is a correct implementation.
 */
public class EvaluatorIut implements ImplementationUnderTest {
    private final String name;
    private final List<String> claims;
    private Program program;
    private LoadedProgram loaded;
    private FunctionBlockInstance instance;
    private String instanceBlock;

    public EvaluatorIut(String name, List<String> claims) {
        this.name = name;
        this.claims = List.copyOf(claims);
    }

    public EvaluatorIut() {
        this("evaluator", List.of());
    }

    /** A load answer that overrides the strict analysis (e.g. accept anything, reject NOT). */
    protected Optional<LoadOutcome> veto(String fcl, Analysis analysis) {
        return Optional.empty();
    }

    /** The program as this implementation understands it. */
    protected Program transform(Program p) {
        return p;
    }

    /** The outputs this implementation gives, knowing the right ones and how they came about. */
    protected Map<String, Double> adjust(FunctionBlock block, Trace trace, Map<String, Double> outputs) {
        return outputs;
    }

    @Override
    public IutInfo hello() {
        return new IutInfo(name, "test", "java:" + getClass().getName(), claims, Map.of());
    }

    @Override
    public LoadOutcome load(String fcl) {
        Analysis analysis = Analysis.analyze(StrictReader.openLevel(), "case.fcl", fcl);   // the corpus language (Open Level methods)
        instance = null;
        loaded = null;
        Optional<LoadOutcome> vetoed = veto(fcl, analysis);
        if (vetoed.isPresent()) {
            return vetoed.get();
        }
        if (analysis.program().isEmpty()) {
            Diagnostic first = analysis.diagnostics().stream().filter(Diagnostic::isError).findFirst().orElseThrow();
            return new LoadOutcome.Rejected(first.code() + ": " + first.message(),
                    OptionalInt.of(first.location().line()));
        }
        program = transform(analysis.program().get());
        loaded = Evaluator.load(program);
        return new LoadOutcome.Loaded(loaded.functionBlockNames());
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        if (loaded == null) {
            throw new IutException(IutException.Kind.EVAL_ERROR, "no program loaded");
        }
        try {
            if (instance == null || (block != null && !block.equalsIgnoreCase(instanceBlock))) {
                instance = block == null ? loaded.newInstance() : loaded.newInstance(block);
                instanceBlock = instance.functionBlockName();
            }
            for (Map.Entry<String, Double> in : inputs.entrySet()) {
                instance.set(in.getKey(), in.getValue());
            }
            Trace trace = new Trace();
            instance.evaluate(trace);
            FunctionBlock fb = program.functionBlock(instance.functionBlockName()).orElseThrow();
            return adjust(fb, trace, new LinkedHashMap<>(instance.outputs()));
        } catch (EvaluationException e) {
            throw new IutException(IutException.Kind.EVAL_ERROR, e.getMessage());
        }
    }

    @Override
    public void reset() {
        if (instance != null) {
            instance.reset();
        }
    }

    @Override
    public Optional<String> export() {
        return Optional.empty();
    }

    @Override
    public void close() {
    }
}
