package org.fclcert.cli;

/** {@code --format}: human-readable text or JSON for tools. Lower case so --help lists them as typed. */
enum OutputFormat {
    text,
    json
}
