package org.fclcert.cli;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fclcert.check.CheckRule;
import org.fclcert.check.Checker;
import org.fclcert.eval.EvaluationCode;
import org.fclcert.model.DiagnosticCode;
import org.fclcert.syntax.SyntaxCode;
import org.fclcert.syntax.dialect.DialectCode;
import org.fclcert.write.ConversionCode;

/**
 * Every diagnostic code fclcert can report, one list gathered from the families' owners: the strict reader
 * ({@link SyntaxCode}), the dialect readers ({@link DialectCode}), the registered check rules (each declares
 * its own {@link org.fclcert.check.CheckCode}; {@link Checker#standardRules()}), the evaluator
 * ({@link EvaluationCode}) and the conversion to standard FCL ({@link ConversionCode}). It lives with the
 * front ends because only they see every producer. docs/diagnostics.md lists exactly these codes, with the
 * same severity, clause and meaning (DiagnosticCatalogueDocTest).
 */
public final class DiagnosticCatalogue {
    private static final Map<String, DiagnosticCode> BY_CODE = gather();

    private DiagnosticCatalogue() {
    }

    /** All codes, family by family in the order above, each family in its own order. */
    public static List<DiagnosticCode> all() {
        return List.copyOf(BY_CODE.values());
    }

    /** The entry of a code such as {@code FCL-C002}. */
    public static Optional<DiagnosticCode> find(String code) {
        return Optional.ofNullable(BY_CODE.get(code));
    }

    private static Map<String, DiagnosticCode> gather() {
        List<DiagnosticCode> codes = new ArrayList<>();
        codes.addAll(Arrays.asList(SyntaxCode.values()));
        codes.addAll(Arrays.asList(DialectCode.values()));
        Checker.standardRules().stream().map(CheckRule::diagnosticCode).forEach(codes::add);
        codes.addAll(Arrays.asList(EvaluationCode.values()));
        codes.addAll(Arrays.asList(ConversionCode.values()));
        codes.addAll(Arrays.asList(org.fclcert.write.WriterCode.values()));
        Map<String, DiagnosticCode> byCode = new LinkedHashMap<>();
        for (DiagnosticCode c : codes) {
            DiagnosticCode before = byCode.putIfAbsent(c.code(), c);
            if (before != null) {
                throw new IllegalStateException(c.code() + " is declared twice: " + before + " and " + c);
            }
        }
        return Collections.unmodifiableMap(byCode);
    }
}
