#include "scripts/forest/forest_scene.h"

#include <array>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scripts/forest/json_text.h"
#include "scripts/forest/landscape_art.h"
#include "scripts/forest/mountain_ring.h"
#include "scripts/forest/random.h"
#include "scripts/forest/tree_views.h"

namespace forest {

using clr::Vec3;
using Json = nlohmann::ordered_json;

namespace {

constexpr int kTreePictureHeight = 640;
constexpr int kFloorTexels = 2048;
// The country around the forest in two pictures: finely drawn where single crowns still show,
// coarsely out to just past the mountains' feet, which hide its edge (their pictures reach
// below the ground).
constexpr int kNearCountryTexels = 1024, kFarCountryTexels = 768;
constexpr double kNearCountryHalfSize = 520, kFarCountryHalfSize = 1700;
const Colour kSky{0.62, 0.77, 0.93};

// The sun stands high in the south-west of the start: trees are lit from the camera's side.
Vec3 towards_sun() { return clr::normalize(Vec3(-0.3, 1.0, 0.45)); }

// Millimetres are plenty, and keep the file short.
double round_mm(double value) { return std::round(value * 1000) / 1000; }

Json vec(const Vec3& v) { return Json::array({round_mm(v.x), round_mm(v.y), round_mm(v.z)}); }

// Renders every kind's views into the folder and returns the view sets for the scene.
std::vector<TreePictures> draw_trees(const ForestOptions& options, const std::filesystem::path& folder, Json& view_sets) {
    std::vector<TreePictures> all;
    for (TreeKind kind : kTreeKinds) {
        const TreeModel model = build_tree_model(kind, derive_seed(options.seed, 10 + static_cast<int>(kind)));
        TreePictures pictures = render_tree_pictures(kind, model, towards_sun(), kTreePictureHeight);
        Json views = Json::array();
        for (int i = 0; i < kViewCount; ++i) {
            const std::string file = kind_name(kind) + "_" + std::to_string(i) + ".png";
            save_png((folder / file).string(), pictures.views[i], true);
            views.push_back({{"filename", file}, {"direction", vec(view_direction(i))}});
        }
        view_sets[kind_name(kind)] = views;
        all.push_back(std::move(pictures));
    }
    return all;
}

// A horizontal billboard at height y over [-half, half]: image top row at -z, read from above.
Json ground_billboard(double half, double y, const std::string& file) {
    return {{"type", "billboard"},
            {"UpperLeft", vec({-half, y, -half})},
            {"LowerLeft", vec({-half, y, half})},
            {"UpperRight", vec({half, y, -half})},
            {"filename", file}};
}

// The forest floor, and the country around it out to the mountains, which share its seed so
// that the range's foot matches the ground in front of it.
Json draw_ground(const ForestLayout& layout, std::uint32_t country_seed, std::uint64_t floor_seed,
                 const std::filesystem::path& folder) {
    const double floor_half = layout.half_extent + 60;
    save_png((folder / "ground.png").string(),
             draw_forest_floor(layout, floor_half, kFloorTexels, static_cast<std::uint32_t>(floor_seed), towards_sun()), false);
    save_png((folder / "near_country.png").string(),
             draw_country(kNearCountryHalfSize, kNearCountryTexels, country_seed), false);
    save_png((folder / "far_country.png").string(), draw_country(kFarCountryHalfSize, kFarCountryTexels, country_seed),
             false);
    // Each lies a few centimetres below the finer one, which covers it wherever both are.
    return Json::array({ground_billboard(floor_half, 0, "ground.png"),
                        ground_billboard(kNearCountryHalfSize, -0.03, "near_country.png"),
                        ground_billboard(kFarCountryHalfSize, -0.06, "far_country.png")});
}

// Upright pictures all around, far away: whichever way the camera turns, it sees mountains.
Json draw_mountains(std::uint32_t country_seed, const std::filesystem::path& folder) {
    const MountainRing ring;
    const std::vector<Canvas> pictures = draw_mountain_ring(ring, country_seed, towards_sun());
    const double height = ring.above_ground + ring.below_ground;
    Json impostors = Json::array();
    for (int i = 0; i < ring.count; ++i) {
        const std::string file = "mountains_" + std::to_string(i) + ".png";
        save_png((folder / file).string(), pictures[i], true);
        const Vec3 centre = picture_direction(ring, i) * ring.distance + Vec3(0, ring.above_ground - height / 2, 0);
        impostors.push_back({{"center", vec(centre)}, {"width", round_mm(picture_width(ring))}, {"height", height},
                             {"filename", file}});
    }
    return impostors;
}

Json tree_impostor(const TreeInstance& tree) {
    // Not rounded: the centre is exactly half the height up, so the base is exactly on the ground.
    return {{"center", Json::array({tree.base.x, tree.height / 2, tree.base.z})},
            {"width", tree.width},
            {"height", tree.height},
            {"facing", "upright"},
            {"views", kind_name(tree.kind)}};
}

Json boulder_sphere(const Boulder& boulder) {
    auto channel = [](double c) { return std::round(c * 1000) / 1000; };
    return {{"type", "sphere"},
            {"center", vec(boulder.centre)},
            {"radius", boulder.radius},
            {"ambient", Json::array({channel(boulder.colour.x), channel(boulder.colour.y), channel(boulder.colour.z)})}};
}

Json camera_locations(const ForestLayout& layout, bool eyes) {
    Json list = Json::array();
    for (const clr::CameraKey& key : layout.camera) list.push_back(vec(eyes ? key.eye : key.lookat));
    return list;
}

}  // namespace

void write_forest(const ForestOptions& options, const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    Json view_sets = Json::object();
    const std::vector<TreePictures> pictures = draw_trees(options, folder, view_sets);
    std::array<double, 3> aspect{};
    for (const TreePictures& p : pictures) aspect[static_cast<int>(p.kind)] = p.width_over_height;
    const ForestLayout layout = plan_forest(options, aspect);

    const auto country_seed = static_cast<std::uint32_t>(derive_seed(options.seed, 21));
    Json impostors = draw_mountains(country_seed, folder);
    for (const TreeInstance& tree : layout.trees) impostors.push_back(tree_impostor(tree));
    Json spheres = Json::array();
    for (const Boulder& boulder : layout.boulders) spheres.push_back(boulder_sphere(boulder));

    Json scene;
    scene["eyeLocations"] = camera_locations(layout, true);
    scene["lookatLocations"] = camera_locations(layout, false);
    scene["up"] = vec({0, 1, 0});
    scene["fov_angle"] = 74;
    scene["width"] = options.width;
    scene["height"] = options.height;
    scene["DefaultColor"] = vec(kSky);
    scene["SunLocation"] = vec(towards_sun() * 5000.0);
    scene["spheres"] = spheres;
    scene["billboards"] = draw_ground(layout, country_seed, derive_seed(options.seed, 20), folder);
    scene["clrender"] = {{"fps", 24},
                         {"frames", options.frames},
                         {"interpolation", "catmull-rom"},
                         {"view_sets", view_sets},
                         {"impostors", impostors}};

    std::ofstream out(folder / "forest.json", std::ios::binary);
    out << scene_text(scene);
    if (!out.flush()) throw std::runtime_error("cannot write " + (folder / "forest.json").string());
}

}  // namespace forest
