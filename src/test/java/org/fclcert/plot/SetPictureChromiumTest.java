package org.fclcert.plot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The accumulated set of a failing step with the standard's and the implementation's values, as Chromium draws it. */
class SetPictureChromiumTest {
    private static final String WHITE = "#ffffff";
    /** A trapezoid clipped at 0.6: 0 up to 20, rising to 0.6 at 40, flat to 60, 0 again from 80 to 100. */
    private static final List<List<Double>> TRAPEZOID = List.of(List.of(0.0, 0.0), List.of(20.0, 0.0),
            List.of(40.0, 0.6), List.of(60.0, 0.6), List.of(80.0, 0.0), List.of(100.0, 0.0));
    private static final double[] UNIT = {0, 1};

    @TempDir
    Path dir;

    @Test
    void theSetIsFilledAndBothValuesAreMarkedOnItsAxis() throws Exception {
        // symmetric about 50, so its CoG is 50 by hand; the implementation said 62.5
        String svg = SetPicture.svg("E-COG-001, step 1: accumulated set of y", "y", false, TRAPEZOID, 50, 62.5);
        double[] d = SetPicture.domain(TRAPEZOID, false, 50, 62.5);
        assertArrayEquals(new double[] {0, 100}, d, "ticks at 0, 20, ..., 100");
        BufferedImage png = Chromium.render(dir, "set", svg, SetPicture.WIDTH, Plotter.HEIGHT);
        // inside the set (u = 30 has degree 0.3): its fill; above it and right of it (u = 90): white
        assertTrue(Chromium.colourNear(png, Plotter.px(30, d), Plotter.py(0.15, UNIT), 0, SetPicture.SET_FILL, 12));
        assertTrue(Chromium.colourNear(png, Plotter.px(30, d), Plotter.py(0.8, UNIT), 0, WHITE, 8));
        assertTrue(Chromium.colourNear(png, Plotter.px(90, d), Plotter.py(0.1, UNIT), 0, WHITE, 8));
        // the outline along the flat top at 0.6
        assertTrue(Chromium.colourNear(png, Plotter.px(45, d), Plotter.py(0.6, UNIT), 1, SetPicture.SET_LINE, 40));
        // the standard's value: a green line at 50, over the fill and above the set alike
        assertTrue(Chromium.colourNear(png, Plotter.px(50, d), Plotter.py(0.3, UNIT), 1, SetPicture.EXPECTED, 40));
        assertTrue(Chromium.colourNear(png, Plotter.px(50, d), Plotter.py(0.9, UNIT), 1, SetPicture.EXPECTED, 40));
        // the implementation's: a dashed red line at 62.5 (a dash within any 10 pixels of it)
        for (double degree : new double[] {0.2, 0.5, 0.9}) {
            assertTrue(Chromium.colourNear(png, Plotter.px(62.5, d), Plotter.py(degree, UNIT), 5, SetPicture.ACTUAL, 40),
                    "actual at degree " + degree);
        }
        assertFalse(Chromium.colourNear(png, Plotter.px(75, d), Plotter.py(0.9, UNIT), 3, SetPicture.ACTUAL, 40));
        // the legend beside the plot names both
        int legend = Plotter.LEFT + Plotter.PLOT_WIDTH + 36;
        assertTrue(Chromium.colourNear(png, legend, Plotter.TOP + 30, 2, SetPicture.EXPECTED, 40));
        assertTrue(Chromium.colourNear(png, legend, Plotter.TOP + 50, 3, SetPicture.ACTUAL, 40));
    }

