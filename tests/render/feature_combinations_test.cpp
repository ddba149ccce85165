// The feature sets the program store is built for: exactly those FeatureSet::of can give a
// scene, so a store built for all of them covers every scene (in one precision and output mode).
#include "render/feature_combinations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "support/scene_builder.h"

namespace clr {
namespace {

std::set<std::string> options_of(const std::vector<FeatureSet>& sets) {
    std::set<std::string> options;
    for (const FeatureSet& features : sets) options.insert(features.build_options());
    return options;
}

// Scenes of every kind of content (none, one or many spheres and billboards, mirrors, images
// opaque and transparent, with and without a sun): the feature sets FeatureSet::of gives them.
std::set<std::string> feature_sets_of_built_scenes() {
    const auto opaque = testing::make_image(2, 2, [](int, int) { return std::array<std::uint8_t, 4>{9, 9, 9, 255}; });
    const auto clear = testing::make_image(2, 2, [](int col, int) {
        return std::array<std::uint8_t, 4>{9, 9, 9, std::uint8_t(col ? 255 : 0)};
    });
    std::set<std::string> options;
    for (int spheres : {0, 1, 20})
        for (int billboards : {0, 1, 2, 20})
            for (bool sphere_mirror : {false, true})
                for (bool billboard_mirror : {false, true})
                    for (int image : {0, 1, 2})
                        for (bool sun : {false, true}) {
                            Scene scene = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
                            for (int i = 0; i < spheres; ++i)
                                scene.spheres.push_back(testing::make_sphere({double(i), 0, 0}, 0.5, {1, 0, 0},
                                                                             sphere_mirror && i == 0));
                            for (int i = 0; i < billboards; ++i)
                                scene.billboards.push_back(testing::make_billboard(
                                    {-1, 1, -double(i)}, {-1, -1, -double(i)}, {1, 1, -double(i)}, {0, 0, 1},
                                    i == 0 && image ? (image == 1 ? opaque : clear) : nullptr,
                                    billboard_mirror && i == billboards - 1 && (billboards > 1 || !image)));
                            scene.has_sun = sun;
                            options.insert(FeatureSet::of(scene).build_options());
                        }
    return options;
}

TEST(FeatureCombinations, AreExactlyTheFeatureSetsScenesHave) {
    const std::vector<FeatureSet> sets = scene_feature_sets(false, false);
    EXPECT_EQ(sets.size(), 38u);
    EXPECT_EQ(options_of(sets).size(), sets.size()) << "each once";
    EXPECT_EQ(options_of(sets), feature_sets_of_built_scenes());
}

// The store holds the scene sets and the four general programs that stand in for every other
// set in a still: with mirrors and lights, and without (the faster packet shading), each with
// and without clipping.
TEST(FeatureCombinations, TheStoreAddsTheFourGeneralPrograms) {
    for (bool double_precision : {false, true})
        for (bool float_output : {false, true}) {
            const std::vector<FeatureSet> scene_sets = scene_feature_sets(double_precision, float_output);
            const std::vector<FeatureSet> store_sets = store_feature_sets(double_precision, float_output);
            ASSERT_EQ(store_sets.size(), scene_sets.size() + 4);
            EXPECT_EQ(options_of(store_sets).size(), store_sets.size()) << "each once";
            EXPECT_TRUE(std::equal(scene_sets.begin(), scene_sets.end(), store_sets.begin()));
            for (std::size_t g = 0; g < 4; ++g) {
                const FeatureSet& general = store_sets[scene_sets.size() + g];
                EXPECT_TRUE(general.spheres && general.billboards && general.triangles && general.planes &&
                            general.textures && general.alpha && general.sun && general.bvh);
                EXPECT_EQ(general.mirrors && general.lights, g < 2) << g;
                EXPECT_EQ(general.mirrors || general.lights, g < 2) << g;
                EXPECT_EQ(general.clip, g % 2 == 1) << g;
                EXPECT_EQ(general.double_precision, double_precision);
                EXPECT_EQ(general.float_output, float_output);
            }
        }
}

// A set with mirrors or lights takes the general program with both; one with neither, the one
// without: it covers every other feature.
TEST(FeatureCombinations, TheGeneralProgramKeepsMirrorsAndLightsOnlyWhereNeeded) {
    FeatureSet flat, mirrored, lit;
    mirrored.mirrors = true;
    lit.lights = true;
    EXPECT_TRUE(FeatureSet::general(mirrored).mirrors && FeatureSet::general(mirrored).lights);
    EXPECT_TRUE(FeatureSet::general(lit).mirrors && FeatureSet::general(lit).lights);
    EXPECT_FALSE(FeatureSet::general(flat).mirrors || FeatureSet::general(flat).lights);
    FeatureSet clipping;
    clipping.clip = true;
    EXPECT_TRUE(FeatureSet::general(clipping).clip);
    EXPECT_FALSE(FeatureSet::general(flat).clip);
}

TEST(FeatureCombinations, CarryThePrecisionAndOutputModeAsked) {
    for (bool double_precision : {false, true})
        for (bool float_output : {false, true})
            for (const FeatureSet& features : scene_feature_sets(double_precision, float_output)) {
                EXPECT_EQ(features.double_precision, double_precision);
                EXPECT_EQ(features.float_output, float_output);
            }
}

}  // namespace
}  // namespace clr
