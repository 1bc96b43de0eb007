package org.fclcert.harness;

import java.nio.charset.StandardCharsets;
import java.security.SecureRandom;
import java.util.SplittableRandom;

/**
 * The seed of a run, from which every case's fresh vectors and disguise are drawn: the same seed gives the same
 * vectors and texts ({@code certify --seed}), so a run and the reproduce line of one of its cases replay exactly,
 * and {@code report --from} / {@code report --verify} regenerate them to re-judge the recorded evidence.
 */
public final class RunSeed {
    private RunSeed() {
    }

    /** A seed no one can know before the run. */
    public static long fresh() {
        return new SecureRandom().nextLong();
    }

    /** The random source of one case for one purpose ({@code "vectors"}, {@code "disguise"}), independent of order. */
    public static SplittableRandom forCase(long seed, String caseId, String purpose) {
        long h = 0xcbf29ce484222325L;   // FNV-1a over the case id and the purpose
        for (byte b : (caseId + "\0" + purpose).getBytes(StandardCharsets.UTF_8)) {
            h = (h ^ (b & 0xff)) * 0x100000001b3L;
        }
        return new SplittableRandom(seed ^ h);
    }

    /** The seed as the header records it (a decimal string: JSON numbers beyond 2^53 lose digits elsewhere). */
    public static String text(long seed) {
        return Long.toString(seed);
    }

    /** A recorded seed read back; fails on anything but a decimal long. */
    public static long parse(String text) {
        return Long.parseLong(text.strip());
    }
}
