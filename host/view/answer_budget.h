// The bytes of frame answers the viewer holds while clients take them. An answer keeps its
// frame until its client has read it (up to the answer's 60 s deadline, view/bounded_server.h),
// so slow clients could otherwise hold a frame each: 32 connections at up to 265 MB. A frame is
// rendered only once its answer's bytes fit the budget; a request beyond it is answered 503.
// An export's answer, which keeps the exported scene's text, takes its room here too.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

namespace clr {

class AnswerBudget {
public:
    // One frame of the largest size the viewer renders (265 MB) fits, with room for many small ones.
    static constexpr std::uint64_t kDefaultBytes = std::uint64_t(384) << 20;

    explicit AnswerBudget(std::uint64_t bytes = kDefaultBytes) : total_(bytes), left_(bytes) {}

    // A hold on `bytes` of the budget, given back when the last copy of the hold is gone; null
    // when the budget has not that much left.
    std::shared_ptr<const void> hold(std::uint64_t bytes);

    std::uint64_t left() const { return left_.load(); }
    std::uint64_t in_flight() const { return total_ - left_.load(); }
    std::uint64_t total() const { return total_; }

private:
    const std::uint64_t total_;
    std::atomic<std::uint64_t> left_;
};

}  // namespace clr
