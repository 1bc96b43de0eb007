package org.fclcert.plot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

class PlotterTest {
    @Test
    void oneInputGivesItsTermsTheOutputsTermsAndATransferCurve() throws Exception {
        List<Plotter.Picture> pictures = new Plotter(PlotPrograms.program(PlotPrograms.DIAGONAL), null, Map.of())
                .pictures();
        assertEquals(List.of("line-x-terms.svg", "line-y-terms.svg", "line-y-over-x.svg"),
                pictures.stream().map(Plotter.Picture::fileName).toList());
        for (Plotter.Picture p : pictures) {
            Document svg = parse(p.svg());
            assertEquals("svg", svg.getDocumentElement().getTagName());
            assertEquals(0, svg.getElementsByTagName("script").getLength(), p.fileName());
            assertFalse(p.svg().contains("href"), "self-contained: no links to fetch");
        }
    }

    @Test
    void theTransferCurveOfTheDiagonalProgramIsTheDiagonal() throws Exception {
        Plotter.Picture transfer = new Plotter(PlotPrograms.program(PlotPrograms.DIAGONAL), null, Map.of())
                .pictures().get(2);
        Element line = (Element) parse(transfer.svg()).getElementsByTagName("polyline").item(0);
        String[] points = line.getAttribute("points").split(" ");
        assertEquals(Plotter.SAMPLES + 1, points.length);
        // y = x by hand; the y axis spans [0, 10] widened by 5 % each side
        double[] dx = {0, 10};
        double[] dy = {-0.5, 10.5};
        for (int i = 0; i < points.length; i += 40) {
            double x = 10.0 * i / Plotter.SAMPLES;
            String[] xy = points[i].split(",");
            assertEquals(Plotter.px(x, dx), Double.parseDouble(xy[0]), 0.01, points[i]);
            assertEquals(Plotter.py(x, dy), Double.parseDouble(xy[1]), 0.01, points[i]);
        }
    }

    @Test
    void inputTermsPassThroughTheirExactCornersAndTheLegendNamesThem() throws Exception {
        Plotter.Picture terms = new Plotter(PlotPrograms.program(PlotPrograms.DIAGONAL), null, Map.of())
                .pictures().get(0);
        Document svg = parse(terms.svg());
        NodeList lines = svg.getElementsByTagName("polyline");
        assertEquals(2, lines.getLength());
        String[] low = ((Element) lines.item(0)).getAttribute("points").split(" ");
        assertEquals(Plotter.LEFT + "," + Plotter.TOP, low[0]);                     // (0, 1)
        assertEquals((Plotter.LEFT + Plotter.PLOT_WIDTH) + "," + (Plotter.TOP + Plotter.PLOT_HEIGHT),
                low[low.length - 1]);                                               // (10, 0)
        assertTrue(terms.svg().contains(">low</text>") && terms.svg().contains(">high</text>"), terms.svg());
        assertTrue(terms.svg().contains(">x</text>") && terms.svg().contains(">degree of membership</text>"));
    }

    @Test
    void twoInputsGiveAHeatMapWhoseCornersAreTheLowestAndHighestColours() throws Exception {
        List<Plotter.Picture> pictures = new Plotter(PlotPrograms.program(PlotPrograms.TWO_INPUTS), null, Map.of())
                .pictures();
        Plotter.Picture surface = pictures.get(pictures.size() - 1);
        assertEquals("pair-y-over-a-and-b.svg", surface.fileName());
        // 48 x 48 cells, then 60 steps of the colour scale
        NodeList rects = parse(surface.svg()).getElementsByTagName("rect");
        int cells = Plotter.CELLS * Plotter.CELLS;
        Element first = (Element) rects.item(2);    // after the background and the frame
        assertEquals("#440154", first.getAttribute("fill"));        // (a, b) lowest: y lowest
        Element last = (Element) rects.item(2 + cells - 1);
        assertEquals("#fde725", last.getAttribute("fill"));         // both highest: y highest
        Element aHighBLow = (Element) rects.item(2 + (Plotter.CELLS - 1) * Plotter.CELLS);
        assertEquals("#21918c", aHighBLow.getAttribute("fill"));    // y = 5: the middle of the scale
    }

    @Test
    void inputsNotOnAnAxisAreHeldAtTheValueGivenAndSaidInTheTitle() throws Exception {
        String three = PlotPrograms.TWO_INPUTS.replace("VAR_INPUT a : REAL; b : REAL; END_VAR",
                "VAR_INPUT a : REAL; b : REAL; c : REAL := 7; END_VAR");
        Plotter plotter = new Plotter(PlotPrograms.program(three), null, Map.of("B", 2.5));
        Plotter.Picture surface = plotter.pictures().get(plotter.pictures().size() - 1);
        assertTrue(surface.svg().contains("pair: y over a and b (c = 7)"), surface.svg());
    }

    static Document parse(String svg) throws Exception {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setNamespaceAware(true);
        return f.newDocumentBuilder().parse(new ByteArrayInputStream(svg.getBytes(StandardCharsets.UTF_8)));
    }
}
