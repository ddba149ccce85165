// clrender --explain-pixel X,Y through the real binary (docs/explain-pixel.md). Each expected
// number is worked out here from the scene's numbers with the lecture's formulas (camera basis,
// witness point, ray-sphere quadratic, ray-plane t_hit, mirror r = d - 2(d.n)n), not by calling
// the reference, and compared with what the explanation prints.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <sys/wait.h>
#include <string>

#include "core/vec3.h"
#include "scene/image_loader.h"
#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::run_clrender;
using testing::TempFolder;

constexpr double kPi = 3.14159265358979323846;
constexpr double kClose = 1e-7;  // printed with 9 significant digits, computed in another order

// The lecture's camera: w = unit(Eye - LookAt), u = unit(Up x w), v = w x u, the image plane at
// distance 1 with half extent tan(fov/2) across the larger side; the ray through the centre
// of pixel (column j, row i from the top).
Vec3 lecture_ray_direction(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov, int nx, int ny, int j,
                           int i) {
    const Vec3 w = normalize(eye - lookat);
    const Vec3 u = normalize(cross(up, w));
    const Vec3 v = cross(w, u);
    const double half = std::tan(fov * kPi / 360);
    const double hw = nx >= ny ? half : half * nx / ny;
    const double hh = nx >= ny ? half * ny / nx : half;
    const double x = (2.0 * j + 1) / nx - 1;
    const double y = 1 - (2.0 * i + 1) / ny;
    return normalize(-w + u * (x * hw) + v * (y * hh));
}

// The number printed right after `label` in `text`, searching from `from` (the first
// occurrence after it); NaN when the label is missing.
double number_after(const std::string& text, const std::string& label, std::size_t from = 0) {
    const std::size_t at = text.find(label, from);
    if (at == std::string::npos) return std::nan("");
    return std::strtod(text.c_str() + at + label.size(), nullptr);
}

// The vector "(x, y, z)" printed right after `label`.
Vec3 vector_after(const std::string& text, const std::string& label, std::size_t from = 0) {
    const std::size_t at = text.find(label, from);
    if (at == std::string::npos) return {std::nan(""), std::nan(""), std::nan("")};
    std::smatch match;
    const std::string rest = text.substr(at + label.size(), 120);
    static const std::regex pattern(R"(^\(([^,]+), ([^,]+), ([^)]+)\))");
    if (!std::regex_search(rest, match, pattern)) return {std::nan(""), std::nan(""), std::nan("")};
    return {std::stod(match[1]), std::stod(match[2]), std::stod(match[3])};
}

void expect_close(const Vec3& actual, const Vec3& expected, const std::string& what) {
    EXPECT_NEAR(actual.x, expected.x, kClose) << what;
    EXPECT_NEAR(actual.y, expected.y, kClose) << what;
    EXPECT_NEAR(actual.z, expected.z, kClose) << what;
}

// The R G B bytes printed after `label` ("... : 12 34 56").
std::string bytes_after(const std::string& text, const std::string& label) {
    const std::size_t at = text.find(label);
    if (at == std::string::npos) return "(missing)";
    std::smatch match;
    const std::string rest = text.substr(at + label.size(), 80);
    static const std::regex pattern(R"(^[^:]*: (\d+ \d+ \d+))");
    return std::regex_search(rest, match, pattern) ? std::string(match[1]) : "(unreadable)";
}

std::string pixel_bytes(const Image& image, int col, int row) {
    return std::to_string(image.at(col, row, 0)) + " " + std::to_string(image.at(col, row, 1)) + " " +
           std::to_string(image.at(col, row, 2));
}

// ---------------------------------------------------------------------------------------

const char* kSphereScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1],
  "spheres": [{"type": "sphere", "center": [0.2, -0.1, 0.3], "radius": 1.5, "ambient": [1, 0.5, 0.25]}]
})";

