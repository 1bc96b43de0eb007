package org.fclcert.fuzz;

import java.time.Duration;
import java.util.Set;
import org.fclcert.harness.fakes.Fakes;
import org.fclcert.write.CanonicalWriter;
import org.junit.jupiter.api.Test;

class FuzzSmokeTest {
    @Test
    void smoke() throws Exception {
        for (IutSession.Factory f : new IutSession.Factory[] {Fakes.NsumAsBsum::new, Fakes.PerRuleCogs::new, Fakes.NcAsZero::new,
                Fakes.EqualPrecedence::new, Fakes.SampledDefuzzification::new, Fakes.WeightBeforeActivation::new, () -> org.fclcert.iut.Iuts.open("reference", org.fclcert.iut.IutOptions.defaults())}) {
            long t0 = System.nanoTime();
            Fuzzer.Result r = new Fuzzer().run(f, Fuzzer.Options.of(1, Duration.ofSeconds(10), FuzzSettings.open(), 1),
                    Duration.ofSeconds(5), p -> System.out.println(p));
            System.out.println(f + " " + (System.nanoTime() - t0) / 1e9 + "s " + r.progress());
            for (Finding x : r.findings()) {
                System.out.println("  " + x.key() + " first at " + x.programIndex() + " trials " + x.shrinkTrials() + " dups " + x.duplicates()
                        + " lines " + new CanonicalWriter().write(x.minimal().program()).lines().count() + " " + x.deviation().message());
            }
            if (!r.findings().isEmpty()) {
                System.out.println(new CanonicalWriter().write(r.findings().get(0).minimal().program()) + r.findings().get(0).minimal().steps());
            }
        }
    }
}
