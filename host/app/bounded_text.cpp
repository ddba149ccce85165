#include "app/bounded_text.h"

#include <cstring>

namespace clr {

void BoundedTextBuffer::pass_on(const char* text, std::streamsize count) {
    if (count <= 0 || target_failed_) return;
    if (target_.sputn(text, count) != count) target_failed_ = true;
}

std::streambuf::int_type BoundedTextBuffer::overflow(int_type c) {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char character = traits_type::to_char_type(c);
    xsputn(&character, 1);
    return c;
}

std::streamsize BoundedTextBuffer::xsputn(const char* text, std::streamsize count) {
    std::streamsize passed = 0;
    if (!cut_) {
        passed = count;
        if (written_ + static_cast<std::uint64_t>(count) > limit_) {
            // Up to the limit, then on to the end of that line.
            const std::streamsize room = static_cast<std::streamsize>(limit_ > written_ ? limit_ - written_ : 0);
            const void* newline = std::memchr(text + room, '\n', static_cast<std::size_t>(count - room));
            if (newline) {
                passed = static_cast<const char*>(newline) - text + 1;
                cut_ = true;
            }
        }
        pass_on(text, passed);
        written_ += static_cast<std::uint64_t>(passed);
    }
    omitted_ += static_cast<std::uint64_t>(count - passed);
    return count;  // the writer never sees a failure: target_failed() reports it
}

}  // namespace clr
