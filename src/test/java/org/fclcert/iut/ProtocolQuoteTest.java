package org.fclcert.iut;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** What a protocol fault shows of the line received: every character visible, a byte-order mark skipped. */
class ProtocolQuoteTest {
    @Test
    void invisibleCharactersAreShownByTheirCodePoint() {
        assertEquals("<U+FEFF>hi<U+001B>[2K<U+200B>é<U+0000>", Protocol.quote("\uFEFFhi\u001b[2K\u200Bé\u0000"));
    }

    @Test
    void aByteOrderMarkBeforeAReplyIsSkippedAndOneInsideIsShown() throws IutException {
        assertEquals(true, Protocol.reply(Protocol.mapper(), "\uFEFF{\"ok\": true, \"id\": 1}", "hello", 1)
                .path("ok").asBoolean());
        IutException e = assertThrows(IutException.class,
                () -> Protocol.reply(Protocol.mapper(), "\uFEFF\uFEFF{\"ok\": true}", "hello", 1));
        assertEquals("the reply to 'hello' is not JSON: <U+FEFF>{\"ok\": true}", e.getMessage());
    }
}
