package org.fclcert.iut;

import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import org.fclcert.check.Analysis;
import org.fclcert.check.AnalysisMemo;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.iut.IutException.Kind;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.Names;
import org.fclcert.model.Program;
import org.fclcert.model.Toolkit;
import org.fclcert.syntax.ReaderOptions;
import org.fclcert.write.CanonicalWriter;

/**
 * fclcert's own front end and evaluator as an implementation under test, in process: a program is
 * rejected exactly when the strict reader (with the Open Level methods, ReaderOptions.OPEN_LEVEL) or a check
 * reports an error (the first error's code,
 * message and line are the rejection), and evaluated by the reference evaluator otherwise. It
 * exports with the canonical writer. Any exception other than an evaluation error is a bug in
 * fclcert and is reported as a crash rather than thrown.
 */
final class ReferenceIut implements ImplementationUnderTest {
    /** The source name diagnostics carry; the line numbers are those of the text as sent. */
    static final String SOURCE_NAME = "<iut>";

    private Program program;
    private LoadedProgram loaded;
    /** The reference evaluator (filtered exact evaluation, the one `fclcert eval` runs), one instance per block. */
    private final Map<String, FunctionBlockInstance> instances = new HashMap<>();
    /**
     * Whether each instance takes the compiled kernel from its first evaluation ({@link LoadedProgram#newCompiledInstance});
     * the same results, so only the corpus's second judgement (CorpusMutationTest) asks for it, to reach the kernel.
     */
    private final boolean compiledFromFirst;
    /** Evaluations that ran on the compiled kernel (counted for that judgement: which vectors reach the kernel). */
    private long kernelEvaluations;

    ReferenceIut() {
        this(false);
    }

    ReferenceIut(boolean compiledFromFirst) {
        this.compiledFromFirst = compiledFromFirst;
    }

    @Override
    public IutInfo hello() {
        List<String> claims = Arrays.stream(Feature.values()).filter(f -> !f.dialectSyntax()).map(Feature::id).toList();
        return new IutInfo("fclcert reference evaluator", Toolkit.version(), "reference", claims, Map.of());
    }

    @Override
    public LoadOutcome load(String fcl) throws IutException {
        Analysis analysis;
        try {
            // memoised: the prober has usually just judged this very text with the same reader
            analysis = AnalysisMemo.analyze(ReaderOptions.OPEN_LEVEL, SOURCE_NAME, fcl);
        } catch (RuntimeException e) {
            throw crash("reading and checking", e);
        }
        return loadAnalysed(analysis);
    }

    /** A library's layout is read with fclcert's reader of that dialect, then computed as the standard says. */
    @Override
    public LoadOutcome loadWritten(String text, org.fclcert.syntax.dialect.Dialect layout) throws IutException {
        Analysis analysis;
        try {
            analysis = Analysis.analyze(org.fclcert.syntax.dialect.DialectReaders.reader(layout), SOURCE_NAME, text);
        } catch (RuntimeException e) {
            throw crash("reading and checking", e);
        }
        return loadAnalysed(analysis);
    }

    private LoadOutcome loadAnalysed(Analysis analysis) throws IutException {
        program = null;
        loaded = null;
        instances.clear();
        if (analysis.program().isEmpty()) {
            return rejection(analysis.diagnostics());
        }
        try {
            loaded = Evaluator.load(analysis.program().get());
        } catch (RuntimeException e) {
            throw crash("compiling a checked program", e);
        }
        program = analysis.program().get();
        return new LoadOutcome.Loaded(loaded.functionBlockNames());
    }

    private static LoadOutcome rejection(List<Diagnostic> diagnostics) {
        return diagnostics.stream().filter(Diagnostic::isError).findFirst()
                .map(d -> new LoadOutcome.Rejected(d.code() + ": " + d.message(),
                        d.location().line() > 0 ? OptionalInt.of(d.location().line()) : OptionalInt.empty()))
                .orElseGet(() -> new LoadOutcome.Rejected("the program could not be read", OptionalInt.empty()));
    }

    @Override
    public Map<String, Double> eval(String block, Map<String, Double> inputs) throws IutException {
        FunctionBlockInstance instance = instance(block);
        try {
            for (Map.Entry<String, Double> input : inputs.entrySet()) {
                instance.setInput(instance.inputIndex(input.getKey()), input.getValue());
            }
            long compiled = instance.compiledEvaluations();
            instance.evaluate();
            kernelEvaluations += instance.compiledEvaluations() - compiled;
            Map<String, Double> out = new LinkedHashMap<>();
            List<String> names = instance.outputNames();
            for (int i = 0; i < names.size(); i++) {
                out.put(names.get(i), instance.output(i));
            }
            return out;
        } catch (EvaluationException e) {
            throw new IutException(Kind.EVAL_ERROR, e.toString());
        } catch (RuntimeException e) {
            throw crash("evaluating", e);
        }
    }

    private FunctionBlockInstance instance(String block) throws IutException {
        if (loaded == null) {
            throw new IutException(Kind.EVAL_ERROR, "no program is loaded");
        }
        String name = block == null ? loaded.functionBlockNames().get(0) : block;
        FunctionBlockInstance instance = instances.get(Names.key(name));
        if (instance == null) {
            try {
                instance = compiledFromFirst ? loaded.newCompiledInstance(name) : loaded.newInstance(name);
            } catch (EvaluationException e) {
                throw new IutException(Kind.EVAL_ERROR, e.toString());
            }
            instances.put(Names.key(name), instance);
        }
        return instance;
    }

    /** How many evaluations so far ran on the compiled kernel. */
    long kernelEvaluations() {
        return kernelEvaluations;
    }

    @Override
    public void reset() {
        instances.clear();
    }

    @Override
    public Optional<String> export() throws IutException {
        if (program == null) {
            throw new IutException(Kind.EVAL_ERROR, "no program is loaded");
        }
        try {
            return Optional.of(new CanonicalWriter().write(program));
        } catch (RuntimeException e) {
            throw crash("exporting", e);
        }
    }

    @Override
    public org.fclcert.sandbox.Isolation isolation() {
        return org.fclcert.sandbox.Isolation.inProcess("the reference evaluator is fclcert's own code, called in its JVM");
    }

    @Override
    public void close() {
        instances.clear();
    }

    private static IutException crash(String what, RuntimeException e) {
        return new IutException(Kind.CRASH, "the reference implementation failed while " + what + ": " + e);
    }
}