TEST(ExplainPixel, SphereHitPrintsTheLecturesQuadratic) {
    TempFolder folder;
    folder.write("sphere.json", kSphereScene);
    const auto result = run_clrender("sphere.json --explain-pixel 25,10", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string& text = result.output;

    const Vec3 eye{0, 0, 6}, centre{0.2, -0.1, 0.3};
    const double radius = 1.5;
    const Vec3 d = lecture_ray_direction(eye, {0, 0, 0}, {0, 1, 0}, 60, 40, 30, 25, 10);
    expect_close(vector_after(text, "w = unit(Eye - LookAt) = "), {0, 0, 1}, "w");
    expect_close(vector_after(text, "u = unit(Up x w) = "), {1, 0, 0}, "u");
    expect_close(vector_after(text, "v = w x u = "), {0, 1, 0}, "v");
    EXPECT_NEAR(number_after(text, "half width hw = "), std::tan(kPi / 6), kClose);
    EXPECT_NEAR(number_after(text, "half height hh = "), std::tan(kPi / 6) * 30 / 40, kClose);
    expect_close(vector_after(text, "d = unit(P(i, j) - Eye) = "), d, "ray direction");

    // A t^2 + B t + C = 0 with A = d.d, B = 2 d.(o - c), C = (o - c).(o - c) - R^2.
    const double a = dot(d, d);
    const double b = 2 * dot(d, eye - centre);
    const double c = dot(eye - centre, eye - centre) - radius * radius;
    const double discriminant = b * b - 4 * a * c;
    ASSERT_GT(discriminant, 0) << "the test's ray must hit";
    const double t = (-b - std::sqrt(discriminant)) / (2 * a);
    EXPECT_NEAR(number_after(text, "B = 2 d.(o - c) = "), b, kClose);
    EXPECT_NEAR(number_after(text, "C = (o - c).(o - c) - R^2 = "), c, kClose);
    EXPECT_NEAR(number_after(text, "discriminant B^2 - 4AC = "), discriminant, 1e-6);
    EXPECT_NEAR(number_after(text, "roots t = "), t, kClose);
    EXPECT_NEAR(number_after(text, "hit at t = "), t, kClose);
    EXPECT_NEAR(number_after(text, "nearest: sphere 0 at t = "), t, kClose);
    expect_close(vector_after(text, "hit point o + t d = "), eye + d * t, "hit point");
    EXPECT_NE(text.find("colour: the sphere's ambient colour (1, 0.5, 0.25)"), std::string::npos) << text;
    EXPECT_EQ(bytes_after(text, "bytes the reference writes"), "255 128 64") << text;
}

TEST(ExplainPixel, KernelBytesPrintedAreTheRenderedPixel) {
    TempFolder folder;
    folder.write("sphere.json", kSphereScene);
    ASSERT_EQ(run_clrender("sphere.json -q -o kernel.png", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("sphere.json -q --reference -o reference.png", folder.path()).exit_code, 0);
    const auto kernel = load_image(folder.file("kernel.png"));
    const auto reference = load_image(folder.file("reference.png"));
    // A pixel on the sphere, one on its silhouette's neighbourhood and the background corner.
    for (const auto& [col, row] : {std::pair{25, 10}, std::pair{12, 20}, std::pair{0, 0}, std::pair{39, 29}}) {
        const std::string where = std::to_string(col) + "," + std::to_string(row);
        const auto result = run_clrender("sphere.json --explain-pixel " + where, folder.path());
        ASSERT_EQ(result.exit_code, 0) << result.output;
        EXPECT_EQ(bytes_after(result.output, "bytes the OpenCL kernels write"), pixel_bytes(*kernel, col, row))
            << where << "\n" << result.output;
        EXPECT_EQ(bytes_after(result.output, "bytes the reference writes"), pixel_bytes(*reference, col, row))
            << where << "\n" << result.output;
    }
}

TEST(ExplainPixel, ReferenceOnlyRunsNoKernels) {
    TempFolder folder;
    folder.write("sphere.json", kSphereScene);
    const auto result = run_clrender("sphere.json --reference --explain-pixel 0,0", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("OpenCL kernels: not run (--reference)"), std::string::npos) << result.output;
    EXPECT_EQ(bytes_after(result.output, "bytes the reference writes"), "26 26 26") << result.output;
    EXPECT_EQ(folder.entry_count(), 1) << "--explain-pixel writes no files";
}

// A 2x1 texture: the left texel opaque red, the right one a hole (alpha 0).
void write_cutout(const TempFolder& folder) {
    const unsigned char rgba[8] = {255, 0, 0, 255, 0, 255, 0, 0};
    ASSERT_TRUE(stbi_write_png(folder.file("cutout.png").c_str(), 2, 1, 4, rgba, 8));
}

const char* kHoleScene = R"({
  "eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 20, "height": 20, "DefaultColor": [0, 0, 0],
  "billboards": [
    {"type": "billboard", "UpperLeft": [-2, 2, 0], "LowerLeft": [-2, -2, 0], "UpperRight": [2, 2, 0],
     "filename": "cutout.png"},
    {"type": "billboard", "UpperLeft": [-10, 10, -3], "LowerLeft": [-10, -10, -3], "UpperRight": [10, 10, -3],
     "ambient": [0, 0, 1]}]
})";

