package org.fclcert.cli;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.PrintWriter;
import java.util.List;
import org.fclcert.probe.DataCheckEntry;

/** Prints the Table 11 data check list: one row per line (text) or a JSON array. */
final class DataCheckPrinter {
    private DataCheckPrinter() {
    }

    /** {@code ≥ 64 rules} for an at-least bound, {@code 3 points} for an exact one, {@code -} when not measured. */
    static String valueWithUnit(DataCheckEntry e) {
        if (e.bound().equals(DataCheckEntry.NOT_MEASURED) || e.value().isEmpty()) {
            return "-";
        }
        boolean number = e.value().chars().allMatch(Character::isDigit);
        String prefix = e.bound().equals(DataCheckEntry.AT_LEAST) && number ? "≥ " : "";
        return prefix + e.value() + (number ? " " + e.unit() : "");
    }

    static void text(PrintWriter out, List<DataCheckEntry> entries) {
        for (DataCheckEntry e : entries) {
            String declared = e.declared().isEmpty() ? "" : "  [declared " + e.declared() + "]";
            out.println(String.format("%-28s %-22s %s%s", e.id(), valueWithUnit(e), e.note(), declared).stripTrailing());
        }
        out.flush();
    }

    static String json(List<DataCheckEntry> entries) {
        try {
            return new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT).writeValueAsString(entries);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a list of records always serialises", e);
        }
    }
}
