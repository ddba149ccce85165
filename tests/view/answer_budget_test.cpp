// The frame answers' budget (view/answer_budget.h): holds up to its bytes, each given back
// when the last copy of its hold goes (the answer sent, or dropped).
#include <gtest/gtest.h>

#include <memory>

#include "view/answer_budget.h"

namespace clr {
namespace {

TEST(AnswerBudget, HoldsUpToItsBytesAndGivesThemBackWhenTheAnswerGoes) {
    AnswerBudget budget(100);
    std::shared_ptr<const void> first = budget.hold(60);
    ASSERT_TRUE(first);
    EXPECT_EQ(budget.in_flight(), 60u);
    EXPECT_FALSE(budget.hold(41)) << "beyond what is left";
    std::shared_ptr<const void> second = budget.hold(40);
    ASSERT_TRUE(second);
    EXPECT_EQ(budget.left(), 0u);
    EXPECT_FALSE(budget.hold(1));
    std::shared_ptr<const void> copy = first;  // the answer's provider keeps a copy
    first.reset();
    EXPECT_EQ(budget.left(), 0u) << "a copy still holds it";
    copy.reset();
    EXPECT_EQ(budget.left(), 60u);
    second.reset();
    EXPECT_EQ(budget.in_flight(), 0u);
    EXPECT_TRUE(budget.hold(100));
}

}  // namespace
}  // namespace clr
