// --stats says how the kernels traced the primary rays (render/primary_ray_path.h): packets
// over screen-tile lists for a small scene, packets through the BVH from 200,000 triangles on
// a CPU (clrender's default device), nothing for the reference.
#include <gtest/gtest.h>

#include <string>
#include <nlohmann/json.hpp>

#include "render/primary_ray_path.h"
#include "support/command.h"
#include "support/obj_text.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kCamera = R"("eye": [0.5, 2, 3], "lookat": [0.5, 0, 0.5], "up": [0, 1, 0], "fov_angle": 60,
  "width": 48, "height": 32, "SunLocation": [3, 9, 4])";

// The report's primary_rays after rendering `scene` in `folder` with `options`.
nlohmann::json primary_rays_of(const TempFolder& folder, const std::string& scene, const std::string& options = "") {
    folder.write("scene.json", scene);
    const auto result = run_clrender("scene.json -q -o out.png --stats stats.json " + options, folder.path());
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return nlohmann::json::parse(read_bytes(folder.file("stats.json"))).at("primary_rays");
}

TEST(StatsPrimaryRays, SmallScenesUseScreenTilesLargeMeshesTheBvhAndTheReferenceNeither) {
    TempFolder folder;
    const std::string spheres = std::string("{") + kCamera +
                                R"(, "spheres": [{"center": [0.5, 0.2, 0.5], "radius": 0.3, "ambient": [1, 0.3, 0.2]}]})";
    const nlohmann::json small = primary_rays_of(folder, spheres);
    if (small == "per pixel") GTEST_SKIP() << "clrender's default device is a GPU, which traces per pixel";
    EXPECT_EQ(small, "screen tiles");
    EXPECT_TRUE(primary_rays_of(folder, spheres, "--reference").is_null());
    // 317 x 317 quads: 200,978 triangles, just past the threshold.
    folder.write("grid.obj", testing::grid_obj_text(317));
    folder.write("grid.mtl", "newmtl green\nKd 0.2 0.8 0.3\n");
    const std::string mesh = std::string("{") + kCamera + R"(, "obj": {"type": "obj", "filename": "grid.obj"}})";
    EXPECT_EQ(primary_rays_of(folder, mesh), "BVH packets");
    EXPECT_EQ(primary_rays_name(PrimaryRays::per_pixel), std::string("per pixel"));
}

}  // namespace
}  // namespace clr