TEST(ExplainPixel, HoleInATextureIsRejectedAndTheBillboardBehindChosen) {
    TempFolder folder;
    write_cutout(folder);
    folder.write("hole.json", kHoleScene);
    const auto result = run_clrender("hole.json --explain-pixel 14,9", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string& text = result.output;

    // Plane z = 0, n = (LL - UL) x (UR - UL): t_hit = ((UL - o).n) / (d.n); alpha and beta are
    // the lecture's projections of r = P - UL on the unit edges, over the edges' lengths.
    const Vec3 eye{0, 0, 5}, ul{-2, 2, 0}, ur{2, 2, 0}, ll{-2, -2, 0};
    const Vec3 d = lecture_ray_direction(eye, {0, 0, 0}, {0, 1, 0}, 60, 20, 20, 14, 9);
    const Vec3 n = cross(ll - ul, ur - ul);
    const double t_hit = dot(ul - eye, n) / dot(d, n);
    const Vec3 r = eye + d * t_hit - ul;
    const double alpha = dot(r, normalize(ur - ul)) / length(ur - ul);
    const double beta = dot(r, normalize(ll - ul)) / length(ll - ul);
    ASSERT_GE(alpha, 0.5) << "the test's ray must land on the right texel, the hole";

    const std::size_t first = text.find("billboard 0 (");
    ASSERT_NE(first, std::string::npos) << text;
    EXPECT_NEAR(number_after(text, "t_hit = ((UL - o).n) / (d.n) = ", first), t_hit, kClose);
    expect_close(vector_after(text, "point o + t_hit d = ", first), eye + d * t_hit, "billboard 0's point");
    const std::size_t pair = text.find("(alpha, beta) = (", first);
    EXPECT_NEAR(number_after(text, "(alpha, beta) = (", first), alpha, kClose);
    EXPECT_NEAR(number_after(text, ", ", pair + 17), beta, kClose);
    EXPECT_NE(text.find("texel (column 1, row 0) of the 2x1 image, alpha 0: a hole (alpha < 255), rejected", first),
              std::string::npos)
        << text;

    // Behind it: z = -3, t_hit = 8 / -d.z.
    const double t_behind = (-3 - 5) / d.z;
    const std::size_t second = text.find("billboard 1 (");
    ASSERT_NE(second, std::string::npos) << text;
    EXPECT_NEAR(number_after(text, "t_hit = ((UL - o).n) / (d.n) = ", second), t_behind, kClose);
    EXPECT_NE(text.find("inside: hit, the nearest so far", second), std::string::npos) << text;
    EXPECT_NEAR(number_after(text, "nearest: billboard 1 at t = "), t_behind, kClose) << text;
    EXPECT_NE(text.find("colour: the billboard's flat colour (0, 0, 1)"), std::string::npos) << text;
    EXPECT_EQ(bytes_after(text, "bytes the reference writes"), "0 0 255") << text;
    EXPECT_EQ(bytes_after(text, "bytes the OpenCL kernels write"), "0 0 255") << text;

    // The opaque half shows the texel itself.
    const auto opaque = run_clrender("hole.json --reference --explain-pixel 6,9", folder.path());
    ASSERT_EQ(opaque.exit_code, 0) << opaque.output;
    EXPECT_NE(opaque.output.find("alpha 255: hit, the nearest so far"), std::string::npos) << opaque.output;
    EXPECT_NE(opaque.output.find("colour: texel (column 0, row 0) = bytes 255 0 0"), std::string::npos)
        << opaque.output;
}

// Sphere 0 seen head-on at (0, 0, 1); the sun at (0, 8, 8); sphere 1 sits halfway on the
// shadow ray from (0, 0, 1) towards the sun.
const char* kShadowScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 21, "height": 21, "DefaultColor": [0, 0, 0], "SunLocation": [0, 8, 8], "OnlyAmbient": 0,
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]},
              {"type": "sphere", "center": [0, 4, 4.5], "radius": 0.5, "ambient": [0, 1, 0]}]
})";

