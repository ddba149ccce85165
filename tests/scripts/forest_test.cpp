// The forest generator (scripts/forest): deterministic for a seed, trees that stand upright in
// pictures that differ by view, every tree on the ground and clear of the camera, and a scene
// that clrender reads without a warning.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>

#include "scene/scene_loader.h"
#include "scripts/forest/camera_flight.h"
#include "scripts/forest/forest_scene.h"
#include "scripts/forest/mountain_ring.h"
#include "scripts/forest/tree_views.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using forest::Canvas;
using testing::read_bytes;
using testing::TempFolder;

constexpr int kTrees = 400;
constexpr int kFrames = 60;

forest::ForestOptions small_forest(std::uint64_t seed) {
    forest::ForestOptions options;
    options.trees = kTrees;
    options.seed = seed;
    options.frames = kFrames;
    options.width = 320;
    options.height = 180;
    return options;
}

// The folder of one forest (seed 7) written once by this test binary and shared by the tests
// that only read it. CTest runs each test in a process of its own, so the forest is kept in
// the tests' cache folder, named after this binary (a rebuilt binary writes a new one), and a
// lock makes the processes that start together wait for the first to finish writing it.
// Writing it took about 15 s of each test's 20 (45 s of 50 under the sanitizers).
std::string shared_forest() {
    struct stat binary {};
    if (::stat("/proc/self/exe", &binary) != 0) throw std::runtime_error("cannot stat the test binary");
    const fs::path cache = CLRENDER_TEST_CACHE_DIR;
    const std::string name = "forest-" + std::to_string(binary.st_mtim.tv_sec) + "." +
                             std::to_string(binary.st_mtim.tv_nsec) + "-" + std::to_string(binary.st_size);
    fs::create_directories(cache);
    // Held until this function returns or throws: closing the descriptor releases the lock.
    struct Lock {
        int fd;
        ~Lock() {
            if (fd >= 0) ::close(fd);
        }
    } lock{::open((cache / "forest.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)};
    if (lock.fd < 0 || ::flock(lock.fd, LOCK_EX) != 0) throw std::runtime_error("cannot lock the shared forest");
    const fs::path folder = cache / name;
    if (!fs::exists(folder / "complete")) {
        for (const auto& entry : fs::directory_iterator(cache)) {  // forests of earlier builds
            if (entry.path().filename().string().rfind("forest-", 0) == 0) fs::remove_all(entry.path());
        }
        forest::write_forest(small_forest(7), folder);
        std::ofstream complete(folder / "complete");
        if (!complete.flush()) throw std::runtime_error("cannot mark the shared forest complete");
    }
    return folder.string();
}

class Forest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder_ = shared_forest();
        scene_ = nlohmann::json::parse(read_bytes(folder_ + "/forest.json"));
    }

    static std::string file(const std::string& name) { return folder_ + "/" + name; }

    static std::string folder_;
    static nlohmann::json scene_;
};

std::string Forest::folder_;
nlohmann::json Forest::scene_;

Vec3 to_vec(const nlohmann::json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

bool is_tree(const nlohmann::json& impostor) { return impostor.contains("views"); }

// The eye at `samples` frames of the scene's flight.
std::vector<Vec3> flight_eyes(const nlohmann::json& scene, int samples) {
    std::vector<CameraKey> keys;
    for (std::size_t i = 0; i < scene["eyeLocations"].size(); ++i) {
        keys.push_back({to_vec(scene["eyeLocations"][i]), to_vec(scene["lookatLocations"][i])});
    }
    return forest::sample_eyes(keys, samples);
}

TEST_F(Forest, SameSeedGivesTheSameBytesAndAnotherSeedAnotherLayout) {
    TempFolder again, other;
    forest::write_forest(small_forest(7), again.path());
    forest::write_forest(small_forest(8), other.path());
    int files = 0;
    for (const auto& entry : fs::directory_iterator(folder_)) {
        const std::string name = entry.path().filename().string();
        if (name == "complete") continue;  // the shared folder's mark, not the generator's
        EXPECT_TRUE(read_bytes(entry.path()) == read_bytes(again.file(name))) << name << " differs between two runs";
        ++files;
    }
    EXPECT_EQ(files, again.entry_count());
    EXPECT_NE(read_bytes(file("forest.json")), read_bytes(other.file("forest.json")));
}

TEST_F(Forest, HasTheRequestedTreesEachStandingOnTheGround) {
    int trees = 0;
    std::set<std::string> kinds;
    for (const nlohmann::json& impostor : scene_["clrender"]["impostors"]) {
        if (!is_tree(impostor)) continue;
        ++trees;
        kinds.insert(impostor["views"].get<std::string>());
        EXPECT_EQ(impostor.value("facing", "upright"), "upright");
        EXPECT_NEAR(impostor["center"][1].get<double>(), impostor["height"].get<double>() / 2, 1e-9);
    }
    EXPECT_EQ(trees, kTrees);
    EXPECT_EQ(kinds.size(), 3u);
    for (const auto& [name, views] : scene_["clrender"]["view_sets"].items()) EXPECT_EQ(views.size(), 8u) << name;
}

TEST_F(Forest, CameraKeepsClearOfTreesAndAboveTheGround) {
    const std::vector<Vec3> eyes = flight_eyes(scene_, 8 * kFrames);
    double closest = 1e9;
    for (const nlohmann::json& impostor : scene_["clrender"]["impostors"]) {
        if (!is_tree(impostor)) continue;
        const Vec3 centre = to_vec(impostor["center"]);
        const double half_width = impostor["width"].get<double>() / 2, top = impostor["height"].get<double>();
        for (const Vec3& eye : eyes) {
            if (eye.y > top + 1) continue;
            closest = std::min(closest, std::hypot(eye.x - centre.x, eye.z - centre.z) - half_width);
        }
    }
    EXPECT_GE(closest, 1.0) << "the camera comes within a metre of a tree's picture";
    for (const Vec3& eye : eyes) EXPECT_GT(eye.y, 1.5);
}

TEST_F(Forest, HasBoulders) {
    EXPECT_GE(scene_["spheres"].size(), 24u);
    for (const nlohmann::json& sphere : scene_["spheres"]) {
        EXPECT_LT(sphere["center"][1].get<double>(), sphere["radius"].get<double>()) << "a boulder floats";
    }
}

TEST_F(Forest, ClrenderReadsItWithoutWarnings) {
    const Scene scene = load_scene(file("forest.json"));
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    EXPECT_EQ(scene.impostors.size(), static_cast<std::size_t>(kTrees + forest::MountainRing().count));
    EXPECT_EQ(scene.camera_path.size(), scene_["eyeLocations"].size());
    EXPECT_EQ(scene.spheres.size(), scene_["spheres"].size());
}

// Wherever the camera is and whichever way it turns, it looks at the full-height middle of a
// mountain picture, never at a picture's end: the ends sink behind the neighbours.
TEST_F(Forest, MountainsSurroundTheWholeFlight) {
    const forest::MountainRing ring;
    const double full_reach = ring.distance * std::tan(ring.full_half_angle * M_PI / 180);
    std::vector<Vec3> centres;
    for (const nlohmann::json& impostor : scene_["clrender"]["impostors"]) {
        if (is_tree(impostor)) continue;
        EXPECT_TRUE(impostor.contains("filename"));
        EXPECT_EQ(impostor.value("facing", "upright"), "upright");
        centres.push_back(to_vec(impostor["center"]));
    }
    ASSERT_EQ(centres.size(), static_cast<std::size_t>(ring.count));
    const std::vector<Vec3> eyes = flight_eyes(scene_, 4 * kFrames);
    for (const Vec3& eye : eyes) {
        for (int degree = 0; degree < 360; ++degree) {
            const double look = degree * M_PI / 180;
            bool covered = false;
            for (const Vec3& centre : centres) {
                const double dx = centre.x - eye.x, dz = centre.z - eye.z, reach = std::hypot(dx, dz);
                const double off = std::remainder(std::atan2(dx, -dz) - look, 2 * M_PI);
                covered = covered || std::abs(off) < std::atan(full_reach / reach);
            }
            EXPECT_TRUE(covered) << "no mountains at " << degree << " degrees from eye " << eye.x << ", " << eye.z;
            if (!covered) return;
        }
    }
}

// ---------------------------------------------------------------------------------------
// The mountain pictures

// Row of the highest opaque texel of a column, or the height when there is none.
int skyline_row(const Canvas& canvas, int column) {
    for (int row = 0; row < canvas.height; ++row) {
        if (canvas.at(column, row).a == 255) return row;
    }
    return canvas.height;
}

class ForestMountains : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        ring_.texels_wide = 180;
        ring_.texels_high = 90;
        pictures_ = forest::draw_mountain_ring(ring_, 5, normalize(Vec3(-0.3, 1, 0.45)));
    }
    static int ground_row() {
        return static_cast<int>(ring_.texels_high * ring_.above_ground / (ring_.above_ground + ring_.below_ground));
    }
    static forest::MountainRing ring_;
    static std::vector<Canvas> pictures_;
};

