package org.fclcert.syntax.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** docs/diagnostics.md lists exactly the dialect readers' codes, with their severity and meaning. */
class DialectCodeDocTest {
    @Test
    void everyDialectCodeIsDocumented() throws IOException {
        String doc = Files.readString(Path.of("docs/diagnostics.md"));
        Map<String, String> documented = new LinkedHashMap<>();
        Matcher m = Pattern.compile("\\| (FCL-D\\d{3}|FCL-[SW]3\\d{2}) \\| (error|warning) \\| (.*) \\|").matcher(doc);
        while (m.find()) {
            documented.put(m.group(1), m.group(2) + " " + m.group(3));
        }
        Map<String, String> declared = new LinkedHashMap<>();
        for (DialectCode c : DialectCode.values()) {
            declared.put(c.code(), c.severity().word() + " " + c.meaning());
        }
        assertEquals(declared, documented);
    }
}
