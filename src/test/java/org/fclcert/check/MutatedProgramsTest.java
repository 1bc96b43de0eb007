package org.fclcert.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.fclcert.model.Diagnostic;
import org.fclcert.syntax.StrictReader;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Robustness of reading + checking + feature detection: every test program, mutated at the token
 * level (deleted, repeated or swapped-in tokens, truncation), yields diagnostics or a program, never an
 * exception. Swapping in tokens from elsewhere in the same program makes many programs that parse but
 * break a check, which is what exercises the rules. The seed is fixed so a failure can be replayed.
 */
class MutatedProgramsTest {
    private static final int MUTATIONS_PER_PROGRAM = 100;

    static Stream<String> programs() {
        return Stream.of("standard/valve_5_3.fcl", "standard/crane_annex_c.fcl", "features/extension.fcl",
                "features/open.fcl", "features/methods.fcl", "negative/FCL-C003.fcl", "negative/FCL-C022.fcl");
    }

    private static List<String> tokens(String text) {
        List<String> out = new ArrayList<>();
        for (String piece : text.split("(?<=[\\s();,:])|(?=[\\s();,:])")) {
            out.add(piece);
        }
        return out;
    }

    private static String mutate(List<String> tokens, Random random) {
        List<String> t = new ArrayList<>(tokens);
        int i = random.nextInt(t.size());
        switch (random.nextInt(4)) {
            case 0 -> t.remove(i);
            case 1 -> t.add(i, t.get(i));
            case 2 -> t.set(i, t.get(random.nextInt(t.size())));
            default -> {
                return String.join("", t).substring(0, random.nextInt(String.join("", t).length()));
            }
        }
        return String.join("", t);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("programs")
    void mutantsGiveDiagnosticsOrAProgramButNeverAnException(String path) {
        List<String> tokens = tokens(Programs.text(path));
        Random random = new Random(61131_7L + path.hashCode());
        int rejected = 0;
        for (int n = 0; n < MUTATIONS_PER_PROGRAM; n++) {
            String mutant = mutate(tokens, random);
            Analysis analysis = Programs.analyze(path, mutant);
            boolean hasError = analysis.diagnostics().stream().anyMatch(Diagnostic::isError);
            assertEquals(hasError, analysis.program().isEmpty(), () -> "mutant:\n" + mutant);
            // the detector must also cope with programs that parse but fail the checks
            new StrictReader().read(path, mutant).program().ifPresent(p -> new FeatureDetector().detect(p));
            for (Diagnostic d : analysis.diagnostics()) {
                assertTrue(d.location().line() >= 1 && !d.message().isBlank(), () -> d + "\nmutant:\n" + mutant);
            }
            rejected += hasError ? 1 : 0;
        }
        assertTrue(rejected > MUTATIONS_PER_PROGRAM / 4, "most mutants should be rejected, only " + rejected + " were");
    }
}
