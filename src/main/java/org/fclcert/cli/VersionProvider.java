package org.fclcert.cli;

import org.fclcert.model.Toolkit;
import picocli.CommandLine;

/** {@code fclcert --version}: the toolkit version from the build. */
final class VersionProvider implements CommandLine.IVersionProvider {
    @Override
    public String[] getVersion() {
        return new String[] {"fclcert " + Toolkit.version()};
    }
}
