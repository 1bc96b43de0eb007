package org.fclcert.syntax.dialect;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/** The files at hand in a format: the corpus, the test resources, FFLL's and fuzzylite's examples (read there). */
final class TextsAtHand {
    private TextsAtHand() {
    }

    /** Every regular file under those roots whose name ends with one of {@code endings}. */
    static List<Path> files(String... endings) throws IOException {
        List<Path> roots = List.of(Path.of("conformance"), Path.of("src/test/resources"), Path.of("/work/shared/peers"),
                Path.of("/usr/share/doc/fuzzylite/examples"));
        List<Path> files = new ArrayList<>();
        for (Path root : roots) {
            if (Files.isDirectory(root)) {
                try (Stream<Path> s = Files.walk(root)) {
                    s.filter(p -> Files.isRegularFile(p) && List.of(endings).stream().anyMatch(p.toString()::endsWith))
                            .forEach(files::add);
                }
            }
        }
        return files;
    }
}
