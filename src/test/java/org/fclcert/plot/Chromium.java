package org.fclcert.plot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;

/**
 * Headless Chromium from Debian's package, as a person's browser: renders a file to a PNG of the given
 * size. Installed by scripts/ensure-chromium; absent, a test skips with the reason, or fails with CI set.
 */
public final class Chromium {
    private Chromium() {
    }

    public static Path executable() {
        for (String candidate : List.of("/usr/bin/chromium", "/usr/bin/chromium-browser")) {
            if (Files.isExecutable(Path.of(candidate))) {
                return Path.of(candidate);
            }
        }
        String why = "no /usr/bin/chromium";
        if (System.getenv("CI") != null) {
            fail("CI is set but Chromium is missing (scripts/ensure-chromium should have installed it): " + why);
        }
        assumeTrue(false, "Chromium is not installed, so the rendering tests are skipped (apt-get install chromium,"
                + " or run scripts/ensure-chromium; with CI set they fail instead): " + why);
        throw new IllegalStateException();
    }

    /** Renders {@code svg} (written to {@code dir}) at width x height CSS pixels, scale 1, and reads the PNG. */
    public static BufferedImage render(Path dir, String name, String svg, int width, int height)
            throws IOException, InterruptedException {
        return render(dir, name + ".svg", svg, width, height, name);
    }

    /** Renders a page ({@code fileName}: its extension says what it is, .html or .svg) as {@link #render}. */
    public static BufferedImage render(Path dir, String fileName, String content, int width, int height, String name)
            throws IOException, InterruptedException {
        Path chromium = executable();
        Path file = dir.resolve(fileName);
        Files.writeString(file, content, StandardCharsets.UTF_8);
        Path png = dir.resolve(name + ".png");
        run(chromium, dir, name, file, null, "--hide-scrollbars", "--window-size=" + width + "," + height,
                "--screenshot=" + png);
        assertTrue(Files.size(png) > 0, "no screenshot written");
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(width, image.getWidth());
        assertEquals(height, image.getHeight());
        return image;
    }

    /**
     * What overflows a page to the right at {@code width} CSS pixels, as Chromium lays it out: the page's scroll
     * width, then one line per visible element whose box ends past the viewport (at most 20), with every
     * {@code <details>} opened first, so that what a reader unfolds is measured too. A page with no horizontal
     * scrollbar gives just its width. The page is written to {@code dir} with a script appended that measures it.
     */
    public static List<String> overflow(Path dir, String name, String html, int width)
            throws IOException, InterruptedException {
        Path chromium = executable();
        Path file = dir.resolve(name + ".html");
        Files.writeString(file, html + "\n<script>(function(){document.querySelectorAll('details').forEach(function(d){d.open=true;});"
                + "var w=document.documentElement.clientWidth,o=[];"
                + "document.querySelectorAll('body *').forEach(function(e){var r=e.getBoundingClientRect();"
                + "if(r.right>w+1&&o.length<20&&e.checkVisibility())o.push(e.tagName+' '+Math.round(r.right)+' '+(e.textContent||'')"
                + ".replace(/\\s+/g,' ').slice(0,80));});var p=document.createElement('pre');p.id='fclcert-overflow';"
                + "p.textContent='width '+document.documentElement.scrollWidth+' of '+w+'\\n'+o.join('\\n');"
                + "document.body.appendChild(p);})();</script>\n", StandardCharsets.UTF_8);
        Path dom = dir.resolve(name + ".dom");
        run(chromium, dir, name, file, dom, "--window-size=" + width + ",900", "--dump-dom");
        String out = Files.readString(dom, StandardCharsets.UTF_8);
        int at = out.indexOf("<pre id=\"fclcert-overflow\">");
        assertTrue(at >= 0, "the measuring script did not run");
        String text = out.substring(at + "<pre id=\"fclcert-overflow\">".length(), out.indexOf("</pre>", at));
        return List.of(text.replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&").split("\n"));
    }

    /**
     * Runs headless Chromium on {@code file} with the flags every use shares and {@code flags}, and waits for it (120 s
     * at most); its standard output goes to {@code stdout} (null: into the log with its errors, {@code name}.log).
     */
    private static void run(Path chromium, Path dir, String name, Path file, Path stdout, String... flags)
            throws IOException, InterruptedException {
        Path profile = Files.createTempDirectory(dir, "profile");
        List<String> command = new java.util.ArrayList<>(List.of(chromium.toString(), "--headless", "--no-sandbox",
                "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
                "--disable-component-update", "--disable-sync", "--user-data-dir=" + profile,
                "--force-device-scale-factor=1"));
        command.addAll(List.of(flags));
        command.add(file.toUri().toString());
        Path log = dir.resolve(name + ".log");
        ProcessBuilder builder = new ProcessBuilder(command);
        if (stdout == null) {
            builder.redirectErrorStream(true).redirectOutput(log.toFile());
        } else {
            builder.redirectOutput(stdout.toFile()).redirectError(log.toFile());
        }
        Process p = builder.start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            fail("Chromium did not finish with " + file + " in 120 s");
        }
        assertEquals(0, p.exitValue(), () -> "Chromium failed: " + read(log));
    }

    private static String read(Path log) {
        try {
            return Files.readString(log);
        } catch (IOException e) {
            return e.toString();
        }
    }

    /** True when some pixel within {@code r} of (x, y) is within {@code tolerance} per channel of rgb. */
    public static boolean colourNear(BufferedImage image, double x, double y, int r, String rgb, int tolerance) {
        int want = Integer.parseInt(rgb.substring(1), 16);
        for (int dx = -r; dx <= r; dx++) {
            for (int dy = -r; dy <= r; dy++) {
                int px = (int) Math.round(x) + dx;
                int py = (int) Math.round(y) + dy;
                if (px >= 0 && py >= 0 && px < image.getWidth() && py < image.getHeight()
                        && close(image.getRGB(px, py), want, tolerance)) {
                    return true;
                }
            }
        }
        return false;
    }

    public static boolean close(int a, int b, int tolerance) {
        for (int shift = 0; shift <= 16; shift += 8) {
            if (Math.abs(((a >> shift) & 0xff) - ((b >> shift) & 0xff)) > tolerance) {
                return false;
            }
        }
        return true;
    }
}
