#include "bench/bench_scenes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

#include "scene/triangle_ties.h"
#include "support/scene_builder.h"

namespace clr::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFovDegrees = 60;
const Vec3 kEye{0, 0, 0};
const Vec3 kLookat{0, 0, -1};
const Vec3 kUp{0, 1, 0};

// Generated fields fill the view frustum between these distances from the eye.
constexpr double kNearDepth = 6;
constexpr double kFarDepth = 40;
// Mean number of object discs a primary ray passes through (before clipping and alpha holes):
// 2.5 covers about 90% of the pixels, so the picture is busy and objects overlap in depth.
constexpr double kDepthComplexity = 2.5;

// Odd, so multiplying by it permutes the 24-bit codes; kUnscramble is its inverse mod 2^24.
constexpr std::uint32_t kCodeMask = 0xFFFFFF;
constexpr std::uint32_t kScramble = 0x9E3779;

constexpr std::uint32_t inverse_mod_2_24(std::uint32_t odd) {
    std::uint32_t x = odd;  // Newton's iteration doubles the correct low bits each step
    for (int i = 0; i < 5; ++i) x *= 2u - odd * x;
    return x & kCodeMask;
}
constexpr std::uint32_t kUnscramble = inverse_mod_2_24(kScramble);
static_assert(((kScramble * kUnscramble) & kCodeMask) == 1, "kUnscramble inverts kScramble");

// Uniform doubles from the raw 64-bit stream of mt19937_64, whose sequence the C++ standard
// fixes; the standard distributions are implementation-defined and would differ between
// standard libraries.
class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double uniform(double lo, double hi) { return lo + (hi - lo) * ((engine_() >> 11) * 0x1.0p-53); }

private:
    std::mt19937_64 engine_;
};

std::array<std::uint8_t, 4> id_texel(std::uint32_t id, std::uint8_t alpha) {
    Color c = id_color(id);
    auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(v * 255)); };
    return {byte(c.x), byte(c.y), byte(c.z), alpha};
}

// A square image in the id's colour, whose texel (col, row) has the alpha alpha_at(col, row).
template <typename AlphaAt>
std::shared_ptr<Image> id_image(std::uint32_t id, int size, AlphaAt alpha_at) {
    auto image = std::make_shared<Image>();
    image->width = image->height = size;
    image->path = "bench:billboard-" + std::to_string(id);
    image->rgba.resize(static_cast<std::size_t>(size) * size * 4);
    for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) {
            auto texel = id_texel(id, alpha_at(col, row));
            std::copy(texel.begin(), texel.end(), image->rgba.begin() + (static_cast<std::ptrdiff_t>(row) * size + col) * 4);
        }
    return image;
}

// A cut-out sprite, like the course's fig1.png: an opaque disc with transparent corners and
// a ring of translucent texels (alpha 128), which the alpha test treats as holes too.
std::shared_ptr<Image> sprite_image(std::uint32_t id, int size) {
    return id_image(id, size, [size](int col, int row) -> std::uint8_t {
        double dx = col + 0.5 - size / 2.0, dy = row + 0.5 - size / 2.0;
        double r = std::sqrt(dx * dx + dy * dy) / (size / 2.0);  // 1 at the disc's edge
        return r > 1 ? 0 : (r > 0.45 && r < 0.55) ? 128 : 255;
    });
}

// A chessboard whose dark squares are transparent, like the course's fig2.png.
std::shared_ptr<Image> chessboard_image(std::uint32_t id, int size, int square) {
    return id_image(id, size, [square](int col, int row) -> std::uint8_t {
        return (col / square + row / square) % 2 == 0 ? 255 : 0;
    });
}

// Three differently cut-out pictures of one impostor, seen from 25 degrees left, straight
// ahead and 25 degrees right of the view axis: which one shows depends on where the impostor
// stands, as a tree's view does in a forest.
std::vector<ImpostorView> impostor_views(std::uint32_t id, int size) {
    const double side = 25 * kPi / 180;
    auto disc = sprite_image(id, size);
    auto square = id_image(id, size, [size](int col, int row) -> std::uint8_t {
        return col >= size / 8 && col < size - size / 8 && row >= size / 8 && row < size - size / 8 ? 255 : 0;
    });
    auto diamond = id_image(id, size, [size](int col, int row) -> std::uint8_t {
        double dx = std::abs(col + 0.5 - size / 2.0), dy = std::abs(row + 0.5 - size / 2.0);
        return dx + dy <= size / 2.0 ? 255 : 0;
    });
    return {{{-std::sin(side), 0, std::cos(side)}, disc}, {{0, 0, 1}, square}, {{std::sin(side), 0, std::cos(side)}, diamond}};
}

