package org.fclcert.plot;

import java.util.Locale;

/** A tiny SVG writer: numbers in a locale-independent short form, text escaped. */
final class Svg {
    private final StringBuilder out = new StringBuilder();

    Svg(int width, int height, String title) {
        out.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n")
                .append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(width).append("\" height=\"")
                .append(height).append("\" viewBox=\"0 0 ").append(width).append(' ').append(height)
                .append("\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\" font-size=\"12\">\n")
                .append("<title>").append(escape(title)).append("</title>\n")
                .append("<rect x=\"0\" y=\"0\" width=\"").append(width).append("\" height=\"").append(height)
                .append("\" fill=\"#ffffff\"/>\n");
    }

    Svg raw(String element) {
        out.append(element).append('\n');
        return this;
    }

    Svg line(double x1, double y1, double x2, double y2, String stroke, double width) {
        return raw("<line x1=\"" + n(x1) + "\" y1=\"" + n(y1) + "\" x2=\"" + n(x2) + "\" y2=\"" + n(y2)
                + "\" stroke=\"" + stroke + "\" stroke-width=\"" + n(width) + "\"/>");
    }

    Svg rect(double x, double y, double w, double h, String fill) {
        return raw("<rect x=\"" + n(x) + "\" y=\"" + n(y) + "\" width=\"" + n(w) + "\" height=\"" + n(h)
                + "\" fill=\"" + fill + "\"/>");
    }

    Svg text(double x, double y, String anchor, String text) {
        return raw("<text x=\"" + n(x) + "\" y=\"" + n(y) + "\" text-anchor=\"" + anchor + "\" fill=\"#222222\">"
                + escape(text) + "</text>");
    }

    Svg polyline(double[] xs, double[] ys, String stroke, double width, String cssClass) {
        StringBuilder p = new StringBuilder();
        for (int i = 0; i < xs.length; i++) {
            p.append(i == 0 ? "" : " ").append(n(xs[i])).append(',').append(n(ys[i]));
        }
        return raw("<polyline class=\"" + cssClass + "\" points=\"" + p + "\" fill=\"none\" stroke=\"" + stroke
                + "\" stroke-width=\"" + n(width) + "\" stroke-linejoin=\"round\"/>");
    }

    String finish() {
        return out + "</svg>\n";
    }

    static String n(double v) {
        String s = String.format(Locale.ROOT, "%.2f", v);
        s = s.contains(".") ? s.replaceAll("0+$", "").replaceAll("\\.$", "") : s;
        return s.equals("-0") ? "0" : s;
    }

    static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
