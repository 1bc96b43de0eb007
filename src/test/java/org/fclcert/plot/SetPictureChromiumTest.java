package org.fclcert.plot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
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
}