forest::MountainRing ForestMountains::ring_;
std::vector<Canvas> ForestMountains::pictures_;

TEST_F(ForestMountains, StandOnTheGroundAndEndLowWithoutAFlatTop) {
    ASSERT_EQ(pictures_.size(), static_cast<std::size_t>(ring_.count));
    for (std::size_t i = 0; i < pictures_.size(); ++i) {
        const Canvas& picture = pictures_[i];
        const int last = picture.width - 1;
        // The ends hold no peak that could show as a vertical cut against the sky.
        EXPECT_GE(skyline_row(picture, 0), ground_row() - 1) << "picture " << i;
        EXPECT_GE(skyline_row(picture, last), ground_row() - 1) << "picture " << i;
        // The skirt under the horizon is opaque all along, and no peak reaches the top row.
        for (int column = 0; column < picture.width; ++column) {
            EXPECT_EQ(picture.at(column, picture.height - 1).a, 255) << "picture " << i << " column " << column;
            EXPECT_EQ(picture.at(column, 0).a, 0) << "picture " << i << " column " << column;
        }
        EXPECT_LT(skyline_row(picture, picture.width / 2), ground_row() - 3) << "picture " << i << " has no mountains";
    }
}

// Where two neighbours meet (half way between their middles, seen from the centre), both show
// the same skyline: the range runs on from one picture into the next.
TEST_F(ForestMountains, NeighboursShowTheSameSkylineWhereTheyMeet) {
    const double seam = ring_.distance * std::tan(M_PI / ring_.count);
    const double texels_per_metre = ring_.texels_wide / forest::picture_width(ring_);
    const int right = static_cast<int>(std::lround(ring_.texels_wide / 2.0 + seam * texels_per_metre - 0.5));
    const int left = ring_.texels_wide - 1 - right;
    double difference = 0;
    for (int i = 0; i < ring_.count; ++i) {
        const Canvas& next = pictures_[(i + 1) % ring_.count];
        difference += std::abs(skyline_row(pictures_[i], right) - skyline_row(next, left));
    }
    EXPECT_LT(difference / ring_.count, 1.5) << "the skylines jump where neighbours meet";
}

