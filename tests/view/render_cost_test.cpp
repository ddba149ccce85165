// The bound on what one viewer request may render: pixels times samples per pixel.
#include "view/render_cost.h"

#include <gtest/gtest.h>

namespace clr {
namespace {

Scene scene_of(int width, int height, int spp) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.sampling.samples_per_pixel = spp;
    return scene;
}

ViewCamera view_of(int width, int height, int spp) {
    ViewCamera view;
    view.width = width;
    view.height = height;
    view.sampling.samples_per_pixel = spp;
    return view;
}

// The parameter a refusal names, or "" when the view is allowed.
std::string refused_parameter(const Scene& scene, const ViewCamera& view, bool spp_given) {
    ViewQuery query;
    if (spp_given) query.samples_per_pixel = view.sampling.samples_per_pixel;
    try {
        check_render_cost(scene, view, query);
        return "";
    } catch (const ParameterError& error) {
        return error.parameter();
    }
}

TEST(RenderCost, AFullHdFrameAt32SamplesIsTheMost) {
    const Scene small = scene_of(64, 36, 1);
    EXPECT_EQ(refused_parameter(small, view_of(1920, 1080, 32), true), "");
    EXPECT_EQ(refused_parameter(small, view_of(1920, 1081, 32), true), "spp");
    EXPECT_EQ(refused_parameter(small, view_of(1920, 1080, 33), true), "spp");
    EXPECT_EQ(refused_parameter(small, view_of(8192, 8192, 4096), true), "spp");
    // Without spp= in the query the samples are the scene's: the size is at fault.
    EXPECT_EQ(refused_parameter(small, view_of(8192, 8192, 1), false), "size");
    EXPECT_EQ(refused_parameter(small, view_of(7680, 4320, 1), false), "");  // 33 million samples
}

TEST(RenderCost, TheScenesOwnFrameIsAlwaysAllowed) {
    // A scene of 8192x8192 at 4 samples: its own frame (the page's still view) and its frame at
    // 1 sample (the page's moving view) render; a larger one does not.
    const Scene large = scene_of(8192, 8192, 4);
    EXPECT_EQ(most_view_samples(large), 8192LL * 8192 * 4);
    EXPECT_EQ(refused_parameter(large, view_of(8192, 8192, 4), false), "");
    EXPECT_EQ(refused_parameter(large, view_of(8192, 8192, 1), true), "");
    EXPECT_EQ(refused_parameter(large, view_of(8192, 8192, 5), true), "spp");
    EXPECT_EQ(most_view_samples(scene_of(64, 36, 16)), kViewerMostSamples);
}

TEST(RenderCost, TheMessageSaysWhatIsAllowedAndHowToRenderIt) {
    ViewQuery query;
    query.samples_per_pixel = 4096;
    try {
        check_render_cost(scene_of(64, 36, 1), view_of(8192, 8192, 4096), query);
        FAIL() << "not refused";
    } catch (const ParameterError& error) {
        EXPECT_STREQ(error.what(),
                     "size 8192x8192 at spp 4096 is 274877906944 samples; the viewer renders at most 66355200 per "
                     "frame (a smaller size); clrender SCENE --size 8192x8192 --spp 4096 renders it");
    }
    try {
        check_render_cost(scene_of(64, 36, 1), view_of(1920, 1080, 64), query);
        FAIL() << "not refused";
    } catch (const ParameterError& error) {
        EXPECT_NE(std::string(error.what()).find("(spp 32 at this size)"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace clr
