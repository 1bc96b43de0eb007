package org.fclcert.write;

import org.fclcert.model.Program;
import org.fclcert.syntax.dialect.Dialect;

/**
 * Writes a program (the standard model, as any reader yields it) in the FCL layout one library reads, so
 * that fclcert's reader of that dialect reads it back to a program with the same meaning wherever the
 * library can say it. Implementations are stateless and thread-safe; {@link DialectWriters#writer} gives them.
 */
public interface DialectWriter {

    Dialect dialect();

    /**
     * The program in the library's layout. Never throws for a program that passed the checks: what the
     * library cannot say is written as the nearest thing it can and listed in {@link Written#notExpressible()}.
     */
    Written write(Program program);
}
