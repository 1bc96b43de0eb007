package org.fclcert.iut;

/**
 * For the corpus's second judgement (org.fclcert.harness.CorpusMutationTest): the reference implementation whose
 * instances take the compiled kernel from their first evaluation, so that a corpus case's few vectors reach the
 * kernel (in certify an instance takes it only at its {@code KERNEL_AFTER}th evaluation). Not a user-visible IUT:
 * the results are the reference's bit for bit, so {@code --iut} offers no such choice.
 */
public final class CompiledReference {
    private CompiledReference() {
    }

    public static ImplementationUnderTest open() {
        return new ReferenceIut(true);
    }

    /** How many evaluations of {@code iut} (opened here) ran on the compiled kernel. */
    public static long kernelEvaluations(ImplementationUnderTest iut) {
        return ((ReferenceIut) iut).kernelEvaluations();
    }
}
