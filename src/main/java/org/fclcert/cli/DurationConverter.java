package org.fclcert.cli;

import java.time.Duration;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** picocli's side of {@link Durations}: {@code 500ms}, {@code 5s}, {@code 2m}, {@code 1h} or seconds; at least 1 ms. */
final class DurationConverter implements ITypeConverter<Duration> {
    @Override
    public Duration convert(String value) {
        return Durations.parse(value).orElseThrow(() -> new TypeConversionException(
                "'" + value + "' is not a duration (write e.g. 5s, 500ms or 2m)"));
    }
}
