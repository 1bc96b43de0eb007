package org.fclcert.syntax.dialect;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.fclcert.model.DefuzzificationMethod;
import org.fclcert.model.Diagnostic;
import org.fclcert.model.Feature;
import org.fclcert.model.FeatureUse;
import org.fclcert.model.FunctionBlock;
import org.fclcert.model.Program;
import org.fclcert.model.SourceLocation;
import org.fclcert.syntax.ReadResult;
import org.fclcert.syntax.ReaderOptions;
import org.fclcert.syntax.StrictReader;

/**
 * The reader of the Free Fuzzy Logic Library's FCL dialect (FFLL; its grammar notes are
 * the FFLL grammar notes (docs/dialects.md), its behaviour docs/peers.md; docs/dialects.md lists every construct).
 *
 * <p>It is the strict pipeline with three changes: a token filter ({@link FfllTokens}: ACCUM, declarations
 * without ':', RETAIN, RANGE comments, END_FUZZIFY closing DEFUZZIFY), builder options (MoM accepted,
 * END_FUZZIFY closing DEFUZZIFY and the draft's forms without warnings) and a model pass ({@link FfllModel}:
 * term-only subconditions and subconclusions bound by position, output terms in FUZZIFY blocks, missing
 * METHOD and DEFAULT, output ranges from comments). The program it yields is the standard model of what FFLL
 * means, with each FFLL construct in {@link Program#dialectFeatures()} where it was written; the usual checks
 * then run on it. Thread-safe: every read has its own state.
 */
public final class FfllReader implements DialectReader {
    /** The METHOD words FFLL reads beyond Table 1. */
    private static final Set<DefuzzificationMethod> OTHER_METHODS = EnumSet.of(DefuzzificationMethod.MOM);

    @Override
    public Dialect dialect() {
        return Dialect.FFLL;
    }

    /** The standard's, and MoM after METHOD. */
    @Override
    public DialectMethods methods() {
        DialectMethods s = DialectMethods.STANDARD;
        List<String> methods = new ArrayList<>(s.defuzzification());
        OTHER_METHODS.forEach(m -> methods.add(m.keyword()));
        return new DialectMethods(s.and(), s.or(), s.activation(), s.accumulation(), methods);
    }

    @Override
    public ReadResult read(String sourceName, String text) {
        return read(sourceName, text, new FfllTokens());
    }

    private static ReadResult read(String sourceName, String text, FfllTokens tokens) {
        String name = sourceName == null ? "<input>" : sourceName;
        ReaderOptions options = new ReaderOptions(OTHER_METHODS, true, true, tokens);
        ReadResult strict = new StrictReader(options).read(name, text == null ? "" : text);
        List<Diagnostic> diagnostics = new ArrayList<>(strict.diagnostics());
        if (strict.program().isEmpty()) {
            return new ReadResult(Optional.empty(), diagnostics);
        }
        try {
            FfllModel model = new FfllModel(tokens);
            Program read = strict.program().get();
            List<FunctionBlock> blocks = new ArrayList<>();
            for (int i = 0; i < read.functionBlocks().size(); i++) {
                blocks.add(model.functionBlock(read.functionBlocks().get(i), i));
            }
            List<FeatureUse> features = new ArrayList<>(tokens.features());
            features.addAll(model.features());
            features.sort(Comparator.comparing(FeatureUse::location));
            diagnostics.addAll(model.diagnostics());
            diagnostics.sort(Comparator.comparing(Diagnostic::location));
            boolean errors = diagnostics.stream().anyMatch(Diagnostic::isError);
            return new ReadResult(errors ? Optional.empty() : Optional.of(new Program(name, blocks, features)),
                    diagnostics);
        } catch (RuntimeException | StackOverflowError e) {
            diagnostics.add(DialectParser.internalError(name, "FFLL reader", e));
            return new ReadResult(Optional.empty(), diagnostics);
        }
    }

    /**
     * The FFLL constructs in the text, in source order: those of a successful read (plus METHOD MoM, which
     * the standard model holds as a method), or, when the text does not read, those the token filter saw.
     */
    @Override
    public List<Giveaway> giveaways(String text) {
        if (!FfllSignals.possible(text == null ? "" : text)) {
            return List.of();   // no word that could give FFLL away: the full read would find none
        }
        return readGiveaways(text);
    }