TEST(ExplainPixel, ShadowedPointNamesItsBlocker) {
    TempFolder folder;
    folder.write("shadow.json", kShadowScene);
    const auto result = run_clrender("shadow.json --explain-pixel 10,10", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string& text = result.output;

    // The centre pixel of an odd-sized image looks straight down -w: the hit is (0, 0, 1).
    const Vec3 point{0, 0, 1}, sun{0, 8, 8};
    const Vec3 l = normalize(sun - point);
    EXPECT_NEAR(number_after(text, "nearest: sphere 0 at t = "), 5, kClose) << text;
    expect_close(vector_after(text, "l = unit(sun - point) = "), l, "l");
    EXPECT_NEAR(number_after(text, "n.l = "), dot(Vec3{0, 0, 1}, l), kClose) << text;

    // The shadow ray meets sphere 1 at its nearer root.
    const Vec3 blocker{0, 4, 4.5};
    const double b = 2 * dot(l, point - blocker);
    const double c = dot(point - blocker, point - blocker) - 0.25;
    const double t = (-b - std::sqrt(b * b - 4 * c)) / 2;
    const std::size_t shadow = text.find("-- shadow ray");
    ASSERT_NE(shadow, std::string::npos) << text;
    EXPECT_NEAR(number_after(text, "0 < t < ", shadow), length(sun - point), kClose) << text;
    EXPECT_EQ(text.find("sphere 0 (", shadow), std::string::npos) << "the shadow ray skips the sphere it leaves";
    EXPECT_NEAR(number_after(text, "blocked by sphere 1 at t = ", shadow), t, kClose) << text;
    EXPECT_NE(text.find("the point is in shadow, s = 0", shadow), std::string::npos) << text;
    EXPECT_EQ(bytes_after(text, "bytes the reference writes"), "0 0 0") << text;
    EXPECT_EQ(bytes_after(text, "bytes the OpenCL kernels write"), "0 0 0") << text;
}

// A mirror in the plane z = 0 facing the eye; the reflected ray comes back towards +z, where a
// large sphere behind the eye catches it.
const char* kMirrorScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 21, "height": 21, "DefaultColor": [0, 0, 0],
  "spheres": [{"type": "sphere", "center": [0, 0, 14], "radius": 7, "ambient": [0, 1, 0]}],
  "billboards": [{"type": "billboard", "UpperLeft": [-3, 3, 0], "LowerLeft": [-3, -3, 0], "UpperRight": [3, 3, 0],
                  "IsMirror": 1}]
})";

TEST(ExplainPixel, MirrorBounceShowsTheReflectedRayAndItsHit) {
    TempFolder folder;
    folder.write("mirror.json", kMirrorScene);
    const auto result = run_clrender("mirror.json --explain-pixel 13,8", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string& text = result.output;

    const Vec3 eye{0, 0, 6};
    const Vec3 d = lecture_ray_direction(eye, {0, 0, 0}, {0, 1, 0}, 60, 21, 21, 13, 8);
    const double t_mirror = -6 / d.z;
    const Vec3 point = eye + d * t_mirror;
    const Vec3 n{0, 0, 1};
    const Vec3 r = d - n * (2 * dot(d, n));
    EXPECT_NE(text.find("rejected: behind the ray's origin"), std::string::npos) << "sphere 0 behind the eye\n" << text;
    EXPECT_NEAR(number_after(text, "nearest: billboard 0 at t = "), t_mirror, kClose) << text;

    const std::size_t bounce = text.find("-- reflected ray 1 of at most MaxDepth = 5");
    ASSERT_NE(bounce, std::string::npos) << text;
    expect_close(vector_after(text, "o = ", bounce), point, "reflected ray's origin");
    expect_close(vector_after(text, "d = ", bounce), r, "reflected ray's direction");

    const Vec3 centre{0, 0, 14};
    const double b = 2 * dot(r, point - centre);
    const double c = dot(point - centre, point - centre) - 49;
    const double t = (-b - std::sqrt(b * b - 4 * c)) / 2;
    EXPECT_NEAR(number_after(text, "nearest: sphere 0 at t = ", bounce), t, kClose) << text;
    EXPECT_NE(text.find("colour: the sphere's ambient colour (0, 1, 0)", bounce), std::string::npos) << text;
    EXPECT_EQ(bytes_after(text, "bytes the reference writes"), "0 255 0") << text;
}

TEST(ExplainPixel, AnimationFrameChosenByFrames) {
    TempFolder folder;
    folder.write("path.json", R"({
      "eyeLocations": [[0, 0, 6], [3, 0, 6]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
      "width": 8, "height": 6, "DefaultColor": [0, 0, 0]})");
    const auto result = run_clrender("path.json --reference --explain-pixel 1,1 --frames 10", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("of frame 10 of"), std::string::npos) << result.output;
    expect_close(vector_after(result.output, "Eye = "), {3, 0, 6}, "the last key's eye");
}

TEST(ExplainPixel, SeveralSamplesAreEachExplained) {
    TempFolder folder;
    folder.write("sphere.json", kSphereScene);
    const auto result = run_clrender("sphere.json --spp 4 --explain-pixel 12,20", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* sample : {"== Sample 0 of 4", "== Sample 1 of 4", "== Sample 2 of 4", "== Sample 3 of 4"})
        EXPECT_NE(result.output.find(sample), std::string::npos) << sample << "\n" << result.output;
    EXPECT_NE(result.output.find("pixel colour = mean of 4 sample(s)"), std::string::npos) << result.output;
}

TEST(ExplainPixel, UnwritableStandardOutputIsAnOutputError) {
    TempFolder folder;
    folder.write("sphere.json", kSphereScene);
    const std::string command = "cd '" + folder.path() + "' && '" + CLRENDER_BINARY +
                                "' sphere.json --reference --explain-pixel 1,1 >/dev/full 2>err.txt";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 4);
    EXPECT_EQ(testing::read_bytes(folder.file("err.txt")),
              "clrender: error: standard output: cannot write the explanation (disk full or pipe closed?)\n");
}

