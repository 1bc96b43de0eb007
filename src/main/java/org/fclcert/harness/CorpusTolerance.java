package org.fclcert.harness;

import org.fclcert.corpus.OutputScales;
import org.fclcert.corpus.Tolerance;

/** The corpus's tolerance class applied with one program's output widths. */
record CorpusTolerance(Tolerance tolerance, OutputScales scales) implements OutputTolerance {

    @Override
    public String describe() {
        return tolerance.word();
    }

    @Override
    public double allowedError(String output, double expected) {
        return tolerance.allowed(expected, scales.width(output));
    }
}
