package org.fclcert.harness;

import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

/** The one Jackson configuration for results and reports. */
public final class Json {
    private static final ObjectMapper MAPPER = new ObjectMapper()
            // newer toolkits may add fields; an older report command still reads the file
            .configure(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES, false)
            .configure(SerializationFeature.FAIL_ON_EMPTY_BEANS, false);

    private Json() {
    }

    /** Compact (one value per line): for {@code results.jsonl}. */
    public static ObjectMapper mapper() {
        return MAPPER;
    }
}