// Two mirrors facing each other 10 apart, the eye between them looking at one, and 40 small
// spheres beside the corridor that every ray of every bounce tests; `spp` samples a pixel.
std::string mirror_corridor(int spp) {
    std::string spheres;
    for (int i = 0; i < 40; ++i)
        spheres += std::string(i ? ", " : "") + "{\"center\": [" + std::to_string(-20 + i) + ", 6, 0], \"radius\": 0.3, \"ambient\": [0.5, 0.5, 0.5]}";
    return R"({
      "eye": [0, 0, 0], "lookat": [0, 0, -1], "up": [0, 1, 0], "fov_angle": 30,
      "width": 8, "height": 8, "MaxDepth": 64, "DefaultColor": [0.1, 0.1, 0.1], "clrender": {"spp": )" +
           std::to_string(spp) + R"(},
      "billboards": [
        {"UpperLeft": [-50, 50, -5], "LowerLeft": [-50, -50, -5], "UpperRight": [50, 50, -5], "ambient": [1, 1, 1], "IsMirror": 1},
        {"UpperLeft": [-50, 50, 5], "LowerLeft": [50, 50, 5], "UpperRight": [-50, -50, 5], "ambient": [1, 1, 1], "IsMirror": 1}],
      "spheres": [)" + spheres + "]}";
}

// Two mirrors facing each other, 40 spheres tested on every ray, 32 samples of 64 reflections:
// about 20 MB of steps (hundreds of MB with more samples), once held whole in memory. The explanation stops its steps at the documented 16 MiB, says so, and
// still ends with the result of every sample.
TEST(ExplainPixel, ManySamplesWithDeepMirrorsAreBounded) {
    TempFolder folder;
    folder.write("mirrors.json", mirror_corridor(32));
    const std::string command = "cd '" + folder.path() + "' && '" + CLRENDER_BINARY +
                                "' mirrors.json --reference --explain-pixel 4,4 >explanation.txt 2>stderr.txt";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << testing::read_bytes(folder.file("stderr.txt"));
    const std::string text = testing::read_bytes(folder.file("explanation.txt"));
    constexpr std::size_t kLimit = std::size_t(16) << 20;
    EXPECT_GT(text.size(), kLimit);
    EXPECT_LT(text.size(), kLimit + 64 * 1024) << "the steps stop at the end of the line crossing 16 MiB";
    const std::size_t cut = text.find("\n\n... ");  // the note, on a line of its own after the last whole line
    ASSERT_NE(cut, std::string::npos);
    EXPECT_GT(cut, kLimit - 1);
    std::smatch note;
    const std::string note_line = text.substr(cut + 2, text.find('\n', cut + 2) - cut - 2);
    ASSERT_TRUE(std::regex_match(note_line, note, std::regex(R"(\.\.\. (\d+) more bytes of steps left out: an explanation prints at most 16 MiB of them .*)")))
        << note_line;
    EXPECT_GT(std::stoull(note[1]), 1000000u) << "about 20 MB of steps in all";
    EXPECT_NE(text.find("== Result ==\npixel colour = mean of 32 sample(s)", cut), std::string::npos);
    EXPECT_NE(text.find("OpenCL kernels: not run (--reference)\n", cut), std::string::npos);
    EXPECT_NE(text.find("== Sample 0 of 32"), std::string::npos);
    EXPECT_EQ(text.find("== Sample 31 of 32"), std::string::npos) << "the last sample's steps are past the limit";
}