Sphere make_sphere(const Vec3& center, double radius, std::uint32_t id) {
    return testing::make_sphere(center, radius, id_color(id));
}

Billboard make_billboard(const Vec3& upper_left, const Vec3& lower_left, const Vec3& upper_right,
                         std::shared_ptr<const Image> image, std::uint32_t id) {
    return testing::make_billboard(upper_left, lower_left, upper_right, id_color(id), std::move(image));
}

Scene empty_scene(const BenchSceneSpec& spec, int width, int height) {
    Scene scene = testing::make_scene(kEye, kLookat, kUp, kFovDegrees, width, height);
    scene.path = "bench:" + spec.name;
    scene.name = spec.name;
    scene.background = id_color(kBackgroundId);
    scene.has_sun = false;  // flat shading: the benchmark measures primary rays only
    scene.only_ambient = true;
    return scene;
}

// Hand-placed like the course's scenes: three spheres in front of a large backdrop with
// chessboard holes, and a tilted cut-out sprite.
void add_course_objects(Scene& scene) {
    scene.spheres = {
        make_sphere({-1.9, -0.2, -8}, 1.5, sphere_id(0)),
        make_sphere({1.6, 0.5, -11}, 2.3, sphere_id(1)),
        make_sphere({0.1, -1.6, -6}, 0.8, sphere_id(2)),
    };
    std::uint32_t backdrop = billboard_id(3, 0), sprite = billboard_id(3, 1);
    scene.billboards = {
        make_billboard({-10, 6, -20}, {-10, -6, -20}, {10, 6, -20}, chessboard_image(backdrop, 32, 4), backdrop),
        make_billboard({1.8, 2.2, -7}, {1.8, -1.6, -7}, {4.0, 2.2, -8}, sprite_image(sprite, 32), sprite),
    };
}

// "course + mesh": a sun to the upper right, and a smooth tessellated ball (corner normals)
// low on the left, partly in the shadow of the nearer sphere; the sprite's shadow, through its
// holes, falls on the sphere behind it.
const Vec3 kCourseSun{8, 12, 4};

void add_course_ball(Scene& scene, const BenchSceneSpec& spec) {
    // slices x stacks quads of two triangles, slices = 2 stacks.
    int stacks = std::max(2, static_cast<int>(std::lround(std::sqrt(spec.ball_triangles / 4.0))));
    testing::TestMesh ball = testing::sphere_mesh({-3.2, -3.0, -13}, 1.6, 2 * stacks, stacks, true);
    testing::add_mesh(scene, ball, id_color(mesh_id(spec.spheres, spec.billboards, 0)));
    scene.has_sun = true;
    scene.only_ambient = false;
    scene.sun_location = kCourseSun;
}

// "100x100k triangles": rows of balls of one shape from above and in front, the sun behind the
// viewer's left shoulder, each ball shading the one behind it. They are one file placed again
// and again, as a scene's `obj` list would place it (Mesh::path alike: one tree shape).
const Vec3 kInstancesEye{0, 9, 12};
const Vec3 kInstancesLookat{0, 0, -6};
const Vec3 kInstancesSun{-10, 14, 16};

void add_instanced_balls(Scene& scene, const BenchSceneSpec& spec) {
    const int stacks = std::max(2, static_cast<int>(std::lround(std::sqrt(spec.instance_triangles / 4.0))));
    constexpr int kColumns = 10;
    constexpr double kSpacing = 2.4;
    // One ball, moved: each placement the same triangles shifted, as a file's are.
    const testing::TestMesh ball = testing::sphere_mesh({0, 0, 0}, 1, 2 * stacks, stacks, true);
    for (int i = 0; i < spec.instances; ++i) {
        const Vec3 shift{((i % kColumns) - (kColumns - 1) / 2.0) * kSpacing, 0, -(i / kColumns) * kSpacing};
        testing::TestMesh placed = ball;
        for (auto& triangle : placed.triangles)
            for (Vec3& corner : triangle) corner = corner + shift;
        testing::add_mesh(scene, placed, id_color(mesh_id(0, 0, i)));
        scene.meshes.back().path = "bench:ball.obj";
    }
    scene.camera_path.front() = CameraKey{kInstancesEye, kInstancesLookat};
    scene.has_sun = true;
    scene.only_ambient = false;
    scene.sun_location = kInstancesSun;
}

// The half extents of the image plane at distance 1 from the eye: the field of view spans the
// larger image dimension (docs/scene-format.md, Conventions: Camera).
struct PlaneExtent {
    double half_width, half_height;
};

PlaneExtent plane_extent(int width, int height) {
    double tan_half = std::tan(kFovDegrees * kPi / 360.0);
    double larger = std::max(width, height);
    return {tan_half * width / larger, tan_half * height / larger};
}

