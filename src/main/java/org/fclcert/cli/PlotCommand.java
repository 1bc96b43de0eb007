package org.fclcert.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.fclcert.cli.SourceFiles.FileProblem;
import org.fclcert.eval.EvaluationException;
import org.fclcert.model.Program;
import org.fclcert.plot.Plotter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fclcert plot}: SVG pictures of a program's terms, control surfaces and transfer curves. */
@Command(name = "plot", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "Draw a valid FCL program as self-contained SVG files: the terms of every input and output; "
                + "for each output, its control surface over the first two inputs (or --axes) as a heat map with a colour "
                + "scale (other inputs fixed at --in values, else initial values, else the middle of their terms),"
                + " or with one input its transfer curve; hatched, the regions where no rule fires (FCL-W005). Values come from the reference evaluator, sampled for "
                + "drawing only. Prints the files written.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = {"0:drawn", "1:the program has errors, or an input or evaluation error",
            ExitCodes.USAGE_LINE, ExitCodes.INTERNAL_LINE})
final class PlotCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "FILE", description = "an FCL source file")
    String file;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "plots",
            description = "directory for the SVG files (default: ${DEFAULT-VALUE})")
    String outDir;

    @Option(names = "--dialect", defaultValue = "strict", paramLabel = "DIALECT",
            completionCandidates = DialectName.Names.class, description = DialectName.DESCRIPTION)
    DialectName dialect;

    @Option(names = "--block", paramLabel = "NAME", description = "function block to draw (default: the first)")
    String block;

    @Option(names = "--axes", paramLabel = "X,Y", split = ",",
            description = "the two inputs a control surface is drawn over (default: the first two inputs)")
    List<String> axes = new ArrayList<>();

    @Option(names = "--in", paramLabel = "NAME=VALUE",
            description = "the value an input is held at where it is not an axis (repeatable)")
    List<String> inputs = new ArrayList<>();

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        Map<String, Double> given = new LinkedHashMap<>();
        for (String in : inputs) {
            int eq = in.indexOf('=');
            if (eq <= 0) {
                err.println("fclcert: --in " + in + ": expected NAME=VALUE, e.g. --in temp=5");
                return ExitCodes.USAGE;
            }
            String name = in.substring(0, eq).trim();
            if (given.keySet().stream().anyMatch(n -> org.fclcert.model.Names.same(n, name))) {
                err.println("fclcert: --in " + name + " is given twice; give each input once");
                return ExitCodes.USAGE;
            }
            try {
                given.put(name, Double.parseDouble(in.substring(eq + 1).trim()));
            } catch (NumberFormatException e) {
                err.println("fclcert: --in " + in + ": '" + in.substring(eq + 1).trim() + "' is not a number");
                return ExitCodes.USAGE;
            }
        }
        try {
            Optional<Program> program = CheckedSource.read(file, dialect, "drawn", err).program();
            if (program.isEmpty()) {
                return ExitCodes.ERRORS;
            }
            if (block != null && program.get().functionBlock(block).isEmpty()) {
                err.println("fclcert: " + file + " has no function block '" + block + "'");
                return ExitCodes.ERRORS;
            }
            Plotter plotter = new Plotter(program.get(), block, given);
            if (!axes.isEmpty()) {
                if (axes.size() != 2) {
                    err.println("fclcert: --axes takes two inputs, X,Y (e.g. --axes error,trend), not " + axes.size());
                    return ExitCodes.USAGE;
                }
                try {
                    plotter.withAxes(axes.get(0).trim(), axes.get(1).trim());
                } catch (IllegalArgumentException e) {
                    err.println("fclcert: " + e.getMessage());
                    return ExitCodes.USAGE;
                }
            }
            for (String name : given.keySet()) {
                if (!plotter.hasInput(name)) {
                    String hint = org.fclcert.model.Names.closest(name, plotter.inputNames())
                            .map(n -> "did you mean '" + n + "'? ").orElse("");
                    err.println("fclcert: --in " + name + ": not an input of the function block; " + hint
                            + "its inputs: " + org.fclcert.model.Names.listed(plotter.inputNames()));
                    return ExitCodes.ERRORS;
                }
            }
            List<Plotter.Picture> pictures = plotter.pictures();
            try {
                java.nio.file.Files.createDirectories(Path.of(outDir));
            } catch (java.io.IOException | java.nio.file.InvalidPathException e) {
                err.println("fclcert: cannot create " + outDir + ": " + e.getMessage());
                return ExitCodes.USAGE;
            }
            for (Plotter.Picture p : pictures) {
                String path = Path.of(outDir).resolve(p.fileName()).toString();
                SourceFiles.write(path, p.svg());
                spec.commandLine().getOut().println(path);
            }
            return ExitCodes.OK;
        } catch (FileProblem e) {
            err.println("fclcert: " + e.getMessage());
            return ExitCodes.USAGE;
        } catch (EvaluationException e) {
            err.println("fclcert: " + e.code() + ": " + e.getMessage());
            return ExitCodes.ERRORS;
        }
    }
}
