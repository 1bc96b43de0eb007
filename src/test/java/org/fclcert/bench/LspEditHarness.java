package org.fclcert.bench;

import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;

/**
 * Many edits in a row to the 10 000-line program of {@link LspBenchmark}, with what JMH does not report: the CPU
 * time of the whole JVM's threads per edit (the server's reader and checker, LSP4J's JSON, the client; not the
 * garbage collector's own threads), which a shared machine's load hardly changes, and the heap after a full
 * collection at edit 100 and at the last edit, which shows whether the server's memory grows with the number of
 * edits; also the bytes the JVM's threads allocate per edit and the collectors' time per edit (their pauses are
 * wall time that the threads' CPU time does not show). Run it with the collector {@code ./fclcert} runs the server
 * with, the parallel one (docs/performance.md, "The language server"):
 * {@code java -XX:+UseParallelGC -Xmx2g -cp … org.fclcert.bench.LspEditHarness [edits] [valid|syntaxError]
 * [debounce] [strict|auto]}.
 */
public final class LspEditHarness {
    private LspEditHarness() {
    }

    public static void main(String[] args) throws Exception {
        int edits = args.length > 0 ? Integer.parseInt(args[0]) : 1000;
        String text = args.length > 1 ? args[1] : "valid";
        LspBenchmark bench = new LspBenchmark();
        bench.text = text;
        bench.debounce = args.length > 2 ? Integer.parseInt(args[2]) : 0;
        bench.dialect = args.length > 3 ? args[3] : "strict";
        bench.start();
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        double[] wall = new double[edits];
        double[] cpu = new double[edits];
        double[] allocated = new double[edits];
        double[] gc = new double[edits];
        long heapAt100 = -1;
        for (int i = 0; i < edits; i++) {
            long c0 = allThreadsCpu(threads);
            long a0 = allThreadsAllocated(threads);
            long g0 = collectorsMillis();
            long t0 = System.nanoTime();
            bench.diagnosticsAfterAnEdit();
            wall[i] = (System.nanoTime() - t0) / 1e6;
            cpu[i] = (allThreadsCpu(threads) - c0) / 1e6;
            allocated[i] = (allThreadsAllocated(threads) - a0) / 1048576.0;
            gc[i] = collectorsMillis() - g0;
            if (i + 1 == 100) {
                heapAt100 = heapAfterGc();
            }
            if ((i + 1) % 100 == 0) {
                System.out.printf("edit %d: wall %.1f ms, cpu %.1f ms%n", i + 1, wall[i], cpu[i]);
            }
        }
        long heapAtEnd = heapAfterGc();
        bench.stop();
        // the first 100 edits warm the JIT up; the figures are of the rest
        double[] w = Arrays.copyOfRange(wall, Math.min(100, edits / 2), edits);
        double[] c = Arrays.copyOfRange(cpu, Math.min(100, edits / 2), edits);
        double[] a = Arrays.copyOfRange(allocated, Math.min(100, edits / 2), edits);
        double[] g = Arrays.copyOfRange(gc, Math.min(100, edits / 2), edits);
        System.out.printf("text=%s dialect=%s debounce=%d edits=%d (figures over edits %d..%d)%n", text,
                bench.dialect, bench.debounce, edits,
                edits - w.length + 1, edits);
        System.out.printf("wall ms per edit: median %.1f, p10 %.1f, p90 %.1f, max %.1f%n", pct(w, 50), pct(w, 10),
                pct(w, 90), pct(w, 100));
        System.out.printf("cpu ms per edit (all JVM threads): median %.1f, p10 %.1f, p90 %.1f%n", pct(c, 50),
                pct(c, 10), pct(c, 90));
        System.out.printf("MB allocated per edit (all JVM threads): median %.1f; collectors' time per edit:"
                + " mean %.1f ms, max %.0f ms (%s)%n", pct(a, 50), Arrays.stream(g).average().orElse(0), pct(g, 100),
                collectorNames());
        System.out.printf("heap after GC: edit 100 %s, edit %d %.1f MB%n",
                heapAt100 < 0 ? "not reached" : String.format("%.1f MB", heapAt100 / 1048576.0), edits,
                heapAtEnd / 1048576.0);
    }

    private static long allThreadsCpu(ThreadMXBean threads) {
        long sum = 0;
        for (long id : threads.getAllThreadIds()) {
            long t = threads.getThreadCpuTime(id);
            if (t > 0) {
                sum += t;
            }
        }
        return sum;
    }

    private static long allThreadsAllocated(ThreadMXBean threads) {
        if (!(threads instanceof com.sun.management.ThreadMXBean hotspot)) {
            return 0;
        }
        long sum = 0;
        for (long id : threads.getAllThreadIds()) {
            long b = hotspot.getThreadAllocatedBytes(id);
            if (b > 0) {
                sum += b;
            }
        }
        return sum;
    }

    /** The time of all collections so far, in ms, as the collectors report it (pauses, for G1's young and Parallel). */
    private static long collectorsMillis() {
        long sum = 0;
        for (GarbageCollectorMXBean bean : ManagementFactory.getGarbageCollectorMXBeans()) {
            sum += Math.max(0, bean.getCollectionTime());
        }
        return sum;
    }

    private static String collectorNames() {
        return String.join(", ", ManagementFactory.getGarbageCollectorMXBeans().stream()
                .map(GarbageCollectorMXBean::getName).toList());
    }

    private static long heapAfterGc() throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(100);
        }
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }

    private static double pct(double[] values, int p) {
        double[] s = values.clone();
        Arrays.sort(s);
        return s[Math.min(s.length - 1, (int) Math.round(p / 100.0 * (s.length - 1)))];
    }
}
