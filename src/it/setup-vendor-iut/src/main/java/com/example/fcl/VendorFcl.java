package com.example.fcl;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.iut.spi.FclImplementation;
import org.fclcert.iut.spi.FclInstance;
import org.fclcert.iut.spi.FclLoadResult;
import org.fclcert.iut.spi.FclProgram;
import org.fclcert.model.Diagnostic;
import org.fclcert.syntax.StrictReader;

/** A vendor implementation that lacks NSUM: it rejects programs that declare it. */
public final class VendorFcl implements FclImplementation {
    private static final Pattern NSUM = Pattern.compile("\\bNSUM\\b", Pattern.CASE_INSENSITIVE);

    @Override
    public String name() {
        return "Vendor FCL";
    }

    @Override
    public String version() {
        return "1.0";
    }

    @Override
    public FclLoadResult load(String fcl) {
        Matcher m = NSUM.matcher(fcl);
        if (m.find()) {
            int line = 1 + (int) fcl.substring(0, m.start()).chars().filter(c -> c == '\n').count();
            return FclLoadResult.rejected("NSUM accumulation is not supported", line);
        }
        Analysis analysis = Analysis.analyze(new StrictReader(), "program", fcl);
        if (analysis.program().isEmpty()) {
            Diagnostic first = analysis.diagnostics().stream().filter(Diagnostic::isError).findFirst().orElseThrow();
            return FclLoadResult.rejected(first.message(), first.location().line());
        }
        LoadedProgram program = Evaluator.load(analysis.program().get());
        return FclLoadResult.loaded(new FclProgram() {
            @Override
            public List<String> blocks() {
                return program.functionBlockNames();
            }

            @Override
            public FclInstance newInstance(String block) {
                try {
                    return new Instance(block == null ? program.newInstance() : program.newInstance(block));
                } catch (EvaluationException e) {
                    throw new IllegalArgumentException(e.getMessage(), e);
                }
            }
        });
    }

    private record Instance(FunctionBlockInstance fb) implements FclInstance {
        @Override
        public void set(String name, double value) {
            try {
                fb.set(name, value);
            } catch (EvaluationException e) {
                throw new IllegalArgumentException(e.getMessage(), e);
            }
        }

        @Override
        public void evaluate() {
            try {
                fb.evaluate();
            } catch (EvaluationException e) {
                throw new IllegalStateException(e.getMessage(), e);
            }
        }

        @Override
        public double get(String name) {
            try {
                return fb.get(name);
            } catch (EvaluationException e) {
                throw new IllegalArgumentException(e.getMessage(), e);
            }
        }

        @Override
        public void reset() {
            fb.reset();
        }
    }
}
