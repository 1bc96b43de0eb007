package org.fclcert.iut;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.ByteArrayOutputStream;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.model.Names;

/**
 * The child-JVM side of the {@code jfuzzylogic:JAR} adapter ({@link JFuzzyLogicIut}): a program that speaks
 * fclcert's JSON-lines protocol ({@code docs/iut-protocol.md}) and answers by calling jFuzzyLogic through
 * reflection, so fclcert compiles without it. It runs in a JVM of its own because jFuzzyLogic prints to
 * standard output and error, keeps static state and overflows its stack on deep nesting.
 *
 * <p>Standard output is the protocol channel only: before the library is touched, {@code System.out} and
 * {@code System.err} are redirected into a capture that also copies to the real standard error. What the
 * library printed while reading a program decides the answer: jFuzzyLogic reports ANTLR parse errors by
 * printing them ({@code line 12:5 mismatched input …}) and still returns a system, so printed parse errors
 * are a rejection, with the line of the first. An ANTLR {@code RecognitionException}, a plain
 * {@code RuntimeException} (jFuzzyLogic's own way to refuse) or a {@code NumberFormatException} is a
 * rejection too; any other throwable (a {@code NullPointerException}, a {@code StackOverflowError}, …) is an
 * internal failure, answered with error kind {@code crash} so that it is recorded as an errored case and the
 * session goes on.
 */
public final class JFuzzyLogicBridge {
    private static final Pattern ANTLR_ERROR = Pattern.compile("(?m)^line \\d+:\\d+ .*$");
    private static final Pattern BLOCK = Pattern.compile("(?i)\\bFUNCTION_BLOCK\\s+([A-Za-z_][A-Za-z0-9_]*)");
    private static final Pattern COMMENT = Pattern.compile("\\(\\*.*?(\\*\\)|\\z)", Pattern.DOTALL);

    private final BridgeLoop loop;
    private final Capture capture;
    private final Method createFromString;
    private final String version;

    private String text;
    private Object fis;
    private List<String> blocks = List.of();

    private JFuzzyLogicBridge(BridgeLoop loop, Capture capture) throws ReflectiveOperationException {
        this.loop = loop;
        this.capture = capture;
        Class<?> fisType = Class.forName("net.sourceforge.jFuzzyLogic.FIS");
        this.createFromString = fisType.getMethod("createFromString", String.class, boolean.class);
        Class<?> info = Class.forName("net.sourceforge.jFuzzyLogic.JFuzzyLogic");
        this.version = String.valueOf(info.getField("VERSION_SHORT").get(null)).strip();
    }

    /** Reads requests from standard input until {@code bye} or its end; one reply line per request. */
    public static void main(String[] args) throws IOException {
        BridgeLoop loop = new BridgeLoop();
        PrintStream stderr = new PrintStream(new FileOutputStream(FileDescriptor.err), true, StandardCharsets.UTF_8);
        Capture capture = new Capture(stderr);
        PrintStream captured = new PrintStream(capture, true, StandardCharsets.UTF_8);
        System.setOut(captured);
        System.setErr(captured);
        JFuzzyLogicBridge bridge;
        try {
            bridge = new JFuzzyLogicBridge(loop, capture);
        } catch (ReflectiveOperationException | LinkageError e) {
            stderr.println("fclcert jfuzzylogic bridge: jFuzzyLogic is not on the class path: " + e);
            stderr.flush();
            Runtime.getRuntime().halt(2);
            return;
        }
        loop.serve(bridge::answer);
    }

    private ObjectNode answer(String op, JsonNode request) {
        try {
            return switch (op) {
                case "hello" -> hello();
                case "load" -> load(request.path("fcl").asText());
                case "eval" -> eval(request.hasNonNull("block") ? request.get("block").asText() : null,
                        request.path("inputs"));
                case "reset" -> reset();
                case "export" -> export();
                case "bye" -> ok();
                default -> error("error", "unknown op '" + op + "'");
            };
        } catch (Refusal r) {
            // a refusal while building what it read is a rejection of the program; elsewhere an evaluation error
            return op.equals("load") ? rejected(r.getMessage(), OptionalInt.empty()) : error("error", r.getMessage());
        } catch (Throwable t) {
            // anything else is jFuzzyLogic failing inside (or the JVM running out of stack or memory)
            return error("crash", describe(t) + where(t));
        }
    }

    private ObjectNode hello() {
        ObjectNode reply = ok();
        ObjectNode implementation = reply.putObject("implementation");
        implementation.put("name", "jFuzzyLogic");
        implementation.put("version", version);
        return reply;
    }

