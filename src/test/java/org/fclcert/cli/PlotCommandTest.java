package org.fclcert.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PlotCommandTest {
    @TempDir
    Path dir;

    @Test
    void writesOneSvgPerPictureAndListsThem() throws Exception {
        Path out = dir.resolve("pictures");
        Cli r = Cli.run("plot", "examples/valve.fcl", "--out", out.toString());
        assertEquals(0, r.exitCode(), r.err());
        List<String> names = List.of("Fuzzy_FB-temp-terms.svg", "Fuzzy_FB-pressure-terms.svg",
                "Fuzzy_FB-valve-terms.svg", "Fuzzy_FB-valve-over-temp-and-pressure.svg");
        assertEquals(names.stream().map(n -> out.resolve(n).toString()).toList(), r.out().lines().toList());
        for (String n : names) {
            String svg = Files.readString(out.resolve(n));
            assertTrue(svg.startsWith("<?xml") && svg.contains("<svg xmlns=\"http://www.w3.org/2000/svg\""), n);
        }
        // the picture in the README is this command's, kept true
        assertEquals(Files.readString(Path.of("docs/images/valve-temp-terms.svg")),
                Files.readString(out.resolve("Fuzzy_FB-temp-terms.svg")));
    }

    @Test
    void heldInputsMustBeInputsAndProgramsWithErrorsAreNotDrawn() {
        Cli unknown = Cli.run("plot", "examples/valve.fcl", "--out", dir.toString(), "--in", "presure=60");
        assertEquals(1, unknown.exitCode());
        assertEquals(List.of("fclcert: --in presure: not an input of the function block; did you mean 'pressure'?"
                + " its inputs: temp, pressure"),
                unknown.errLines());
        Cli broken = Cli.run("plot", "examples/broken.fcl", "--out", dir.toString());
        assertEquals(1, broken.exitCode());
        assertTrue(broken.err().contains("examples/broken.fcl has errors; not drawn"), broken.err());
        assertEquals(2, Cli.run("plot", dir.resolve("none.fcl").toString()).exitCode());
        Cli notANumber = Cli.run("plot", "examples/valve.fcl", "--in", "temp=warm");
        assertEquals(2, notANumber.exitCode());
        assertEquals(List.of("fclcert: --in temp=warm: 'warm' is not a number"), notANumber.errLines());
    }
}