TEST(ExplainPixel, HelpAndTheOptionsReferenceDescribeIt) {
    const auto help = run_clrender("--help");
    EXPECT_NE(help.output.find("--explain-pixel"), std::string::npos) << help.output;
    const std::string reference = testing::read_bytes(std::string(CLRENDER_SOURCE_DIR) + "/docs/command-line.md");
    EXPECT_NE(reference.find("| `--explain-pixel X,Y` |"), std::string::npos);
    const std::string page = testing::read_bytes(std::string(CLRENDER_SOURCE_DIR) + "/docs/explain-pixel.md");
    EXPECT_NE(page.find("## A worked example"), std::string::npos);
}

}  // namespace
}  // namespace clr

namespace clr {
namespace {

// A mesh of two triangles: one before the camera, one off to the side that the pixel's ray
// passes by. Corners listed clockwise as seen from the eye: a mesh has no back, so its normal
// is turned to face the ray, and the sun on the eye's side lights it.
const char* kTriangleScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1], "SunLocation": [1, 2, 9],
  "obj": {"filename": "two.obj", "position": [0, 0, -1], "ambient": [0.5, 1, 0.25]}
})";
const char* kTwoTriangles = "v -2 -1.5 0\nv 0.5 2 -0.5\nv 2.5 -1 0.5\nv 10 10 0\nv 11 10 0\nv 10 11 0\nf 1 2 3\nf 4 5 6\n";

