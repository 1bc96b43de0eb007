package com.example.leaky;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import org.antlr.v4.runtime.CharStreams;
import org.fclcert.eval.Evaluator;
import org.fclcert.iut.spi.FclImplementation;
import org.fclcert.iut.spi.FclLoadResult;
import picocli.CommandLine;

/** Uses fclcert's evaluator, ANTLR, Jackson and picocli: none of them is on a compile path of fclcert-spi. */
public final class LeakyFcl implements FclImplementation {
    @Override
    public String name() {
        return "Leaky FCL " + List.of(Evaluator.class, CharStreams.class, ObjectMapper.class, CommandLine.class);
    }

    @Override
    public String version() {
        return "1.0";
    }

    @Override
    public FclLoadResult load(String fcl) {
        return FclLoadResult.rejected("never used");
    }
}