    private ObjectNode load(String fcl) throws Throwable {
        text = null;
        fis = null;
        blocks = List.of();
        capture.start();
        Object system;
        try {
            system = createFromString.invoke(null, fcl, false);
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            String printed = capture.stop();
            Optional<String> parseError = firstParseError(printed);
            if (isRefusal(cause)) {
                String message = String.valueOf(cause.getMessage() == null ? describe(cause) : cause.getMessage());
                return rejected("jFuzzyLogic: " + parseError.orElse(message), refusalLine(cause, printed));
            }
            if (parseError.isPresent()) {
                // it reported the error, then its tree walker tripped over what error recovery left: a rejection
                return rejected("jFuzzyLogic: " + parseError.get() + " (then it failed internally: " + describe(cause)
                        + where(cause) + ")", LibraryMessages.antlrLine(parseError.get()));
            }
            throw cause;
        }
        String printed = capture.stop();
        Optional<String> parseError = firstParseError(printed);
        if (parseError.isPresent()) {
            return rejected("jFuzzyLogic printed a parse error and still returned a system: " + parseError.get(),
                    LibraryMessages.antlrLine(parseError.get()));
        }
        if (system == null) {
            String said = printed.strip();
            return rejected("jFuzzyLogic built no system" + (said.isEmpty() ? "" : ": " + firstLine(said)),
                    OptionalInt.empty());
        }
        List<String> names = blockNames(system, fcl);
        startInputsAtZero(system);
        text = fcl;
        fis = system;
        blocks = names;
        ObjectNode reply = ok();
        names.forEach(reply.putArray("blocks")::add);
        return reply;
    }

    /** jFuzzyLogic's own refusals: ANTLR's exceptions, its plain RuntimeExceptions, unreadable numbers. */
    private static boolean isRefusal(Throwable t) {
        for (Class<?> c = t.getClass(); c != null; c = c.getSuperclass()) {
            if (c.getName().equals("org.antlr.runtime.RecognitionException")) {
                return true;
            }
        }
        return t.getClass() == RuntimeException.class || t instanceof NumberFormatException;
    }

    private static OptionalInt refusalLine(Throwable cause, String printed) {
        Optional<String> parseError = firstParseError(printed);
        if (parseError.isPresent()) {
            return LibraryMessages.antlrLine(parseError.get());
        }
        try {
            // RecognitionException carries the token's line in a public field
            Object line = cause.getClass().getField("line").get(cause);
            if (line instanceof Integer n && n > 0) {
                return OptionalInt.of(n);
            }
        } catch (ReflectiveOperationException | RuntimeException e) {
            // not an ANTLR exception
        }
        return LibraryMessages.antlrLine(String.valueOf(cause.getMessage()));
    }

    private static Optional<String> firstParseError(String printed) {
        Matcher m = ANTLR_ERROR.matcher(printed);
        return m.find() ? Optional.of(m.group().strip()) : Optional.empty();
    }

    /** The function blocks in the order written, each named as jFuzzyLogic stored it. */
    private List<String> blockNames(Object system, String fcl) throws Throwable {
        List<String> stored = new ArrayList<>();
        for (Object fb : (Iterable<?>) system) {
            stored.add(String.valueOf(call(fb, "getName")));
        }
        List<String> names = new ArrayList<>();
        Matcher m = BLOCK.matcher(COMMENT.matcher(fcl).replaceAll(" "));
        while (m.find()) {
            for (String s : stored) {
                if (Names.same(s, m.group(1)) && !names.contains(s)) {
                    names.add(s);
                }
            }
        }
        for (String s : stored) {
            if (!names.contains(s)) {
                names.add(s);
            }
        }
        return names;
    }

    private ObjectNode eval(String block, JsonNode inputs) throws Throwable {
        Object fb = block(block);
        Map<String, Object> variables = variables(fb);
        for (Map.Entry<String, JsonNode> input : inputs.properties()) {
            Object variable = find(variables, input.getKey());
            if (variable == null || !(Boolean) call(variable, "isInput")) {
                throw new Refusal("'" + input.getKey() + "' is not an input of function block " + call(fb, "getName"));
            }
            call(fb, "setVariable", String.valueOf(call(variable, "getName")), input.getValue().asDouble());
        }
        call(fb, "evaluate");
        ObjectNode reply = ok();
        ObjectNode outputs = reply.putObject("outputs");
        for (Object variable : variables.values()) {
            if ((Boolean) call(variable, "isOutput")) {
                outputs.put(String.valueOf(call(variable, "getName")), (Double) call(variable, "getValue"));
            }
        }
        return reply;
    }

    /** A fresh system from the same text: every variable and NC output back where a new one starts. */
    private ObjectNode reset() throws Throwable {
        requireProgram();
        capture.start();
        try {
            fis = createFromString.invoke(null, text, false);
        } catch (InvocationTargetException e) {
            throw e.getCause();
        } finally {
            capture.stop();
        }
        startInputsAtZero(fis);
        return ok();
    }