TEST(ExplainPixel, TriangleHitPrintsThePlaneTestAndBarycentricCoordinates) {
    TempFolder folder;
    folder.write("tri.json", kTriangleScene);
    folder.write("two.obj", kTwoTriangles);
    const auto result = run_clrender("tri.json --explain-pixel 21,14", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string& text = result.output;

    const Vec3 eye{0, 0, 6};
    const Vec3 c0{-2, -1.5, -1}, c1{0.5, 2, -1.5}, c2{2.5, -1, -0.5};
    const Vec3 d = lecture_ray_direction(eye, {0, 0, 0}, {0, 1, 0}, 60, 40, 30, 21, 14);
    // The plane n = (c1 - c0) x (c2 - c0), t = ((c0 - o).n) / (d.n), and the point's
    // barycentric coordinates as ratios of the areas of the triangles it makes with the edges.
    const Vec3 n = cross(c1 - c0, c2 - c0);
    const double t = dot(c0 - eye, n) / dot(d, n);
    const Vec3 p = eye + d * t;
    const double area = length(n);
    const double b0 = length(cross(c1 - p, c2 - p)) / area;
    const double b1 = length(cross(c2 - p, c0 - p)) / area;
    const double b2 = length(cross(c0 - p, c1 - p)) / area;
    ASSERT_NEAR(b0 + b1 + b2, 1, 1e-12) << "the test's ray must hit inside";
    const std::string name = "triangle 0 of mesh 0 ('two.obj')";
    EXPECT_NE(text.find(name + " (c0 = (-2, -1.5, -1), c1 = (0.5, 2, -1.5), c2 = (2.5, -1, -0.5))"), std::string::npos)
        << text;
    EXPECT_NEAR(number_after(text, "t_hit = ((c0 - o).n) / (d.n) = "), t, kClose);
    expect_close(vector_after(text, "barycentric (b0, b1, b2) = "), {b0, b1, b2}, "barycentric");
    EXPECT_NEAR(number_after(text, "nearest: " + name + " at t = "), t, kClose);
    EXPECT_NE(text.find("1 triangle: the ray passes outside"), std::string::npos) << text;

    // Lit: the normal faces the eye, n.l with the sun, nothing in the way.
    Vec3 facing = normalize(n);
    if (dot(facing, d) > 0) facing = -facing;
    expect_close(vector_after(text, "normal n = "), facing, "normal facing the ray");
    const Vec3 l = normalize(Vec3{1, 2, 9} - p);
    const double cosine = dot(facing, l);
    ASSERT_GT(cosine, 0);
    EXPECT_NEAR(number_after(text, "n.l = "), cosine, kClose);
    const auto byte = [](double c) { return std::to_string(static_cast<int>(std::floor(std::min(1.0, c) * 255 + 0.5))); };
    EXPECT_EQ(bytes_after(text, "bytes the reference writes"),
              byte(0.5 * cosine) + " " + byte(cosine) + " " + byte(0.25 * cosine))
        << text;
    EXPECT_NE(text.find("bytes the OpenCL kernels write"), std::string::npos);
}

// A faceted pyramid seen along its axis at an odd image size: the centre pixel's ray runs
// through its apex, those on the image's diagonals along its ridges. Such a hit is settled on
// the lowest-numbered triangle there, and the narration says so; the kernels give the bytes.
TEST(ExplainPixel, AHitOnASharedEdgeOrCornerNamesTheTriangleShadedThere) {
    TempFolder folder;
    folder.write("pyramid.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
      "width": 161, "height": 121, "DefaultColor": [0.1, 0.1, 0.2], "SunLocation": [10, 20, 30],
      "obj": {"filename": "pyramid.obj", "ambient": [0.9, 0.7, 0.3]}})");
    folder.write("pyramid.obj", "v 0 0 1\nv 1 1 0\nv -1 1 0\nv -1 -1 0\nv 1 -1 0\nf 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 2\n");
    const std::string lowest = "triangle 0 of mesh 0 ('pyramid.obj')";
    const auto explained = [&](const std::string& where) {
        const auto result = run_clrender("pyramid.json --explain-pixel " + where, folder.path());
        EXPECT_EQ(result.exit_code, 0) << result.output;
        EXPECT_EQ(bytes_after(result.output, "bytes the reference writes"),
                  bytes_after(result.output, "bytes the OpenCL kernels write"))
            << result.output;
        return result.output;
    };
    // The apex is corner c0 of every face; face 0 is the lowest around it.
    const std::string apex = explained("80,60");
    EXPECT_NE(apex.find("the hit point lies on corner c0 of triangle "), std::string::npos) << apex;
    EXPECT_TRUE(apex.find("the lowest-numbered triangle there is " + lowest) != std::string::npos ||
                apex.find("corner c0 of " + lowest) != std::string::npos)
        << apex;
    // Ten pixels right and up: the ridge x = y, shared by faces 0 and 3 (its edge c0-c1 or c2-c0).
    const std::string ridge = explained("90,50");
    EXPECT_NE(ridge.find("the hit point lies on edge "), std::string::npos) << ridge;
    EXPECT_NE(ridge.find(lowest), std::string::npos) << ridge;
    EXPECT_NE(ridge.find("triangle 3 of mesh 0 ('pyramid.obj')"), std::string::npos) << ridge;
    // Twenty pixels right of the centre: inside face 3, nothing to settle.
    const std::string inside = explained("100,60");
    EXPECT_EQ(inside.find("the hit point lies on"), std::string::npos) << inside;
}

