// BoundedTextBuffer: text passes on until the line that crosses the limit ends; the rest is
// counted; a target that refuses bytes is reported.
#include "app/bounded_text.h"

#include <gtest/gtest.h>

#include <sstream>

namespace clr {
namespace {

TEST(BoundedText, PassesEverythingUnderTheLimit) {
    std::ostringstream target;
    BoundedTextBuffer buffer(target, 100);
    std::ostream out(&buffer);
    out << "one\n" << 2 << " two\n";
    EXPECT_EQ(target.str(), "one\n2 two\n");
    EXPECT_FALSE(buffer.cut());
    EXPECT_EQ(buffer.omitted(), 0u);
    EXPECT_FALSE(buffer.target_failed());
}

TEST(BoundedText, StopsAtTheEndOfTheLineThatCrossesTheLimit) {
    std::ostringstream target;
    BoundedTextBuffer buffer(target, 6);
    std::ostream out(&buffer);
    out << "abcd\n" << "efgh";  // the limit falls inside "efgh": its line is finished first
    out << "ij\nklm\n";
    out << 'n' << "opq\n";
    EXPECT_EQ(target.str(), "abcd\nefghij\n");
    EXPECT_TRUE(buffer.cut());
    EXPECT_EQ(buffer.omitted(), 9u);  // "klm\n", "n" and "opq\n"
}

TEST(BoundedText, ReportsATargetThatRefusesBytes) {
    struct Full : std::streambuf {
        int_type overflow(int_type) override { return traits_type::eof(); }
        std::streamsize xsputn(const char*, std::streamsize) override { return 0; }
    } full;
    std::ostream full_stream(&full);
    BoundedTextBuffer buffer(full_stream, 100);
    std::ostream out(&buffer);
    out << "lost\n";
    EXPECT_TRUE(buffer.target_failed());
    EXPECT_TRUE(out.good()) << "the writer goes on; the caller asks target_failed()";
}

}  // namespace
}  // namespace clr
