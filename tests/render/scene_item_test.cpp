// Scene items, the (kind, index) pairs of screen-tile lists and BVH leaves: every kind the
// kind bits hold and every index the index bits hold come back, and nothing that would wrap
// into another object's item is made.
#include "render/scene_item.h"

#include <gtest/gtest.h>

#include <set>

namespace clr {
namespace {

TEST(SceneItem, EveryKindAndIndexComeBack) {
    std::set<std::uint32_t> items;
    for (int kind = CLR_HIT_NONE + 1; kind < (1 << CLR_ITEM_KIND_BITS); ++kind) {
        for (std::size_t index : {std::size_t{0}, std::size_t{1}, std::size_t{123456}, std::size_t{CLR_ITEM_INDEX_MASK}}) {
            const std::uint32_t item = scene_item(kind, index);
            EXPECT_EQ(scene_item_kind(item), kind) << index;
            EXPECT_EQ(scene_item_index(item), index) << kind;
            items.insert(item);
        }
    }
    EXPECT_EQ(items.size(), 15u * 4u);  // no two (kind, index) pairs share an item
    EXPECT_GE(1 << CLR_ITEM_KIND_BITS, 8) << "room for more kinds than spheres and billboards";
}

TEST(SceneItem, WhatDoesNotFitIsRefused) {
    EXPECT_THROW(scene_item(CLR_HIT_SPHERE, std::size_t{CLR_ITEM_INDEX_MASK} + 1), std::length_error);
    EXPECT_THROW(scene_item(CLR_HIT_NONE, 0), std::length_error);
    EXPECT_THROW(scene_item(1 << CLR_ITEM_KIND_BITS, 0), std::length_error);
}

}  // namespace
}  // namespace clr
