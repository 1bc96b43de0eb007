package org.fclcert.iut;

import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fclcert.iut.spi.FclImplementation;
import org.fclcert.iut.spi.FclInstance;
import org.fclcert.iut.spi.FclLoadResult;
import org.fclcert.iut.spi.FclProgram;

/**
 * A tiny vendor implementation for testing the java: adapter. It does no fuzzy logic: output
 * {@code y} is the sum of the inputs, {@code count} the evaluations since the instance was made or
 * reset. A line containing {@code REJECT} is refused at that line; an input {@code hang} makes
 * evaluate hang, {@code boom} makes it throw, {@code die} throws an Error.
 */
public final class SummingFcl implements FclImplementation {
    @Override
    public String name() {
        return "summing";
    }

    @Override
    public String version() {
        return "0.1";
    }

    @Override
    public List<String> claims() {
        return List.of("B-FB", "B-COGS");
    }

    @Override
    public FclLoadResult load(String fcl) {
        String[] lines = fcl.split("\n", -1);
        for (int k = 0; k < lines.length; k++) {
            if (lines[k].contains("REJECT")) {
                return FclLoadResult.rejected("REJECT is not allowed", k + 1);
            }
        }
        if (fcl.contains("THROW_ON_LOAD")) {
            throw new IllegalStateException("cannot cope");
        }
        Matcher m = Pattern.compile("\\bFUNCTION_BLOCK\\s+(\\w+)").matcher(fcl);
        List<String> blocks = m.results().map(r -> r.group(1)).toList();
        return FclLoadResult.loaded(new Program(blocks, fcl));
    }

    private record Program(List<String> blocks, String text) implements FclProgram {
        @Override
        public FclInstance newInstance(String block) {
            return new Instance();
        }

        @Override
        public Optional<String> export() {
            return Optional.of(text);
        }
    }

    private static final class Instance implements FclInstance {
        private final Map<String, Double> inputs = new HashMap<>();
        private double sum;
        private int count;

        @Override
        public void set(String name, double value) {
            inputs.put(name.toLowerCase(Locale.ROOT), value);
        }

        @Override
        public void evaluate() {
            if (inputs.containsKey("hang")) {
                sleepForever();
            }
            if (inputs.containsKey("boom")) {
                throw new IllegalStateException("boom input");
            }
            if (inputs.containsKey("die")) {
                throw new StackOverflowError("deep");
            }
            sum = inputs.values().stream().mapToDouble(Double::doubleValue).sum();
            count++;
        }

        private static void sleepForever() {
            try {
                Thread.sleep(Long.MAX_VALUE);
            } catch (InterruptedException e) {
                throw new IllegalStateException("interrupted");
            }
        }

        @Override
        public double get(String name) {
            return switch (name.toLowerCase(Locale.ROOT)) {
                case "y" -> sum;
                case "count" -> count;
                default -> throw new IllegalArgumentException("no output " + name);
            };
        }

        @Override
        public void reset() {
            inputs.clear();
            sum = 0;
            count = 0;
        }
    }
}
