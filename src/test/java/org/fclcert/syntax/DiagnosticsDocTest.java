package org.fclcert.syntax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** docs/diagnostics.md lists exactly the reader's codes, each with its meaning, and codes are unique. */
class DiagnosticsDocTest {
    @Test
    void everyReaderCodeIsDocumentedWithItsMeaning() throws IOException {
        String doc = Files.readString(Path.of("docs/diagnostics.md"));
        int start = doc.indexOf("## Reader (syntax) diagnostics");
        assertTrue(start >= 0, "section missing");
        int end = doc.indexOf("\n## ", start + 1);
        String section = end < 0 ? doc.substring(start) : doc.substring(start, end);
        Set<String> documented = new HashSet<>();
        Matcher m = Pattern.compile("\\| (FCL-[SW]\\d{3}) \\| (.*) \\|").matcher(section);
        while (m.find()) {
            documented.add(m.group(1));
            SyntaxCode code = find(m.group(1));
            assertEquals(code.meaning(), m.group(2).replace("\\|", "|"), m.group(1));
        }
        Set<String> declared = new HashSet<>();
        for (SyntaxCode c : SyntaxCode.values()) {
            assertTrue(declared.add(c.code()), "duplicate code " + c.code());
        }
        assertEquals(declared, documented);
    }

    private static SyntaxCode find(String code) {
        for (SyntaxCode c : SyntaxCode.values()) {
            if (c.code().equals(code)) {
                return c;
            }
        }
        throw new AssertionError("documented but not declared: " + code);
    }
}
