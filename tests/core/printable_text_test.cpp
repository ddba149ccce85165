// Text a scene file puts into a message: escaped so that it cannot drive the terminal or
// break the line, and shortened so that one message stays a few lines long.
#include "core/printable_text.h"

#include <gtest/gtest.h>

#include <string>

namespace clr {
namespace {

TEST(MessageText, EscapesC0AndC1ControlCharacters) {
    EXPECT_EQ(printable("a\nb\x1b[31m"), "a\\x0Ab\\x1B[31m");
    EXPECT_EQ(printable("\x7f"), "\\x7F");
    // U+009B is CSI, U+0085 NEL: terminals act on them as on ESC [ and a newline.
    EXPECT_EQ(printable("x\xC2\x9B" "31m\xC2\x85y"), "x\\xC2\\x9B31m\\xC2\\x85y");
}

TEST(MessageText, EscapesBidirectionalOverrides) {
    // U+202E RIGHT-TO-LEFT OVERRIDE and U+2066 LEFT-TO-RIGHT ISOLATE reorder what follows.
    EXPECT_EQ(printable("a\xE2\x80\xAE" "b\xE2\x81\xA6"), "a\\xE2\\x80\\xAEb\\xE2\\x81\\xA6");
}

TEST(MessageText, EscapesInvisibleFormatCharacters) {
    // A byte order mark, a zero-width space, a soft hyphen, a word joiner and the Arabic letter
    // mark show nothing: "a.mtl" and "a.mtl\uFEFF" would read the same.
    EXPECT_EQ(printable("a.mtl\xEF\xBB\xBF"), "a.mtl\\xEF\\xBB\\xBF");
    EXPECT_EQ(printable("a\xE2\x80\x8B" "b\xC2\xAD" "c\xE2\x81\xA0" "d\xD8\x9C"),
              "a\\xE2\\x80\\x8Bb\\xC2\\xADc\\xE2\\x81\\xA0d\\xD8\\x9C");
    // Their neighbours that show something stay: a hair space, a hyphen.
    EXPECT_EQ(printable("a\xE2\x80\x8A" "b\xE2\x80\x90"), "a\xE2\x80\x8A" "b\xE2\x80\x90");
}

TEST(MessageText, EscapesInvalidUtf8ByteByByte) {
    EXPECT_EQ(printable("ty\xFF\xFEpe"), "ty\\xFF\\xFEpe");
    EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");            // overlong '/'
    EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");    // a UTF-16 surrogate
    EXPECT_EQ(printable("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
    EXPECT_EQ(printable("end\xE2\x82"), "end\\xE2\\x82");       // cut off
}

TEST(MessageText, KeepsPrintableUtf8AsItIs) {
    const std::string text = "caf\xC3\xA9 \xE6\x97\xA5\xE6\x9C\xAC \xF0\x9F\x8C\xB2 ~/x \xC2\xA0";
    EXPECT_EQ(printable(text), text);
}

TEST(MessageText, ShortensLongTextKeepingBothEnds) {
    const std::string text = "start" + std::string(1000, 'x') + "end";
    const std::string shown = shortened(text, 100);
    EXPECT_EQ(shown.size(), 100u);
    EXPECT_EQ(shown.rfind("start", 0), 0u);
    EXPECT_EQ(shown.substr(shown.size() - 3), "end");
    EXPECT_NE(shown.find(" ... "), std::string::npos);
    EXPECT_EQ(shortened("short", 100), "short");
    EXPECT_EQ(shortened(std::string(100, 'y'), 100), std::string(100, 'y'));
}

TEST(MessageText, ShorteningCountsCharactersAndNeverSplitsOne) {
    std::string text;
    for (int i = 0; i < 300; ++i) text += "\xC3\xA9";  // 300 characters, 600 bytes
    EXPECT_EQ(shortened(text, 300), text);
    const std::string shown = shortened(text, 50);
    EXPECT_EQ(printable(shown), shown) << "a character was cut in two";
    EXPECT_EQ(shown.size(), 45u * 2 + 5);
}

}  // namespace
}  // namespace clr