    /**
     * jFuzzyLogic starts every variable at NaN; a new instance starts with its inputs at their initial value,
     * which for the REAL inputs jFuzzyLogic reads (it rejects declared initial values) is 0.
     */
    private static void startInputsAtZero(Object system) throws Throwable {
        for (Object fb : (Iterable<?>) system) {
            for (Object variable : variables(fb).values()) {
                if ((Boolean) call(variable, "isInput")) {
                    call(fb, "setVariable", String.valueOf(call(variable, "getName")), 0.0);
                }
            }
        }
    }

    private ObjectNode export() throws Throwable {
        requireProgram();
        ObjectNode reply = ok();
        reply.put("fcl", String.valueOf(call(fis, "toStringFcl")));
        return reply;
    }

    private void requireProgram() throws Refusal {
        if (fis == null) {
            throw new Refusal("no program is loaded");
        }
    }

    private Object block(String name) throws Throwable {
        requireProgram();
        String wanted = name == null ? blocks.get(0) : name;
        for (String b : blocks) {
            if (Names.same(b, wanted)) {
                return call(fis, "getFunctionBlock", b);
            }
        }
        throw new Refusal("the program has no function block " + wanted);
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> variables(Object fb) throws Throwable {
        Map<String, Object> byName = new LinkedHashMap<>();
        for (Object v : (List<Object>) call(fb, "variablesSorted")) {
            byName.put(String.valueOf(call(v, "getName")), v);
        }
        return byName;
    }

    /** jFuzzyLogic's names are case-sensitive, FCL's are not: an exact match first, then any case. */
    private static Object find(Map<String, Object> variables, String name) {
        Object exact = variables.get(name);
        if (exact != null) {
            return exact;
        }
        return variables.entrySet().stream().filter(e -> Names.same(e.getKey(), name)).map(Map.Entry::getValue)
                .findFirst().orElse(null);
    }

    private static Object call(Object target, String method, Object... args) throws Throwable {
        for (Method m : target.getClass().getMethods()) {
            if (m.getName().equals(method) && m.getParameterCount() == args.length && fits(m, args)) {
                try {
                    return m.invoke(target, args);
                } catch (InvocationTargetException e) {
                    Throwable cause = e.getCause();
                    if (cause.getClass() == RuntimeException.class) {
                        // jFuzzyLogic's deliberate refusal (an unknown variable, no such block)
                        throw new Refusal("jFuzzyLogic: " + cause.getMessage());
                    }
                    throw cause;
                }
            }
        }
        throw new NoSuchMethodException(target.getClass().getName() + "." + method);
    }

    private static boolean fits(Method m, Object[] args) {
        Class<?>[] types = m.getParameterTypes();
        for (int k = 0; k < types.length; k++) {
            boolean ok = types[k] == double.class ? args[k] instanceof Double
                    : types[k] == boolean.class ? args[k] instanceof Boolean
                    : types[k].isInstance(args[k]);
            if (!ok) {
                return false;
            }
        }
        return true;
    }

    private ObjectNode ok() {
        return loop.ok();
    }

    private ObjectNode rejected(String message, OptionalInt line) {
        return loop.rejected(message, line);
    }

    private ObjectNode error(String kind, String message) {
        return loop.error(kind, message);
    }

    private static String describe(Throwable t) {
        return t.getClass().getName() + (t.getMessage() == null ? "" : ": " + t.getMessage());
    }

    /** Where inside jFuzzyLogic it failed: the first frame of the library's own code. */
    private static String where(Throwable t) {
        for (StackTraceElement frame : t.getStackTrace()) {
            if (frame.getClassName().startsWith("net.sourceforge.jFuzzyLogic")) {
                return " (at " + frame.getClassName() + "." + frame.getMethodName() + ":" + frame.getLineNumber() + ")";
            }
        }
        return "";
    }

    private static String firstLine(String text) {
        return text.lines().findFirst().orElse("").strip();
    }

    /** An evaluation-style refusal: answered with error kind {@code error}. */
    private static final class Refusal extends Exception {
        private static final long serialVersionUID = 1L;

        Refusal(String message) {
            super(message, null, false, false);
        }
    }

    /** Keeps what the library prints between {@link #start} and {@link #stop}, and copies everything to stderr. */
    private static final class Capture extends OutputStream {
        private final PrintStream stderr;
        private final ByteArrayOutputStream kept = new ByteArrayOutputStream();
        private boolean keeping;

        Capture(PrintStream stderr) {
            this.stderr = stderr;
        }

        synchronized void start() {
            kept.reset();
            keeping = true;
        }

        synchronized String stop() {
            keeping = false;
            String text = kept.toString(StandardCharsets.UTF_8);
            kept.reset();
            return text;
        }

        @Override
        public synchronized void write(int b) {
            stderr.write(b);
            if (keeping && kept.size() < 1 << 20) {
                kept.write(b);
            }
        }

        @Override
        public synchronized void write(byte[] b, int off, int len) {
            stderr.write(b, off, len);
            if (keeping && kept.size() < 1 << 20) {
                kept.write(b, off, len);
            }
        }
    }
}
