// A request's query as sent (view/query_tokens.h): the pairs as they stand, which the guard
// counts its tokens in and the routes read their parameters from.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "view/query_tokens.h"

namespace clr {
namespace {

TEST(QueryTokens, EveryTokenIsCountedAndTakenWhole) {
    using Tokens = std::vector<std::string>;
    EXPECT_EQ(query_tokens_as_sent("/a?token=T&token=T"), (Tokens{"T", "T"}));
    EXPECT_EQ(query_tokens_as_sent("/a?token=zzz=T"), (Tokens{"zzz=T"}));
    EXPECT_EQ(query_tokens_as_sent("/a?%74oken=T&x=1"), (Tokens{"T"})) << "a name however encoded";
    EXPECT_EQ(query_tokens_as_sent("/a?%u0074oken=T"), (Tokens{})) << "%uXXXX is no browser's";
    EXPECT_EQ(query_tokens_as_sent("/a?token"), (Tokens{""}));
    EXPECT_EQ(query_tokens_as_sent("/a"), (Tokens{}));
}

TEST(QueryTokens, PairsAreSplitAtTheirFirstEqualsThenDecoded) {
    const std::vector<QueryPair> pairs = query_pairs_as_sent("/a?eye=9,9,9=1&&up=0%2C1%2C0&n=a+b%3Dc&%zz=%4&");
    ASSERT_EQ(pairs.size(), 4u);
    EXPECT_EQ(pairs[0].name, "eye");
    EXPECT_EQ(pairs[0].value, "9,9,9=1");
    EXPECT_TRUE(pairs[0].equals_in_value);
    EXPECT_EQ(pairs[1].value, "0,1,0");
    EXPECT_EQ(pairs[2].value, "a b=c");
    EXPECT_FALSE(pairs[2].equals_in_value) << "%3D is a '=' written as one";
    EXPECT_EQ(pairs[3].name, "%zz");
    EXPECT_EQ(pairs[3].value, "%4");
}

}  // namespace
}  // namespace clr
