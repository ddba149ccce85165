// Text streamed to another stream up to a limit of bytes: --explain-pixel's steps go out as the
// reference computes them, instead of hundreds of megabytes held in memory first, and stop at
// the end of the line that crosses the limit; what follows is counted, not written. A target
// that stops taking bytes (a full disk, a closed pipe) is remembered, so the caller can fail
// instead of claiming success.
#pragma once

#include <cstdint>
#include <ostream>
#include <streambuf>

namespace clr {

class BoundedTextBuffer : public std::streambuf {
public:
    BoundedTextBuffer(std::ostream& target, std::uint64_t limit) : target_(*target.rdbuf()), limit_(limit) {}

    bool cut() const { return cut_; }                     // the limit was reached
    std::uint64_t omitted() const { return omitted_; }    // bytes not written past the limit
    bool target_failed() const { return target_failed_; } // the target refused some bytes

protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* text, std::streamsize count) override;

private:
    void pass_on(const char* text, std::streamsize count);

    std::streambuf& target_;
    std::uint64_t limit_;
    std::uint64_t written_ = 0;
    std::uint64_t omitted_ = 0;
    bool cut_ = false;
    bool target_failed_ = false;
};

}  // namespace clr