    @Test
    void singletonsAreBarsAsHighAsTheirDegreesAndAFarValueSitsAtTheEdge() throws Exception {
        List<List<Double>> singletons = List.of(List.of(-100.0, 0.0), List.of(0.0, 0.25), List.of(100.0, 0.75));
        // CoGS by hand: 100 * 0.75 / (0.25 + 0.75) = 75; the implementation said 1e6, far off the axis
        String svg = SetPicture.svg("t", "y", true, singletons, 75, 1e6);
        assertTrue(svg.contains("implementation: 1000000 (off the axis, right)"), svg);
        double[] d = SetPicture.domain(singletons, true, 75, 1e6);
        assertTrue(d[0] < -100 && d[1] > 100, "room beside the outer bars");
        BufferedImage png = Chromium.render(dir, "singletons", svg, SetPicture.WIDTH, Plotter.HEIGHT);
        assertTrue(Chromium.colourNear(png, Plotter.px(100, d), Plotter.py(0.7, UNIT), 1, SetPicture.SET_LINE, 40));
        assertTrue(Chromium.colourNear(png, Plotter.px(100, d), Plotter.py(0.8, UNIT), 0, WHITE, 8), "bar ends at 0.75");
        assertTrue(Chromium.colourNear(png, Plotter.px(0, d), Plotter.py(0.2, UNIT), 1, SetPicture.SET_LINE, 40));
        assertTrue(Chromium.colourNear(png, Plotter.px(0, d), Plotter.py(0.3, UNIT), 0, WHITE, 8), "bar ends at 0.25");
        assertFalse(Chromium.colourNear(png, Plotter.px(-100, d), Plotter.py(0.1, UNIT), 2, SetPicture.SET_LINE, 40),
                "a singleton of degree 0 has no bar");
        assertTrue(Chromium.colourNear(png, Plotter.px(75, d), Plotter.py(0.5, UNIT), 1, SetPicture.EXPECTED, 40));
        assertTrue(Chromium.colourNear(png, Plotter.px(d[1], d), Plotter.py(0.5, UNIT), 5, SetPicture.ACTUAL, 40));
    }

    /**
     * E-ACCU-NSUM-002 as issue 29 found it: the standard's 49.13 and an implementation's 49.72 on an axis of 0 to 100
     * are 2.4 pixels apart, one line to the eye. Under the legend a strip of the axis from 48.93 to 49.92 draws them
     * again, 156 pixels apart (49.13 at a fifth of the strip's 260 pixels, 49.72 at four fifths).
     */
    @Test
    void closeValuesAreDrawnAgainMagnifiedSoThatTheyStandApart() throws Exception {
        String svg = SetPicture.svg("E-ACCU-NSUM-002, step 1: accumulated set of y", "y", false, TRAPEZOID, 49.13, 49.72);
        double[] d = SetPicture.domain(TRAPEZOID, false, 49.13, 49.72);
        assertTrue(Math.abs(Plotter.px(49.13, d) - Plotter.px(49.72, d)) < 3, "one line on the main axis");
        assertTrue(SetPicture.tooClose(49.13, 49.72, d));
        double[] strip = SetPicture.stripDomain(49.13, 49.72);
        int left = Plotter.LEFT + Plotter.PLOT_WIDTH + 24;
        double xe = SetPicture.stripX(49.13, strip, left);
        double xa = SetPicture.stripX(49.72, strip, left);
        assertEquals(left + 52.0, xe, 1e-9);
        assertEquals(left + 208.0, xa, 1e-9);
        // 100 units on 400 pixels, 0.59·5/3 units on 260: 260 / (0.59·5/3) / 4 = 66×
        assertTrue(svg.contains("the two values, magnified 66×:"), svg);
        BufferedImage png = Chromium.render(dir, "close", svg, SetPicture.WIDTH, Plotter.HEIGHT);
        java.nio.file.Files.copy(dir.resolve("close.png"), Path.of("target/set-picture-close.png"),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        int y = Plotter.TOP + 80 + 35;
        assertTrue(Chromium.colourNear(png, (int) Math.round(xe), y, 1, SetPicture.EXPECTED, 40), "standard in the strip");
        assertTrue(Chromium.colourNear(png, (int) Math.round(xa), y, 5, SetPicture.ACTUAL, 40), "implementation in the strip");
        assertFalse(Chromium.colourNear(png, (int) Math.round((xe + xa) / 2), y, 20, SetPicture.ACTUAL, 40),
                "nothing red between them");
        assertFalse(Chromium.colourNear(png, (int) Math.round((xe + xa) / 2), y, 20, SetPicture.EXPECTED, 40),
                "nothing green between them");
        // values far apart get no strip
        assertFalse(SetPicture.svg("t", "y", false, TRAPEZOID, 50, 62.5).contains("magnified"));
    }
}
