package org.fclcert.iut;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.fclcert.iut.spi.FclImplementation;
import org.fclcert.iut.spi.FclInstance;
import org.fclcert.iut.spi.FclLoadResult;
import org.fclcert.iut.spi.FclProgram;

/**
 * A hostile vendor class for the {@code java:} sandbox tests. It answers like the Python fakes of
 * {@code corpus-process} (output {@code sum} = a + b), so a run looks normal, while on every load it writes
 * {@link #MARK} into its working directory (the checkout, when fclcert runs there) and on every evaluation it counts
 * the entries of the directory a program names in a comment {@code (* spy-read: DIR *)} (output {@code seen}: the
 * count, -1 when it cannot read it). An input {@code exit} of 1 makes it call {@code System.exit(3)} mid-request.
 */
public final class SpyFcl implements FclImplementation {
    /** The file every load tries to write into the working directory. */
    public static final String MARK = "fclcert-java-spy-was-here.txt";
    private static final Pattern READ = Pattern.compile("\\(\\* spy-read: (.+?) \\*\\)");
    private static final Pattern BLOCK = Pattern.compile("\\bFUNCTION_BLOCK\\s+(\\w+)");

    @Override
    public String name() {
        return "spy";
    }

    @Override
    public String version() {
        return "1.0";
    }

    @Override
    public FclLoadResult load(String fcl) {
        try {
            Files.writeString(Path.of(MARK), "written by a java: implementation\n");
        } catch (IOException e) {
            // a read-only place: nothing written
        }
        Matcher read = READ.matcher(fcl);
        String dir = read.find() ? read.group(1) : null;
        List<String> blocks = BLOCK.matcher(fcl).results().map(r -> r.group(1)).toList();
        return FclLoadResult.loaded(new FclProgram() {
            @Override
            public List<String> blocks() {
                return blocks;
            }

            @Override
            public FclInstance newInstance(String block) {
                return new Instance(dir);
            }
        });
    }

    private static final class Instance implements FclInstance {
        private final String dir;
        private final Map<String, Double> inputs = new HashMap<>();
        private double seen = -1;

        Instance(String dir) {
            this.dir = dir;
        }

        @Override
        public void set(String name, double value) {
            inputs.put(name.toLowerCase(java.util.Locale.ROOT), value);
        }

        @Override
        public void evaluate() {
            if (inputs.getOrDefault("exit", 0.0) == 1.0) {
                System.exit(3);
            }
            seen = -1;
            if (dir != null) {
                try (Stream<Path> entries = Files.list(Path.of(dir))) {
                    seen = entries.count();
                } catch (IOException e) {
                    seen = -1;
                }
            }
        }

        @Override
        public double get(String name) {
            return switch (name.toLowerCase(java.util.Locale.ROOT)) {
                case "sum" -> inputs.getOrDefault("a", 0.0) + inputs.getOrDefault("b", 0.0);
                case "seen" -> seen;
                default -> 0.0;
            };
        }

        @Override
        public void reset() {
            inputs.clear();
        }
    }
}
