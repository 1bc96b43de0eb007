package org.fclcert.plot;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The pictures as a browser shows them: rendered by headless Chromium, checked pixel by pixel. */
class PlotChromiumTest {
    private static final String WHITE = "#ffffff";

    @TempDir
    Path dir;

    @Test
    void theTransferCurveIsDrawnWhereHandCalculationPutsIt() throws Exception {
        Plotter.Picture transfer = new Plotter(PlotPrograms.program(PlotPrograms.DIAGONAL), null, Map.of())
                .pictures().get(2);
        BufferedImage png = Chromium.render(dir, "transfer", transfer.svg(), Plotter.WIDTH, Plotter.HEIGHT);
        double[] dx = {0, 10};
        double[] dy = {-0.5, 10.5};
        String blue = Plotter.PALETTE.get(0);
        for (double x : new double[] {1, 2.5, 5, 7.5, 9}) {
            // y = x by hand: the curve's colour on the diagonal, white well above and below it
            assertTrue(Chromium.colourNear(png, Plotter.px(x, dx), Plotter.py(x, dy), 1, blue, 40), "curve at " + x);
            assertTrue(Chromium.colourNear(png, Plotter.px(x, dx), Plotter.py(x + 2, dy), 0, WHITE, 8), "above " + x);
            assertFalse(Chromium.colourNear(png, Plotter.px(x, dx), Plotter.py(x - 2, dy), 2, blue, 40), "below " + x);
        }
    }

    @Test
    void membershipFunctionsCrossAtHalfAndEachHasItsColour() throws Exception {
        Plotter.Picture terms = new Plotter(PlotPrograms.program(PlotPrograms.DIAGONAL), null, Map.of())
                .pictures().get(0);
        BufferedImage png = Chromium.render(dir, "terms", terms.svg(), Plotter.WIDTH, Plotter.HEIGHT);
        double[] dx = {0, 10};
        double[] unit = {0, 1};
        String low = Plotter.PALETTE.get(0);
        String high = Plotter.PALETTE.get(1);
        // low = 1 - x/10 and high = x/10 by hand: at x = 2 low is 0.8, high 0.2
        assertTrue(Chromium.colourNear(png, Plotter.px(2, dx), Plotter.py(0.8, unit), 1, low, 40));
        assertTrue(Chromium.colourNear(png, Plotter.px(2, dx), Plotter.py(0.2, unit), 1, high, 40));
        assertTrue(Chromium.colourNear(png, Plotter.px(8, dx), Plotter.py(0.8, unit), 1, high, 40));
        assertTrue(Chromium.colourNear(png, Plotter.px(2, dx), Plotter.py(0.5, unit), 0, WHITE, 8));
        // the legend: each term's colour beside the plot
        assertTrue(Chromium.colourNear(png, Plotter.LEFT + Plotter.PLOT_WIDTH + 36, Plotter.TOP + 10, 1, low, 40));
        assertTrue(Chromium.colourNear(png, Plotter.LEFT + Plotter.PLOT_WIDTH + 36, Plotter.TOP + 30, 1, high, 40));
        // and the labels are drawn: dark text pixels below the x axis and left of the y axis
        assertTrue(darkPixels(png, Plotter.LEFT, Plotter.TOP + Plotter.PLOT_HEIGHT + 8, Plotter.PLOT_WIDTH, 36) > 50);
        assertTrue(darkPixels(png, 0, Plotter.TOP, Plotter.LEFT - 6, Plotter.PLOT_HEIGHT) > 50);
    }

    @Test
    void theHeatMapShowsTheHandCalculatedCornersAndItsColourScale() throws Exception {
        List<Plotter.Picture> pictures = new Plotter(PlotPrograms.program(PlotPrograms.TWO_INPUTS), null, Map.of())
                .pictures();
        Plotter.Picture surface = pictures.get(pictures.size() - 1);
        BufferedImage png = Chromium.render(dir, "surface", surface.svg(), Plotter.WIDTH, Plotter.HEIGHT);
        int left = Plotter.LEFT + 4;
        int right = Plotter.LEFT + Plotter.PLOT_WIDTH - 4;
        int bottom = Plotter.TOP + Plotter.PLOT_HEIGHT - 4;
        int top = Plotter.TOP + 4;
        // y lowest at a = b = 0, highest at a = b = 10, halfway where one is high and the other low
        assertTrue(Chromium.colourNear(png, left, bottom, 0, "#440154", 12));
        assertTrue(Chromium.colourNear(png, right, top, 0, "#fde725", 12));
        assertTrue(Chromium.colourNear(png, right, bottom, 0, "#21918c", 12));
        assertTrue(Chromium.colourNear(png, left, top, 0, "#21918c", 12));
        // the scale bar: dark at its foot, yellow at its head
        int bar = Plotter.LEFT + Plotter.PLOT_WIDTH + 39;
        assertTrue(Chromium.colourNear(png, bar, bottom, 0, "#440154", 16));
        assertTrue(Chromium.colourNear(png, bar, top, 0, "#fde725", 16));
    }

    private static int darkPixels(BufferedImage png, int x0, int y0, int w, int h) {
        int n = 0;
        for (int x = x0; x < x0 + w; x++) {
            for (int y = y0; y < y0 + h; y++) {
                int rgb = png.getRGB(x, y);
                if (((rgb >> 16) & 0xff) < 120 && ((rgb >> 8) & 0xff) < 120 && (rgb & 0xff) < 120) {
                    n++;
                }
            }
        }
        return n;
    }

    @Test
    void theRegionsWhereNoRuleFiresAreHatchedWhereHandDerivationPutsThem() throws Exception {
        // examples/heater.fcl, surface over error (x, [-5, 5]) and trend (y, [-2, 2]): by hand no rule fires for
        // error <= -1 with trend <= 0, and on the lines error = -1 (trend > 0) and error = 1
        String text = java.nio.file.Files.readString(Path.of("examples/heater.fcl"));
        org.fclcert.model.Program program = org.fclcert.check.Analysis.analyze(new org.fclcert.syntax.StrictReader(),
                "heater.fcl", text).program().orElseThrow();
        Plotter.Picture surface = new Plotter(program, null, Map.of()).pictures().get(3);
        BufferedImage png = Chromium.render(dir, "gaps", surface.svg(), Plotter.WIDTH, Plotter.HEIGHT);
        double[] dx = {-5, 5};
        double[] dy = {-2, 2};
        // the outline of the box: its right edge at error = -1, its top at trend = 0
        assertTrue(Chromium.colourNear(png, Plotter.px(-1, dx), Plotter.py(-1, dy), 1, Plotter.GAP, 60), "edge -1");
        assertTrue(Chromium.colourNear(png, Plotter.px(-3, dx), Plotter.py(0, dy), 1, Plotter.GAP, 60), "top 0");
        // the zero-width gap at error = 1, drawn as a line over the whole trend axis
        assertTrue(Chromium.colourNear(png, Plotter.px(1, dx), Plotter.py(1.5, dy), 1, Plotter.GAP, 60), "line 1");
        // no hatching where rules fire: error = 3 (cold) and error = -3 with trend = 1 (hot and rising)
        assertFalse(Chromium.colourNear(png, Plotter.px(3, dx), Plotter.py(0, dy), 3, Plotter.GAP, 60), "at 3");
        assertFalse(Chromium.colourNear(png, Plotter.px(-3, dx), Plotter.py(1, dy), 3, Plotter.GAP, 60), "at -3, 1");
    }
}