// A field of objects filling the view frustum: uniform screen position, uniform depth, and an
// angular radius that varies by a factor of 3, scaled with the object count so that every
// field has the same depth complexity.
void add_field_objects(Scene& scene, const BenchSceneSpec& spec, std::uint64_t seed) {
    PlaneExtent plane = plane_extent(scene.width, scene.height);
    double screen_area = 4 * plane.half_width * plane.half_height;
    int count = spec.objects();
    const double mean_square_factor = 13.0 / 12.0;  // E[f^2] for f uniform in [0.5, 1.5]
    double mean_radius = std::sqrt(kDepthComplexity * screen_area / (count * kPi * mean_square_factor));

    Random random(seed);
    // A point in view at depth d, and the world radius of a disc of angular radius rho there.
    auto place = [&](double& depth, double& radius) {
        depth = random.uniform(kNearDepth, kFarDepth);
        double sx = random.uniform(-1, 1), sy = random.uniform(-1, 1);
        radius = mean_radius * random.uniform(0.5, 1.5) * depth;
        return Vec3{sx * plane.half_width * depth, sy * plane.half_height * depth, -depth};
    };
    for (int i = 0; i < spec.spheres; ++i) {
        double depth, radius;
        Vec3 center = place(depth, radius);
        scene.spheres.push_back(make_sphere(center, radius, sphere_id(i)));
    }
    for (int j = 0; j < spec.billboards; ++j) {
        double depth, radius;
        Vec3 center = place(depth, radius);
        // Upright, turned by up to 45 degrees about the vertical; the sprite's disc has the
        // angular radius drawn for it, like a sphere's silhouette.
        double yaw = random.uniform(-kPi / 4, kPi / 4);
        Vec3 right = Vec3{std::cos(yaw), 0, std::sin(yaw)} * radius;
        Vec3 up = kUp * radius;
        std::uint32_t id = billboard_id(spec.spheres, j);
        scene.billboards.push_back(
            make_billboard(center - right + up, center - right - up, center + right + up, sprite_image(id, 16), id));
    }
    for (int k = 0; k < spec.impostors; ++k) {
        double depth, radius;
        Impostor impostor;
        impostor.center = place(depth, radius);
        impostor.width = impostor.height = 2 * radius;
        impostor.views = impostor_views(billboard_id(spec.spheres, spec.billboards + k), 16);
        scene.impostors.push_back(std::move(impostor));
    }
}

// The terrain scenes: the height field below, sampled on a square grid over [-30, 30] x
// [-63, -3] (two triangles a cell, split along the cell's diagonal), with its exact normals at
// the corners, so that the shading is smooth and the peers' normal interpolation is compared.
constexpr double kTerrainHalfWidth = 30;
constexpr double kTerrainNear = -3, kTerrainFar = -63;
const Vec3 kTerrainEye{0, 4, 2};
const Vec3 kTerrainLookat{0, -2, -22};
const Vec3 kTerrainSun{-30, 40, 0};

// Gentle hills with ripples on them, about 2.4 high around y = -3.
double terrain_height(double x, double z) {
    return -3 + std::sin(0.35 * x + 0.2 * z) * std::cos(0.3 * z) + 0.4 * std::sin(1.3 * x) * std::sin(1.1 * z + 0.5 * x);
}

// The unit upward normal (-dh/dx, 1, -dh/dz) of the height field at (x, z).
Vec3 terrain_normal(double x, double z) {
    double dx = 0.35 * std::cos(0.35 * x + 0.2 * z) * std::cos(0.3 * z) +
                0.4 * (1.3 * std::cos(1.3 * x) * std::sin(1.1 * z + 0.5 * x) +
                       0.5 * std::sin(1.3 * x) * std::cos(1.1 * z + 0.5 * x));
    double dz = 0.2 * std::cos(0.35 * x + 0.2 * z) * std::cos(0.3 * z) -
                0.3 * std::sin(0.35 * x + 0.2 * z) * std::sin(0.3 * z) +
                0.4 * 1.1 * std::sin(1.3 * x) * std::cos(1.1 * z + 0.5 * x);
    Vec3 n{-dx, 1, -dz};
    return n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
}

// Cells per side of a grid of about `triangles` triangles (two a cell).
int terrain_cells(int triangles) { return std::max(1, static_cast<int>(std::lround(std::sqrt(triangles / 2.0)))); }

