package org.fclcert.fuzz;

import java.util.List;
import org.fclcert.check.Analysis;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.LoadedProgram;
import org.fclcert.iut.spi.FclImplementation;
import org.fclcert.iut.spi.FclInstance;
import org.fclcert.iut.spi.FclLoadResult;
import org.fclcert.iut.spi.FclProgram;
import org.fclcert.syntax.StrictReader;
import org.fclcert.syntax.dialect.Dialect;
import org.fclcert.syntax.dialect.DialectReaders;

/** Java SPI implementations for the command-line tests ({@code --iut java:CLASS}), on the reference evaluator. */
public final class SpiFakes {
    private SpiFakes() {
    }

    /** Correct except that NSUM is read as BSUM. */
    public static class NsumAsBsum implements FclImplementation {
        @Override
        public String name() {
            return "nsum-as-bsum";
        }

        @Override
        public String version() {
            return "1";
        }

        protected String rewrite(String fcl) {
            return fcl.replace("ACCU : NSUM", "ACCU : BSUM");
        }

        /** The program as this implementation reads it. */
        protected Analysis analyze(String fcl) {
            return Analysis.analyze(StrictReader.openLevel(), "in.fcl", rewrite(fcl));
        }

        @Override
        public FclLoadResult load(String fcl) {
            Analysis a = analyze(fcl);
            if (a.program().isEmpty()) {
                return FclLoadResult.rejected(a.diagnostics().get(0).message(), a.diagnostics().get(0).location().line());
            }
            LoadedProgram loaded = Evaluator.load(a.program().get());
            return FclLoadResult.loaded(new FclProgram() {
                @Override
                public List<String> blocks() {
                    return loaded.functionBlockNames();
                }

                @Override
                public FclInstance newInstance(String block) {
                    try {
                        return instance(loaded.newInstance(block));
                    } catch (EvaluationException e) {
                        throw new IllegalArgumentException(e.getMessage());
                    }
                }
            });
        }
    }

    /**
     * Reads only fuzzylite's layout (a text the strict reader reads is refused, as fuzzylite refuses standard FCL)
     * and computes NSUM as BSUM: what {@code --present-as fuzzylite} is for.
     */
    public static final class FuzzyliteLayoutOnly extends NsumAsBsum {
        @Override
        public String name() {
            return "fuzzylite-layout-only";
        }

        @Override
        protected Analysis analyze(String fcl) {
            if (!Analysis.analyze(StrictReader.openLevel(), "in.fcl", fcl).hasErrors()) {
                return Analysis.analyze(StrictReader.openLevel(), "in.fcl", "not fuzzylite's layout");
            }
            return Analysis.analyze(DialectReaders.reader(Dialect.FUZZYLITE), "in.fcl", rewrite(fcl));
        }
    }

    /** Correct, but its loader throws on any program that negates. */
    public static final class CrashesOnNot extends NsumAsBsum {
        @Override
        public String name() {
            return "crashes-on-not";
        }

        @Override
        protected String rewrite(String fcl) {
            if (fcl.contains("NOT")) {
                throw new IllegalStateException("NOT is not implemented");
            }
            return fcl;
        }
    }

    static FclInstance instance(FunctionBlockInstance fb) {
        return new FclInstance() {
            @Override
            public void set(String name, double value) {
                try {
                    fb.set(name, value);
                } catch (EvaluationException e) {
                    throw new IllegalArgumentException(e.getMessage());
                }
            }

            @Override
            public void evaluate() {
                try {
                    fb.evaluate();
                } catch (EvaluationException e) {
                    throw new IllegalStateException(e.getMessage());
                }
            }

            @Override
            public double get(String name) {
                try {
                    return fb.get(name);
                } catch (EvaluationException e) {
                    throw new IllegalArgumentException(e.getMessage());
                }
            }

            @Override
            public void reset() {
                fb.reset();
            }
        };
    }
}
