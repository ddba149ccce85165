#include "view/answer_budget.h"

namespace clr {

std::shared_ptr<const void> AnswerBudget::hold(std::uint64_t bytes) {
    std::uint64_t left = left_.load();
    do {
        if (left < bytes) return nullptr;
    } while (!left_.compare_exchange_weak(left, left - bytes));
    // The budget outlives every hold: the server's routes, and so their answers, end first.
    return std::shared_ptr<const void>(this, [this, bytes](const void*) { left_.fetch_add(bytes); });
}

}  // namespace clr
