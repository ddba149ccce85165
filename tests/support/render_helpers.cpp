#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include "reference/reference.h"
#include "render/feature_set.h"
#include "support/image_compare.h"
#include "support/opencl_test_device.h"

namespace clr::testing {

Image render_with_kernels(const Scene& scene, const RendererOptions& options) {
    Renderer renderer(test_device(), scene, options);
    return renderer.render(scene.camera_path.front());
}

Image render_with_reference(const Scene& scene) {
    const CameraKey& key = scene.camera_path.front();
    return reference::render(scene, reference::camera_of(scene, key));
}

void expect_kernels_match_reference(const Scene& scene, const std::string& what, const RendererOptions& options,
                                    double differing_fraction) {
    const ImageComparison comparison =
        compare_images(render_with_kernels(scene, options), render_with_reference(scene));
    EXPECT_LE(comparison.differing_fraction(), differing_fraction)
        << what << ": " << comparison.differing << " pixels differ, the first " << comparison.first_differing;
    EXPECT_EQ(comparison.differing_off_edge, 0) << what << ": " << comparison.first_off_edge;
}

void expect_every_kernel_path_matches_reference(const Scene& scene, const std::string& what) {
    expect_kernels_match_reference(scene, what + ", screen tiles", {}, 0);
    RendererOptions walk;
    walk.packets_walk_bvh = true;
    expect_kernels_match_reference(scene, what + ", packets through the BVH", walk, 0);
    RendererOptions one_by_one;
    one_by_one.screen_tiles = false;
    expect_kernels_match_reference(scene, what + ", one ray a work-item", one_by_one, 0);
    RendererOptions double_precision;
    double_precision.double_precision = true;
    expect_kernels_match_reference(scene, what + ", double", double_precision, 0);
}

void expect_general_program_renders_the_same(const Scene& scene) {
    const FeatureSet own = FeatureSet::of(scene);
    const FeatureSet general = FeatureSet::general(own);
    ASSERT_FALSE(general == own) << "the scene's own program is the general one";
    for (bool in_double : {false, true}) {
        RendererOptions specialised, standing_in;
        specialised.double_precision = standing_in.double_precision = in_double;
        standing_in.features = general;
        EXPECT_TRUE(render_with_kernels(scene, specialised).rgba == render_with_kernels(scene, standing_in).rgba)
            << (in_double ? "double: " : "float: ") << own.build_options();
    }
}

}  // namespace clr::testing
