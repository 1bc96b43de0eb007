package org.fclcert.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Locale;

/**
 * A plain loop over PeerComparisonBenchmark's programs and cycles (fclcert's side, and jfuzzylite's with
 * {@code peer}): thread CPU time per step, the minimum over rounds. Not a JMH benchmark: a cheap first look, the
 * figures to be confirmed by PeerComparisonBenchmark. Arguments: {@code valve|cog3|rules125} [{@code peer}]
 * [rounds].
 */
public final class EvalLoopHarness {
    private EvalLoopHarness() {
    }

    public static void main(String[] args) throws Exception {
        String program = args.length > 0 ? args[0] : "valve";
        boolean peer = args.length > 1 && args[1].equals("peer");
        int rounds = args.length > 2 ? Integer.parseInt(args[2]) : 10;
        double[][] cycle;
        PeerComparisonBenchmark.Side side;
        PeerComparisonBenchmark.Reference ref = null;
        switch (program) {
            case "valve" -> {
                cycle = PeerPrograms.VALVE_INPUTS;
                side = peer ? new PeerComparisonBenchmark.Jfuzzylite(PeerPrograms.valveFuzzylite(), "temp", "pressure")
                        : (ref = new PeerComparisonBenchmark.Reference(PeerPrograms.valveStandard()));
            }
            case "cog3" -> {
                cycle = PeerPrograms.COG3_INPUTS;
                side = peer ? new PeerComparisonBenchmark.Jfuzzylite(PeerPrograms.cog3Fuzzylite(), "x")
                        : (ref = new PeerComparisonBenchmark.Reference(PeerPrograms.cog3Standard()));
            }
            default -> {
                cycle = PeerPrograms.RULES125_INPUTS;
                side = peer ? new PeerComparisonBenchmark.Jfuzzylite(PeerPrograms.rules125(true), PeerPrograms.INPUTS125)
                        : (ref = new PeerComparisonBenchmark.Reference(PeerPrograms.rules125(false)));
            }
        }
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        int steps = program.equals("valve") ? 5_000_000 : 500_000;
        double best = Double.MAX_VALUE;
        double sink = 0;
        for (int r = 0; r < rounds; r++) {
            long start = threads.getCurrentThreadCpuTime();
            int i = 0;
            for (int k = 0; k < steps; k++) {
                if (++i >= cycle.length) {
                    i = 0;
                }
                sink += side.step(cycle[i]);
            }
            double ns = (threads.getCurrentThreadCpuTime() - start) / (double) steps;
            best = Math.min(best, ns);
            System.out.printf(Locale.ROOT, "round %d: %.1f ns/step%n", r, ns);
        }
        System.out.printf(Locale.ROOT, "%s %s: best %.1f ns/step (sink %s)%s%n", program, peer ? "jfuzzylite" : "fclcert",
                best, sink, ref == null ? "" : "; " + ref.counts());
    }
}