// The fall 2019 format: a plane lit by a point light, in the model's terms.
TEST(ExplainPixel, PlaneLitByAPointLightPrintsTheBlinnPhongTerms) {
    TempFolder folder;
    folder.write("plane.json", R"({
      "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 40, "height": 30,
      "surfaces": [{"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 3], "ambient": [0.1, 0.2, 0.05],
                    "diffuse": [0.5, 0.25, 0.75], "specular": [0.3, 0.3, 0.3], "phong_exponent": 5}],
      "lights": [{"position": [1, 2, 9], "color": [0.8, 0.6, 0.4]}]})");
    const auto result = run_clrender("plane.json --explain-pixel 21,14", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string& text = result.output;

    const Vec3 eye{0, 0, 6};
    const Vec3 d = lecture_ray_direction(eye, {0, 0, 0}, {0, 1, 0}, 60, 40, 30, 21, 14);
    const Vec3 n{0, 0, 1};  // the plane's unit normal, facing the eye
    const double t = dot(Vec3{0, 0, -1} - eye, n) / dot(d, n);
    const Vec3 p = eye + d * t;
    EXPECT_NE(text.find("plane 0 (P0 = (0, 0, -1), n = (0, 0, 1))"), std::string::npos) << text;
    EXPECT_NEAR(number_after(text, "t = ((P0 - o).n) / (d.n) = "), t, kClose);
    const Vec3 l = normalize(Vec3{1, 2, 9} - p);
    const Vec3 h = normalize(l - d);
    const double cosine = dot(n, l), highlight = std::pow(dot(n, h), 5);
    EXPECT_NEAR(number_after(text, "light 0 at (1, 2, 9), colour (0.8, 0.6, 0.4): n.l = "), cosine, kClose);
    EXPECT_NEAR(number_after(text, "max(0, n.h)^p = "), highlight, kClose);
    // L = k_a + I (k_d n.l + k_s max(0, n.h)^p), channel by channel.
    const Vec3 colour{0.1 + 0.8 * (0.5 * cosine + 0.3 * highlight), 0.2 + 0.6 * (0.25 * cosine + 0.3 * highlight),
                      0.05 + 0.4 * (0.75 * cosine + 0.3 * highlight)};
    const auto byte = [](double c) { return std::to_string(static_cast<int>(std::floor(std::min(1.0, c) * 255 + 0.5))); };
    EXPECT_EQ(bytes_after(text, "bytes the reference writes"), byte(colour.x) + " " + byte(colour.y) + " " + byte(colour.z))
        << text;
    EXPECT_NE(text.find("colour = ambient + sum over the lights counted of I (k_d n.l + k_s max(0, n.h)^p)"),
              std::string::npos)
        << text;
}

// A camera with a near clip distance searches from the near plane: the story says where that
// search starts, and every point it prints lies on its surface (they were the points of t
// measured from the near plane applied to the eye's ray: 2.1 above the floor they named).
TEST(ExplainPixel, ANearPlaneSearchSaysWhereItStarts) {
    TempFolder folder;
    folder.write("floor.obj", "v -10 0 -10\nv 10 0 -10\nv 10 0 10\nv -10 0 10\nf 1 2 3 4\n");
    folder.write("near.json", R"({"eye": [0, 2, 8], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
        "width": 80, "height": 60, "near": 5,
        "obj": {"filename": "floor.obj", "position": [0, -0.5, 0], "ambient": [0.7, 0.7, 0.7]}})");
    const auto result = run_clrender("near.json --reference --explain-pixel 40,45", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string& text = result.output;
    const Vec3 eye{0, 2, 8};
    const Vec3 d = lecture_ray_direction(eye, {0, 0, 0}, {0, 1, 0}, 50, 80, 60, 40, 45);
    // The near plane lies 5 along the view direction -w: t_start = near / (d.-w).
    const double t_start = 5 / dot(d, normalize(Vec3{0, 0, 0} - eye));
    EXPECT_NEAR(number_after(text, "t from "), t_start, kClose * 10) << text;
    expect_close(vector_after(text, " d = ", text.find("o' = o + ")), eye + d * t_start, "the near plane's point");
    // Wherever it is printed, the floor's point lies on the floor, at the eye's t along d.
    const double t = (-0.5 - eye.y) / d.y;
    expect_close(vector_after(text, ", point "), eye + d * t, "the triangle's point");
    EXPECT_NEAR(number_after(text, "nearest: triangle 1 of mesh 0 ('floor.obj') at t = "), t, kClose * 10) << text;
    expect_close(vector_after(text, "hit point o + t d = "), eye + d * t, "the hit point");
}

// Ctrl-C ends a long explanation between two samples: exit 130 and the run's own message, not
// the watchdog that ends a run whose work ignores the signal.
TEST(ExplainPixel, CtrlCEndsALongExplanation) {
    TempFolder folder;
    folder.write("mirrors.json", mirror_corridor(4096));  // each sample's 64 bounces test 40 spheres
    const auto run = testing::run_clrender_interrupted("mirrors.json --reference --explain-pixel 4,4", folder.path(), 1);
    const std::string& errors = run.output;
    EXPECT_EQ(run.exit_code, 130) << errors;
    EXPECT_NE(errors.find("interrupted by SIGINT"), std::string::npos) << errors;
    EXPECT_EQ(errors.find("cannot be interrupted"), std::string::npos) << "the watchdog ended it: " << errors;
}

}  // namespace
}  // namespace clr
