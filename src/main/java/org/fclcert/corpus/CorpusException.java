package org.fclcert.corpus;

import java.util.List;
import java.util.stream.Collectors;

/** The corpus could not be loaded; carries every problem found, not only the first. */
public final class CorpusException extends Exception {
    private static final long serialVersionUID = 1L;

    private final transient List<CorpusProblem> problems;

    public CorpusException(List<CorpusProblem> problems) {
        super(problems.size() + " problem(s) in the corpus:\n"
                + problems.stream().map(CorpusProblem::toString).collect(Collectors.joining("\n")));
        this.problems = List.copyOf(problems);
    }

    public List<CorpusProblem> problems() {
        return problems;
    }
}
