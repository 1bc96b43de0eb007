package org.fclcert.orchestration;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class CertificationTest {
    @Test
    void reportDirectoriesAreNamedAfterTheImplementation() {
        assertEquals("reference", Certification.defaultDirectoryName("reference", "fclcert reference evaluator"));
        assertEquals("fuzzylite-6.0", Certification.defaultDirectoryName("process:fl.sh", "fuzzylite 6.0"));
        assertEquals("my-iut", Certification.defaultDirectoryName("process:x", "../My IUT!/"));
        assertEquals("iut", Certification.defaultDirectoryName("process:x", "///"));
    }
}
