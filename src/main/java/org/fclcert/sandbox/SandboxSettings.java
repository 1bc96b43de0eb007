package org.fclcert.sandbox;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * How implementations are launched: in a bubblewrap sandbox (the default) or, with {@code --no-sandbox}, as
 * plain processes of the user.
 *
 * @param enabled  false only when the user asked for no sandbox
 * @param limits   the resource limits inside the sandbox
 * @param readOnly further files or directories the implementation may read (a model, a licence), bound
 *                 read-only at their own paths
 * @param hidden   directories that must stay invisible even where they lie inside a part of the system that
 *                 is bound (the output directory, the corpus); anything outside the system is invisible anyway
 */
public record SandboxSettings(boolean enabled, Limits limits, List<Path> readOnly, List<Path> hidden) {
    public SandboxSettings {
        Objects.requireNonNull(limits, "limits");
        readOnly = List.copyOf(readOnly);
        hidden = List.copyOf(hidden);
    }

    /** The sandbox on, with the default limits. */
    public static SandboxSettings defaults() {
        return new SandboxSettings(true, Limits.defaults(), List.of(), List.of());
    }

    /** No sandbox ({@code --no-sandbox}). */
    public static SandboxSettings none() {
        return new SandboxSettings(false, Limits.defaults(), List.of(), List.of());
    }

    public SandboxSettings withLimits(Limits value) {
        return new SandboxSettings(enabled, value, readOnly, hidden);
    }

    public SandboxSettings withReadOnly(List<Path> paths) {
        return new SandboxSettings(enabled, limits, paths, hidden);
    }

    /** These settings, also hiding {@code paths} (added to those hidden already). */
    public SandboxSettings hiding(List<Path> paths) {
        List<Path> all = new java.util.ArrayList<>(hidden);
        all.addAll(paths);
        return new SandboxSettings(enabled, limits, readOnly, all);
    }
}
