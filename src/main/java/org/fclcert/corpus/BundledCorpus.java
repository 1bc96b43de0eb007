package org.fclcert.corpus;

import java.io.IOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.FileSystem;
import java.nio.file.FileSystemAlreadyExistsException;
import java.nio.file.FileSystems;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * The conformance corpus shipped inside fclcert's own jar (the build copies {@code conformance/}
 * there), so that {@code certify} and the Maven plugin work without a checkout of this repository.
 */
public final class BundledCorpus {
    /** Where the build puts the corpus on the class path. */
    static final String RESOURCE = "/org/fclcert/conformance";

    /** How reports name the bundled corpus. */
    public static final String NAME = "bundled";

    private BundledCorpus() {
    }

    /** Loads the bundled corpus. */
    public static Corpus load() throws CorpusException {
        return Corpus.load(directory());
    }

    /**
     * The bundled corpus as a directory: a plain directory when fclcert runs from its build output,
     * a directory inside the jar (a zip file system) when it runs from the jar.
     */
    public static Path directory() throws CorpusException {
        URL marker = BundledCorpus.class.getResource(RESOURCE + "/RETIRED");
        if (marker == null) {
            throw problem("this build of fclcert carries no conformance corpus");
        }
        try {
            URI uri = marker.toURI();
            if ("jar".equals(uri.getScheme())) {
                return zipFileSystem(uri).getPath(RESOURCE);
            }
            return Path.of(uri).getParent();
        } catch (URISyntaxException | IOException e) {
            throw problem("cannot open the bundled corpus: " + e.getMessage());
        }
    }

    private static CorpusException problem(String message) {
        return new CorpusException(List.of(new CorpusProblem(Path.of(RESOURCE), 0, message)));
    }

    private static FileSystem zipFileSystem(URI entry) throws IOException {
        try {
            return FileSystems.newFileSystem(entry, Map.of());
        } catch (FileSystemAlreadyExistsException e) {
            return FileSystems.getFileSystem(entry);
        }
    }
}