void add_terrain_objects(Scene& scene, const BenchSceneSpec& spec) {
    const int cells = terrain_cells(spec.terrain_triangles);
    auto corner = [&](int i, int j) {
        double x = -kTerrainHalfWidth + 2 * kTerrainHalfWidth * i / cells;
        double z = kTerrainNear + (kTerrainFar - kTerrainNear) * j / cells;
        return Vec3{x, terrain_height(x, z), z};
    };
    auto normal = [](const Vec3& p) { return terrain_normal(p.x, p.z); };
    testing::TestMesh terrain;
    terrain.triangles.reserve(2 * static_cast<std::size_t>(cells) * cells);
    terrain.normals.reserve(terrain.triangles.capacity());
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            Vec3 p00 = corner(i, j), p10 = corner(i + 1, j), p11 = corner(i + 1, j + 1), p01 = corner(i, j + 1);
            terrain.triangles.push_back({p00, p10, p11});
            terrain.normals.push_back({normal(p00), normal(p10), normal(p11)});
            terrain.triangles.push_back({p00, p11, p01});
            terrain.normals.push_back({normal(p00), normal(p11), normal(p01)});
        }
    int billboard_count = spec.billboards + spec.impostors;
    testing::add_mesh(scene, terrain, id_color(mesh_id(spec.spheres, billboard_count, 0)));
    // The spheres float in a row above the hills, between the sun and the terrain in view.
    for (int i = 0; i < spec.spheres; ++i) {
        double x = -4.0 + 8.0 * (i + 0.5) / spec.spheres, z = -16.0 - 2.0 * i;
        scene.spheres.push_back(make_sphere({x, terrain_height(x, z) + 4.0, z}, 2.0, sphere_id(i)));
    }
}

std::vector<BenchSceneSpec> make_specs() {
    return {
        {"course", 3, 2},
        {"16+16", 16, 16},
        {"256+256", 256, 256},
        {"4096+4096", 4096, 4096},
        {"100k spheres", 100000, 0},
        {"10k impostors", 0, 0, 10000},
        {"70k triangles", 1, 0, 0, 70000},
        {"70k triangles flat", 1, 0, 0, 70000, 0, true},
        {"1M triangles", 1, 0, 0, 1000000},
        {"course + mesh", 3, 2, 0, 0, 25600},
        {"100x100k triangles", 0, 0, 0, 0, 0, false, 100, 100000},
    };
}

}  // namespace

const std::vector<BenchSceneSpec>& bench_scene_specs() {
    static const std::vector<BenchSceneSpec> specs = make_specs();
    return specs;
}

const BenchSceneSpec& find_bench_scene(const std::string& name) {
    std::string names;
    for (const BenchSceneSpec& spec : bench_scene_specs()) {
        if (spec.name == name) return spec;
        names += (names.empty() ? "" : ", ") + ("'" + spec.name + "'");
    }
    throw std::invalid_argument("unknown benchmark scene '" + name + "' (scenes: " + names + ")");
}

Scene make_bench_scene(const BenchSceneSpec& spec, int width, int height) {
    Scene scene = empty_scene(spec, width, height);
    if (spec.name == "course") {
        add_course_objects(scene);
    } else if (spec.ball_triangles > 0) {
        add_course_objects(scene);
        add_course_ball(scene, spec);
    } else if (spec.instances > 0) {
        add_instanced_balls(scene, spec);
    } else if (spec.terrain()) {
        scene.camera_path.front() = CameraKey{kTerrainEye, kTerrainLookat};
        scene.has_sun = true;
        scene.only_ambient = spec.unlit;
        scene.sun_location = kTerrainSun;
        add_terrain_objects(scene, spec);
    } else {
        // One fixed seed per object count, so that a scene never changes when others are added.
        std::uint64_t seed = 0x5EEDB0A4D000ull + 1000003ull * spec.spheres + spec.billboards + 7919ull * spec.impostors;
        add_field_objects(scene, spec, seed);
    }
    compute_triangle_ties(scene);  // as a scene file's meshes have them
    return scene;
}

Color id_color(std::uint32_t id) {
    std::uint32_t code = (id * kScramble) & kCodeMask;
    return Color{(code >> 16) / 255.0, ((code >> 8) & 0xFF) / 255.0, (code & 0xFF) / 255.0};
}

std::uint32_t id_of_bytes(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    std::uint32_t code = (std::uint32_t{r} << 16) | (std::uint32_t{g} << 8) | b;
    return (code * kUnscramble) & kCodeMask;
}

std::vector<std::uint32_t> object_ids(const Image& image) {
    std::vector<std::uint32_t> ids(static_cast<std::size_t>(image.width) * image.height);
    for (std::size_t i = 0; i < ids.size(); ++i)
        ids[i] = id_of_bytes(image.rgba[i * 4], image.rgba[i * 4 + 1], image.rgba[i * 4 + 2]);
    return ids;
}

}  // namespace clr::bench