// ---------------------------------------------------------------------------------------
// The tree pictures

struct Opacity {
    long transparent = 0, opaque = 0, partial = 0;
};

Opacity count_opacity(const Canvas& canvas) {
    Opacity counts;
    for (const forest::Rgba& t : canvas.texels) (t.a == 0 ? counts.transparent : t.a == 255 ? counts.opaque : counts.partial)++;
    return counts;
}

// Mean column of the opaque texels in `row`, or -1 when there are none.
double opaque_centre(const Canvas& canvas, int row) {
    double sum = 0;
    int count = 0;
    for (int x = 0; x < canvas.width; ++x) {
        if (canvas.at(x, row).a == 255) sum += x, ++count;
    }
    return count ? sum / count : -1;
}

bool same_texels(const Canvas& a, const Canvas& b) {
    return std::equal(a.texels.begin(), a.texels.end(), b.texels.begin(), [](const forest::Rgba& p, const forest::Rgba& q) {
        return p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a;
    });
}

const Vec3 kLight = normalize(Vec3(-0.3, 1, 0.5));

TEST(ForestTrees, PicturesAreCutOutsThatDifferByView) {
    for (forest::TreeKind kind : forest::kTreeKinds) {
        const forest::TreePictures pictures =
            forest::render_tree_pictures(kind, forest::build_tree_model(kind, 3), kLight, 128);
        ASSERT_EQ(pictures.views.size(), 8u);
        for (std::size_t i = 0; i < pictures.views.size(); ++i) {
            const Opacity counts = count_opacity(pictures.views[i]);
            EXPECT_GT(counts.transparent, 0) << forest::kind_name(kind) << " view " << i;
            EXPECT_GT(counts.opaque, 0) << forest::kind_name(kind) << " view " << i;
            EXPECT_EQ(counts.partial, 0) << forest::kind_name(kind) << " view " << i;
            for (std::size_t j = 0; j < i; ++j) {
                EXPECT_FALSE(same_texels(pictures.views[i], pictures.views[j]))
                    << forest::kind_name(kind) << " views " << i << " and " << j << " are the same";
            }
        }
    }
}