    /** The giveaways as the full read finds them, without {@link FfllSignals}'s first look. */
    static List<Giveaway> readGiveaways(String text) {
        FfllTokens tokens = new FfllTokens();
        ReadResult result;
        try {
            result = read("<auto>", blankForeignComments(text == null ? "" : text), tokens);
        } catch (RuntimeException | StackOverflowError e) {
            throw new IllegalStateException("the FFLL giveaway scan failed", e);
        }
        result.diagnostics().stream().filter(d -> d.diagnosticCode() == org.fclcert.syntax.SyntaxCode.INTERNAL_ERROR).findFirst()
                .ifPresent(d -> {
                    throw new IllegalStateException(d.message());
                });
        List<FeatureUse> uses = new ArrayList<>(result.program().map(Program::dialectFeatures).orElse(tokens.features()));
        uses.addAll(tokens.momMethods());
        uses.sort(Comparator.comparing(FeatureUse::location));
        // FFLL loads no program without RANGE comments (FCL-D118): then what is merely left out (METHOD, DEFAULT,
        // a block name), which jFuzzyLogic's users leave out too, is no sign of FFLL
        boolean ranged = uses.stream().anyMatch(u -> u.feature() == Feature.O_RANGE_COMMENT);
        return uses.stream().filter(u -> ranged || weight(u.feature()) > 1)
                .map(u -> new Giveaway(construct(u.feature()), u.location().line(), weight(u.feature()))).toList();
    }

    /**
     * How specific an FFLL construct is: ACCUM, term-only rules, output terms in FUZZIFY, END_FUZZIFY closing
     * DEFUZZIFY, RANGE comments and ': =' only FFLL writes (3); a declaration without ':' and RETAIN are rarer slips
     * (2); what is merely missing (DEFAULT, METHOD, a block name) or MoM, which other libraries write too, weighs 1.
     */
    private static int weight(Feature f) {
        return switch (f) {
            case O_ACCUM, O_FFLL_TERM_ONLY_CONDITION, O_FFLL_TERM_ONLY_CONCLUSION, O_FFLL_OUTPUT_FUZZIFY, O_END_FUZZIFY,
                    O_RANGE_COMMENT, O_SPACED_ASSIGN -> 3;
            case O_DECLARATION_WITHOUT_COLON, O_VAR_RETAIN -> 2;
            default -> 1;
        };
    }

    /**
     * The text with its {@code //} and {@code /* *\/} comments (which FFLL does not know, but the other libraries
     * write) blanked out, lines kept, so that no word inside them counts as FFLL evidence; {@code (* *)} comments
     * are FFLL's own and stay.
     */
    static String blankForeignComments(String text) {
        StringBuilder b = new StringBuilder(text);
        int i = 0;
        int n = text.length();
        while (i < n) {
            char c = text.charAt(i);
            char d = i + 1 < n ? text.charAt(i + 1) : '\0';
            if (c == '(' && d == '*') {
                int end = text.indexOf("*)", i + 2);
                i = end < 0 ? n : end + 2;
            } else if (c == '/' && d == '/') {
                while (i < n && text.charAt(i) != '\n') {
                    b.setCharAt(i++, ' ');
                }
            } else if (c == '/' && d == '*') {
                int end = text.indexOf("*/", i + 2);
                int stop = end < 0 ? n : end + 2;
                for (; i < stop; i++) {
                    if (text.charAt(i) != '\n') {
                        b.setCharAt(i, ' ');
                    }
                }
            } else {
                i++;
            }
        }
        return b.toString();
    }

    /** A construct in a few words, as {@code --dialect auto} shows it. */
    static String construct(Feature f) {
        return switch (f) {
            case O_ACCUM -> "ACCUM:";
            case O_FFLL_TERM_ONLY_CONDITION -> "term-only subcondition";
            case O_FFLL_TERM_ONLY_CONCLUSION -> "term-only subconclusion";
            case O_FFLL_OUTPUT_FUZZIFY -> "FUZZIFY of an output";
            case O_END_FUZZIFY -> "END_FUZZIFY closing DEFUZZIFY";
            case O_RANGE_COMMENT -> "RANGE comment";
            case O_FFLL_NO_DEFAULT -> "no DEFAULT";
            case O_FFLL_NO_METHOD -> "no METHOD";
            case O_DECLARATION_WITHOUT_COLON -> "declaration without ':'";
            case O_VAR_RETAIN -> "RETAIN";
            case O_MOM -> "METHOD: MoM";
            case O_UNNAMED_BLOCK -> "FUNCTION_BLOCK without a name";
            case O_SPACED_ASSIGN -> "': ='";
            default -> f.id();
        };
    }
}
