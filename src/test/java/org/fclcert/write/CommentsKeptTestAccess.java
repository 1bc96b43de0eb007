package org.fclcert.write;

import java.util.List;

/** CommentsKeptTest's program and comment pattern, for the command line's tests in another package. */
public final class CommentsKeptTestAccess {
    private CommentsKeptTestAccess() {
    }

    public static String commentedHeater() {
        return CommentsKeptTest.commentedHeater();
    }

    public static List<String> comments(String text) {
        return CommentsKeptTest.comments(text);
    }
}
