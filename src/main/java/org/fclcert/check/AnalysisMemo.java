package org.fclcert.check;

import java.lang.ref.SoftReference;
import org.fclcert.syntax.ReaderOptions;
import org.fclcert.syntax.StrictReader;

/**
 * The last analysis made, kept for whoever reads the same text next: when the prober judges a generated
 * program with the reference and then loads it into the in-process reference implementation, the text
 * (often megabytes) is read and checked once instead of twice. An {@link Analysis} is immutable, so
 * sharing it is invisible to both; the entry is held softly, so it never keeps a large program alive
 * under memory pressure. Thread-safe (one volatile entry).
 */
public final class AnalysisMemo {
    private record Entry(ReaderOptions options, String sourceName, String text, SoftReference<Analysis> analysis) {
    }

    private static volatile Entry last;

    private AnalysisMemo() {
    }

    /** {@link Analysis#analyze} with a strict reader of these options, or the last result for the same arguments. */
    public static Analysis analyze(ReaderOptions options, String sourceName, String text) {
        Entry e = last;
        if (e != null && e.options().equals(options) && e.sourceName().equals(sourceName)
                && (e.text() == text || e.text().equals(text))) {
            Analysis a = e.analysis().get();
            if (a != null) {
                return a;
            }
        }
        Analysis a = Analysis.analyze(new StrictReader(options), sourceName, text);
        last = new Entry(options, sourceName, text, new SoftReference<>(a));
        return a;
    }
}
