package org.fclcert.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.fclcert.cli.SourceFiles.FileProblem;
import org.fclcert.eval.EvaluationException;
import org.fclcert.eval.Evaluator;
import org.fclcert.eval.FunctionBlockInstance;
import org.fclcert.eval.Trace;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Names;
import org.fclcert.model.Program;
import org.fclcert.model.Variable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fclcert eval}: runs a checked program on the reference evaluator. */
@Command(name = "eval", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "Evaluate a valid FCL program with fclcert's reference evaluator (exact, closed-form "
                + "defuzzification; readings in docs/semantics.md). Prints one name=value line per output. "
                + "With --csv, evaluates one row per step on one function block instance, so DEFAULT NC and "
                + "unset inputs carry over, and writes CSV: input columns, then output columns.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = {"0:evaluated", "1:the program has errors, or an input or evaluation error",
            ExitCodes.USAGE_LINE, ExitCodes.INTERNAL_LINE})
final class EvalCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "FILE", description = "an FCL source file")
    String file;

    @Option(names = "--dialect", defaultValue = "strict", paramLabel = "DIALECT",
            completionCandidates = DialectName.Names.class, description = DialectName.DESCRIPTION)
    DialectName dialect;

    @Option(names = "--block", paramLabel = "NAME", description = "function block to evaluate (default: the first)")
    String block;

    @Option(names = "--in", paramLabel = "NAME=VALUE",
            description = "an input value (repeatable); with --csv, values before the first row")
    List<String> inputs = new ArrayList<>();

    @Option(names = "--trace", description = "also print every stage: term degrees, rule degrees, activations, "
            + "accumulated sets, results (not with --csv)")
    boolean trace;

    @Option(names = "--csv", paramLabel = "FILE",
            description = "input rows: a header of input names, then one row of numbers per step; "
                    + "an empty cell keeps the input's previous value")
    String csv;

    @Option(names = "--ignore-unknown-columns", description = "with --csv: skip columns that name no input of the"
            + " block (a time stamp, a logged output); they are not passed through to the output")
    boolean ignoreUnknownColumns;

    @Option(names = "--out", paramLabel = "FILE", description = "write the result here instead of stdout")
    String outFile;

    @Option(names = "--format", defaultValue = "text", paramLabel = "FORMAT",
            description = "text or json (default: ${DEFAULT-VALUE}); with --csv, text means CSV")
    OutputFormat format;

    /** A problem with the inputs or the evaluation: reported in one sentence, exit code 1. */
    static final class InputProblem extends Exception {
        private static final long serialVersionUID = 1L;

        InputProblem(String message) {
            super(message);
        }
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        if (trace && csv != null) {
            err.println("fclcert: --trace cannot be combined with --csv (trace one step with --in instead)");
            return ExitCodes.USAGE;
        }
        List<String> named = new ArrayList<>();
        for (String in : inputs) {
            if (in.indexOf('=') <= 0) {
                err.println("fclcert: --in " + TerminalText.visible(in) + ": expected NAME=VALUE, e.g. --in temp=5");
                return ExitCodes.USAGE;
            }
            String name = in.substring(0, in.indexOf('=')).trim();
            if (named.stream().anyMatch(n -> Names.same(n, name))) {
                // last-wins would hide a typo in a long command line
                err.println("fclcert: --in " + TerminalText.visible(name) + " is given twice; give each input once");
                return ExitCodes.USAGE;
            }
            named.add(name);
        }
        try {
            Optional<Program> program = checkedProgram(err);
            if (program.isEmpty()) {
                return ExitCodes.ERRORS;
            }
            String result = csv == null ? single(program.get()) : steps(program.get());
            if (outFile == null) {
                spec.commandLine().getOut().print(result);
            } else {
                SourceFiles.write(outFile, result);
            }
            return ExitCodes.OK;
        } catch (FileProblem e) {
            err.println("fclcert: " + TerminalText.visible(e.getMessage()));
            return ExitCodes.USAGE;
        } catch (EvaluationException e) {
            // the message may quote a cell of the CSV table or a --in value: shown, never acted upon by the terminal
            err.println("fclcert: " + e.code() + ": " + TerminalText.visible(e.getMessage()));
            return ExitCodes.ERRORS;
        } catch (InputProblem e) {
            err.println("fclcert: " + TerminalText.visible(e.getMessage()));
            return ExitCodes.ERRORS;
        }
    }

    /** Reads and checks FILE; diagnostics go to stderr, and a program with errors is not evaluated. */
    private Optional<Program> checkedProgram(PrintWriter err) throws FileProblem {
        return CheckedSource.read(file, dialect, "evaluated", err).program();
    }

    private FunctionBlock declaration(Program program) {
        return block == null ? program.functionBlocks().get(0)
                : program.functionBlock(block).orElse(program.functionBlocks().get(0));
    }

    private Run start(Program program) throws EvaluationException, InputProblem {
        var loaded = Evaluator.load(program);
        FunctionBlockInstance fb = block == null ? loaded.newInstance() : loaded.newInstance(block);
        Run run = new Run(fb, declaration(program));
        for (String in : inputs) {
            int eq = in.indexOf('=');
            String name = in.substring(0, eq).trim();
            run.requireInput(name, "--in " + in);
            run.set(name, in.substring(eq + 1).trim(), "--in " + in);
        }
        return run;
    }

    private String single(Program program) throws EvaluationException, InputProblem {
        Run run = start(program);
        Trace t = trace ? new Trace() : null;
        run.evaluate(t, "");
        Map<String, Double> outputs = run.fb.outputs();
        if (format == OutputFormat.json) {
            Map<String, Object> json = new LinkedHashMap<>();
            json.put("block", run.fb.functionBlockName());
            json.put("inputs", run.inputValues());
            json.put("outputs", outputs);
            if (t != null) {
                json.put("trace", TracePrinter.json(t));
            }
            return DiagnosticPrinter.toJson(json) + "\n";
        }
        StringBuilder sb = new StringBuilder();
        outputs.forEach((name, value) -> sb.append(name).append('=').append(Double.toString(value)).append('\n'));
        if (t != null) {
            sb.append(TracePrinter.text(t));
        }
        return sb.toString();
    }

    private String steps(Program program) throws EvaluationException, InputProblem, FileProblem {
        Run run = start(program);
        List<String> lines = SourceFiles.read(csv).lines().toList();
        CsvTable table = CsvTable.parse(csv, lines);
        boolean[] skipped = new boolean[table.columns().size()];
        for (int c = 0; c < table.columns().size(); c++) {
            String column = table.columns().get(c);
            for (int before = 0; before < c; before++) {
                if (Names.same(table.columns().get(before), column)) {
                    throw new InputProblem(csv + ":" + table.headerLine() + ": column '" + column + "' is given twice"
                            + " (columns " + (before + 1) + " and " + (c + 1) + "); give each input one column");
                }
            }
            if (ignoreUnknownColumns && run.fb.inputNames().stream().noneMatch(n -> Names.same(n, column))) {
                skipped[c] = true;
                continue;
            }
            // a header typo is the header's mistake, found before any row runs
            run.requireInput(column, csv + ":" + table.headerLine() + ": column '" + column + "'");
        }
        List<Map<String, Object>> json = new ArrayList<>();
        StringBuilder sb = new StringBuilder(header(run.fb));
        for (CsvTable.Row row : table.rows()) {
            String where = csv + ":" + row.line();
            for (int c = 0; c < table.columns().size(); c++) {
                if (!skipped[c] && !row.cells().get(c).isEmpty()) {
                    run.set(table.columns().get(c), row.cells().get(c), where);
                }
            }
            run.evaluate(null, where + ": ");
            Map<String, Object> step = new LinkedHashMap<>();
            step.put("inputs", run.inputValues());
            step.put("outputs", run.fb.outputs());
            json.add(step);
            sb.append(csvRow(run));
        }
        return format == OutputFormat.json ? DiagnosticPrinter.jsonLines(json) + "\n" : sb.toString();
    }

    private static String header(FunctionBlockInstance fb) {
        List<String> names = new ArrayList<>(fb.inputNames());
        names.addAll(fb.outputNames());
        return String.join(",", names) + "\n";
    }

    private static String csvRow(Run run) {
        List<String> cells = new ArrayList<>();
        run.inputValues().values().forEach(v -> cells.add(Double.toString(v)));
        run.fb.outputs().values().forEach(v -> cells.add(Double.toString(v)));
        return String.join(",", cells) + "\n";
    }

    /** A decimal number; NaN and Infinity are numbers too, which the evaluator refuses (FCL-V002) by name. */
    private static final java.util.regex.Pattern DECIMAL = java.util.regex.Pattern.compile(
            "\\s*[+-]?((\\d+(\\.\\d*)?|\\.\\d+)([eE][+-]?\\d+)?|NaN|Infinity)\\s*");

    /** One instance and which of its inputs have a value (declared initial value or given). */
    private static final class Run {
        final FunctionBlockInstance fb;
        private final Map<String, Boolean> hasValue = new LinkedHashMap<>();

        Run(FunctionBlockInstance fb, FunctionBlock declaration) {
            this.fb = fb;
            Map<String, Variable> declared = new java.util.HashMap<>();   // one pass: 10^5 inputs were quadratic
            for (Variable v : declaration.variables()) {
                declared.putIfAbsent(Names.key(v.name()), v);
            }
            for (String input : fb.inputNames()) {
                Variable v = declared.get(Names.key(input));
                hasValue.put(Names.key(input), v != null && v.initialValue().isPresent());
            }
        }

        /** An unknown name is reported with the inputs there are, and the one it most likely misspells. */
        void requireInput(String name, String where) throws EvaluationException {
            try {
                fb.get(name);
            } catch (EvaluationException e) {
                List<String> names = fb.inputNames();
                String hint = Names.closest(name, names).map(n -> "did you mean '" + n + "'? ").orElse("");
                throw new EvaluationException(e.diagnosticCode(), where + ": " + e.getMessage() + "; " + hint
                        + (names.size() == 1 ? "its input: " : "its inputs: ") + Names.listed(names));
            }
        }

        void set(String name, String text, String where) throws EvaluationException, InputProblem {
            double value;
            if (!DECIMAL.matcher(text).matches()) {
                // Double.parseDouble would also take 0x1p2, 5d and 5f: Java spellings, not numbers to a user
                throw new InputProblem(where + ": '" + text + "' is not a number: write a decimal number"
                        + " such as 4, -2.5 or 1.5E3");
            }
            try {
                value = Double.parseDouble(text);
            } catch (NumberFormatException e) {
                throw new InputProblem(where + ": '" + text + "' is not a number");
            }
            try {
                fb.set(name, value);
            } catch (EvaluationException e) {
                throw new EvaluationException(e.diagnosticCode(), where + ": " + e.getMessage());
            }
            hasValue.put(Names.key(name), true);
        }

        void evaluate(Trace trace, String where) throws EvaluationException, InputProblem {
            for (String input : fb.inputNames()) {
                if (!hasValue.get(Names.key(input))) {
                    throw new InputProblem(where + "input '" + input + "' has no value: give it one (--in "
                            + input + "=VALUE or a CSV column) or declare an initial value");
                }
            }
            try {
                fb.evaluate(trace);
            } catch (EvaluationException e) {
                throw new EvaluationException(e.diagnosticCode(), where + e.getMessage());
            }
        }

        Map<String, Double> inputValues() {
            Map<String, Double> values = new LinkedHashMap<>();
            for (String input : fb.inputNames()) {
                try {
                    values.put(input, fb.get(input));
                } catch (EvaluationException e) {
                    throw new IllegalStateException(e);
                }
            }
            return values;
        }
    }
}