TEST(ForestTrees, StandUprightOnTheBottomRow) {
    for (forest::TreeKind kind : forest::kTreeKinds) {
        const forest::TreePictures pictures =
            forest::render_tree_pictures(kind, forest::build_tree_model(kind, 3), kLight, 128);
        for (const Canvas& view : pictures.views) {
            const int bottom = view.height - 1;
            const double centre = opaque_centre(view, bottom);
            ASSERT_GE(centre, 0) << forest::kind_name(kind) << ": the trunk does not reach the bottom row";
            EXPECT_NEAR(centre, (view.width - 1) / 2.0, view.width * 0.05) << forest::kind_name(kind);
            EXPECT_LT(count_opacity(view).opaque, static_cast<long>(view.width) * view.height);
            // The top rows are the crown's tip: far narrower than the picture.
            EXPECT_LT(opaque_centre(view, 0), 0) << forest::kind_name(kind) << ": the picture is cut at the top";
        }
    }
}

// A trunk with one ball on its +x side: the eye at +z sees the ball on its right, the eye at
// -z on its left, as clrender's placement (right = up x towards-eye) shows them.
TEST(ForestTrees, ViewsAreNotMirrored) {
    forest::TreeModel model;
    model.frusta.push_back({0, 0, -0.01, 1, 0.05, 0.05, {0.4, 0.3, 0.2}, forest::Surface::Bark});
    model.balls.push_back({{0.3, 0.5, 0}, 0.1, {0.2, 0.6, 0.2}, forest::Surface::Leaves});
    model.top = 1;
    model.half_width = 0.4;
    const Canvas from_front = forest::render_tree_view(model, {0, 0, 1}, kLight, 64, 80);
    const Canvas from_back = forest::render_tree_view(model, {0, 0, -1}, kLight, 64, 80);
    const Canvas from_side = forest::render_tree_view(model, {1, 0, 0}, kLight, 64, 80);
    const int ball_row = 40;
    EXPECT_GT(opaque_centre(from_front, ball_row), 40);
    EXPECT_LT(opaque_centre(from_back, ball_row), 24);
    EXPECT_NEAR(opaque_centre(from_side, ball_row), 31.5, 2);
}

}  // namespace
}  // namespace clr
