// A scene's `obj` meshes (scene/mesh_loader): one object or a list, placed as
// p * scale + position with a number or per-axis scale, normals transformed as normals, the
// ambient colour from the scene, else the .mtl's Kd, else 0.8 grey; a missing or bad OBJ is
// the scene's error at its "filename" (or a placeholder cube with --placeholders); bad
// settings are refused where they are written.
#include <gtest/gtest.h>

#include <cstdlib>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/output_plan.h"
#include "core/errors.h"
#include "output/output_roles.h"
#include "scene/mesh_loader.h"
#include "scene/obj_reader.h"
#include "scene/scene_loader.h"
#include "support/address_space_child.h"
#include "support/scene_json.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;
using testing::scene_json::Json;
using testing::scene_json::minimal_scene;

// Two triangles of the unit square in z = 0, with a normal per corner tilted away from +z.
const std::string kSquareObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 1 0 1\nvn 0 1 1\nvn 0 0 1\nf 1//1 2//2 3//3 4//3\n";

// Writes `scene` beside the files already in `folder` and loads it.
Scene load_in(const TempFolder& folder, const Json& scene, const LoadOptions& options = {}) {
    return load_scene(folder.write("scene.json", scene.dump()), options);
}

Json with_obj(const Json& obj) {
    Json scene = minimal_scene();
    scene["obj"] = obj;
    return scene;
}

// The text of an OBJ strip of `columns` - 1 triangles (2 * columns corners in two rows),
// after `head`: big enough that reading it again shows in the bytes read.
std::string strip_obj(int columns, const std::string& head = "") {
    std::string obj = head;
    for (int i = 0; i < columns; ++i) obj += "v " + std::to_string(i) + " 0 0\nv " + std::to_string(i) + " 1 0\n";
    for (int i = 1; i < columns; ++i)
        obj += "f " + std::to_string(2 * i - 1) + " " + std::to_string(2 * i + 1) + " " + std::to_string(2 * i) + "\n";
    return obj;
}

// The SceneError loading `scene` in `folder` gives: "location: detail", or "" when it loads.
std::string error_of(const TempFolder& folder, const Json& scene, const LoadOptions& options = {}) {
    try {
        load_in(folder, scene, options);
    } catch (const SceneError& error) {
        return error.location() + ": " + error.detail();
    }
    return "";
}

TEST(MeshLoader, OneObjectIsPlacedAsScaleThenPosition) {
    TempFolder folder;
    folder.write("square.obj", kSquareObj);
    const Scene scene = load_in(folder, with_obj({{"type", "obj"}, {"filename", "square.obj"}, {"position", {2, 0, 8}},
                                                  {"scale", {2, 3, 4}}}));
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.triangles.size(), 2u);  // the quad, fanned
    EXPECT_EQ(scene.meshes[0].triangle_count, 2u);
    // Corner 3 of the file, (1, 1, 0): (2, 3, 0) scaled, then moved by (2, 0, 8).
    EXPECT_EQ(scene.triangles[0].corners[2], (Vec3{4, 3, 8}));
    EXPECT_EQ(scene.triangles[1].corners[2], (Vec3{2, 3, 8}));  // corner 4, (0, 1, 0)
    EXPECT_EQ(scene.meshes[0].ambient, (Vec3{0.8, 0.8, 0.8})) << "no ambient and no material: 0.8 grey";
    EXPECT_FALSE(scene.meshes[0].is_mirror);
}

TEST(MeshLoader, NormalsAreDividedByTheScaleAndMadeUnit) {
    TempFolder folder;
    folder.write("square.obj", kSquareObj);
    const Scene scene = load_in(folder, with_obj({{"filename", "square.obj"}, {"scale", {2, 1, 0.5}}}));
    ASSERT_EQ(scene.triangles.size(), 2u);
    ASSERT_GE(scene.triangles[0].normals, 0);
    // (1, 0, 1) / (2, 1, 0.5) = (0.5, 0, 2), made unit.
    const Vec3 n = scene.corner_normals[scene.triangles[0].normals][0];
    const double size = std::sqrt(0.25 + 4);
    EXPECT_NEAR(n.x, 0.5 / size, 1e-15);
    EXPECT_NEAR(n.y, 0, 1e-15);
    EXPECT_NEAR(n.z, 2 / size, 1e-15);
}

TEST(MeshLoader, AListOfMeshesAUniformScaleAndTheirOwnColours) {
    TempFolder folder;
    folder.write("square.obj", kSquareObj);
    folder.write("red.mtl", "newmtl red\nKd 0.9 0.1 0.2\n");
    folder.write("red.obj", "mtllib red.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Scene scene = load_in(folder, with_obj(Json::array({
                                            {{"filename", "square.obj"}, {"scale", 3}, {"ambient", {0, 1, 0}}, {"IsMirror", 1}},
                                            {{"filename", "red.obj"}},
                                        })));
    ASSERT_EQ(scene.meshes.size(), 2u);
    ASSERT_EQ(scene.triangles.size(), 3u);
    EXPECT_EQ(scene.triangles[0].corners[2], (Vec3{3, 3, 0}));
    EXPECT_EQ(scene.meshes[0].ambient, (Vec3{0, 1, 0}));
    EXPECT_TRUE(scene.meshes[0].is_mirror);
    EXPECT_EQ(scene.meshes[1].ambient, (Vec3{0.9, 0.1, 0.2})) << "the material's Kd";
    EXPECT_EQ(scene.meshes[1].first_triangle, 2u);
    EXPECT_EQ(scene.triangles[2].mesh, 1u);
    EXPECT_EQ(scene.triangles[2].normals, -1) << "no vn: the geometric normal";
}

TEST(MeshLoader, TrianglesWithoutAreaAreLeftOut) {
    TempFolder folder;
    folder.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\nf 1 1 4\n");
    const Scene scene = load_in(folder, with_obj({{"filename", "flat.obj"}}));
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].corners[2], (Vec3{0, 1, 0}));
}

// A mesh that would draw nothing is refused as a file without faces is: its faces all have
// repeated or collinear corners in the file, or collapse once placed far from its origin.
TEST(MeshLoader, AMeshWhoseFacesAllHaveZeroAreaIsRefused) {
    TempFolder folder;
    folder.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\nf 3 2 1 1\n");
    const std::string error = error_of(folder, with_obj({{"filename", "flat.obj"}}));
    EXPECT_EQ(error.rfind("/obj/filename: cannot read OBJ '", 0), 0u) << error;
    EXPECT_NE(error.find("flat.obj': all its faces have zero area"), std::string::npos) << error;
    LoadOptions options;
    options.placeholder_images = true;
    const Scene scene = load_in(folder, with_obj({{"filename", "flat.obj"}}), options);
    EXPECT_TRUE(scene.meshes.at(0).placeholder);
    EXPECT_EQ(scene.triangles.size(), 12u);
    // A triangle of 1e-10 sides has an area in the file, and none at 1e10 from the origin.
    folder.write("tiny.obj", "v 0 0 0\nv 1e-10 0 0\nv 0 1e-10 0\nf 1 2 3\n");
    EXPECT_EQ(load_in(folder, with_obj({{"filename", "tiny.obj"}})).triangles.size(), 1u);
    const std::string placed = error_of(folder, with_obj({{"filename", "tiny.obj"}, {"position", {1e10, 1e10, 0}}}));
    EXPECT_EQ(placed, "/obj/filename: mesh 'tiny.obj': all its faces have zero area once scaled and placed (repeated or "
                      "collinear corners): it draws nothing") << placed;
    // Corners 1e-160 apart are not collinear: the square of their distance underflows double,
    // and the message says the edge is below the lengths clrender renders.
    folder.write("tinier.obj", "v 0 0 0\nv 1e-160 0 0\nv 0 1e-160 0\nf 1 2 3\n");
    const std::string tinier = error_of(folder, with_obj({{"filename", "tinier.obj"}}));
    EXPECT_NE(tinier.find("tinier.obj': all its faces have zero area (its longest edge is 1.414213562373095e-160 long, "
                          "outside the range clrender renders exactly enough: lengths must be from 1e-15 to 1e16): it "
                          "draws nothing"),
              std::string::npos)
        << tinier;
}

// A triangle placed smaller than the length range (its longest edge below 1e-15) is left out
// as one without area is: the kernels' hit weights, cubes of lengths, underflow float for
// such a triangle seen from as near, and it vanished from their image while the reference drew
// it. A mesh of only such triangles is refused; an edge of exactly 1e-15 is kept.
TEST(MeshLoader, TrianglesPlacedBelowTheLengthRangeAreLeftOut) {
    TempFolder folder;
    // A cube of side 2e-9, placed with the smallest scale: sides of 2e-24, in documented ranges.
    folder.write("cube.obj",
                 "v -1e-9 -1e-9 -1e-9\nv 1e-9 -1e-9 -1e-9\nv 1e-9 1e-9 -1e-9\nv -1e-9 1e-9 -1e-9\n"
                 "v -1e-9 -1e-9 1e-9\nv 1e-9 -1e-9 1e-9\nv 1e-9 1e-9 1e-9\nv -1e-9 1e-9 1e-9\n"
                 "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 5 1 4 8\n");
    EXPECT_EQ(load_in(folder, with_obj({{"filename", "cube.obj"}})).triangles.size(), 12u) << "2e-9 is in range";
    const std::string placed = error_of(folder, with_obj({{"filename", "cube.obj"}, {"scale", 1e-15}}));
    EXPECT_EQ(placed, "/obj/filename: mesh 'cube.obj': all its faces are too small once scaled and placed "
                      "(its longest edge is 2.8284271247461903e-24 long, outside the range clrender renders "
                      "exactly enough: lengths must be from 1e-15 to 1e16): it draws nothing")
        << placed;
    // Beside a triangle of the unit square, one of edges 1e-16 is left out, one whose longest edge
    // is 1e-15 is kept.
    folder.write("mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2e-16 0 0\nv 1e-16 1e-16 0\nv 1e-15 0 0\n"
                              "v 5e-16 5e-16 0\nf 1 2 3\nf 1 4 5\nf 1 6 7\n");
    const Scene scene = load_in(folder, with_obj({{"filename", "mixed.obj"}}));
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_EQ(scene.triangles[0].corners[1], (Vec3{1, 0, 0}));
    EXPECT_EQ(scene.triangles[1].corners[1], (Vec3{1e-15, 0, 0}));
    EXPECT_EQ(scene.meshes.at(0).triangle_count, 2u);
}

// Placed vertices are doubles, 1/8 apart near 9e14: a triangle 0.01 across placed there loses its
// area, which is a warning naming the spacing, not a silent change of the model. A sliver 1e-16
// wide that loses its area 1000 from the origin changed nothing visible: no warning.
TEST(MeshLoader, TrianglesThatPlacingMovesBeyondAThousandthOfTheirSizeAreAWarning) {
    TempFolder folder;
    folder.write("two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.01 0 0\nv 0 0.01 0\nf 1 2 3\nf 1 4 5\n");
    const Scene near = load_in(folder, with_obj({{"filename", "two.obj"}}));
    EXPECT_EQ(near.triangles.size(), 2u);
    EXPECT_EQ(testing::scene_json::all_warnings(near), "");
    const Scene far = load_in(folder, with_obj({{"filename", "two.obj"}, {"position", {9e14, 0, 0}}}));
    EXPECT_EQ(far.triangles.size(), 1u);
    EXPECT_TRUE(testing::scene_json::has_warning(far, "mesh 'two.obj': 1 of its 2 triangles move by more than a "
                                                      "thousandth of their size once placed, where coordinates are "
                                                      "0.125 apart (doubles near 900000000000001), and 1 of them "
                                                      "lose their area"))
        << testing::scene_json::all_warnings(far);
    folder.write("sliver.obj", "v 0 0 0\nv 1 0 0\nv 0.5 1e-16 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    const Scene sliver = load_in(folder, with_obj({{"filename", "sliver.obj"}, {"position", {1000, 1000, 0}}}));
    EXPECT_EQ(sliver.triangles.size(), 1u);
    EXPECT_EQ(testing::scene_json::all_warnings(sliver), "");
}

// The message and exit code of the Error loading `scene` in `folder` with a mesh memory budget
// of `budget` bytes; "" when it loads.
std::pair<std::string, int> memory_error_of(const TempFolder& folder, const Json& scene, std::uint64_t budget) {
    LoadOptions options;
    options.mesh_memory_budget = budget;
    options.placeholder_images = true;  // a mesh too large is no missing file: no cube stands in
    try {
        load_in(folder, scene, options);
    } catch (const Error& error) {
        return {error.what(), error.code()};
    }
    return {"", 0};
}

// A mesh that would take more memory than the scene's meshes may is refused with exit 6 at its
// "filename": before its parse (twice its text, its triangles at kParsedTriangleBytes and its
// vertex lines at kVertexLineBytes), or once the
// scene's triangles at kPlacedTriangleBytes each pass the budget, counted across its meshes.
TEST(MeshLoader, MeshesBeyondTheMemoryBudgetEndTheRunWithExit6) {
    TempFolder folder;
    const std::string text = folder.write("square.obj", kSquareObj);
    const std::uint64_t text_bytes = kSquareObj.size(), parse = 2 * text_bytes + 2 * kParsedTriangleBytes + 7 * kVertexLineBytes;
    const Json two = with_obj(Json::array({{{"filename", "square.obj"}}, {{"filename", "square.obj"}, {"position", {0, 0, 1}}}}));
    EXPECT_EQ(memory_error_of(folder, two, 4 * kPlacedTriangleBytes).first, "") << "four triangles fit";
    const auto [placed, placed_code] = memory_error_of(folder, two, 4 * kPlacedTriangleBytes - 1);
    EXPECT_EQ(placed_code, kExitOutOfMemory);
    EXPECT_NE(placed.find("scene.json: /obj/1/filename: out of memory: mesh 'square.obj' brings the scene's triangles to 4, "
                          "about 0.0 GiB to load and render"),
              std::string::npos)
        << placed;
    ASSERT_LT(parse, 2 * kPlacedTriangleBytes);
    const auto [parsed, parsed_code] = memory_error_of(folder, two, parse - 1);
    EXPECT_EQ(parsed_code, kExitOutOfMemory);
    EXPECT_NE(parsed.find("scene.json: /obj/0/filename: out of memory: OBJ '" + text +
                          "': its 2 triangles and 7 v, vt and vn lines would take about 0.0 GiB to read"),
              std::string::npos)
        << parsed;
    EXPECT_EQ(memory_error_of(folder, with_obj({{"filename", "square.obj"}}), 2 * kPlacedTriangleBytes).first, "");
}

// Memory that runs out all the same while a mesh is read (a limit below the budget, such as
// `ulimit -v`) ends the run with exit 6 and one line at the mesh's "filename", naming the OBJ
// (it said only "out of memory"). Checked in a child whose address space may grow by 8 MiB,
// reading an OBJ of 100k triangles (the parse alone takes about 25 MB). The child is forked
// from a fresh run of this test alone (gtest's "threadsafe" death test runs it again): memory
// that earlier tests of the same run freed, but the allocator kept mapped, would be room
// beyond the bound.
TEST(MeshLoader, MemoryThatRunsOutWhileReadingAMeshIsNamedAtItsFilename) {
#ifdef __SANITIZE_ADDRESS__
    GTEST_SKIP() << "AddressSanitizer's allocator reserves address space of its own";
#endif
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    TempFolder folder;
    std::string text;
    constexpr int kCells = 224;  // 2 * 224^2 = 100,352 triangles
    for (int j = 0; j <= kCells; ++j)
        for (int i = 0; i <= kCells; ++i) text += "v " + std::to_string(i) + " " + std::to_string(j) + " 0\n";
    for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < kCells; ++i) {
            const int a = j * (kCells + 1) + i + 1, b = a + 1, c = a + kCells + 2, d = a + kCells + 1;
            text += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
        }
    const std::string obj = folder.write("grid.obj", text);
    const Json scene = with_obj({{"filename", "grid.obj"}});
    const std::string expected = "scene.json: /obj/filename: out of memory: OBJ '" + obj +
                                 "': reading it took more memory than the system gives";
    const auto named = [&] {  // run where the death test exits, with no destructors: it removes its folder
        const bool passed = testing::passes_in_bounded_child({std::uint64_t(8) << 20}, [&] {
            ::setenv("CLRENDER_CACHE_DIR", "off", 1);  // read, not taken from the mesh cache
            try {
                load_in(folder, scene);
            } catch (const Error& error) {
                return error.code() == kExitOutOfMemory && std::string(error.what()).find(expected) != std::string::npos;
            }
            return false;
        });
        std::filesystem::remove_all(folder.path());
        return passed;
    };
    EXPECT_EXIT(std::_Exit(named() ? 0 : 1), ::testing::ExitedWithCode(0), "")
        << "not ended with \"" << expected << "\"";
}

// The reader's warnings are the scene's, at the mesh's "filename" (so --strict refuses them).
TEST(MeshLoader, AnUndefinedMaterialIsAWarningAtTheFilename) {
    TempFolder folder;
    folder.write("red.mtl", "newmtl red\nKd 1 0 0\n");
    folder.write("blue.obj", "mtllib red.mtl\nusemtl blue\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Scene scene = load_in(folder, with_obj(Json::array({{{"filename", "blue.obj"}}})));
    EXPECT_TRUE(testing::scene_json::has_warning(
        scene, "/obj/0/filename: OBJ '" + folder.file("blue.obj") + "': line 2: usemtl blue: no .mtl file"))
        << testing::scene_json::all_warnings(scene);
    EXPECT_EQ(scene.meshes.at(0).ambient, (Vec3{0.8, 0.8, 0.8}));
}

// The bytes this process has read so far (rchar of /proc/self/io: every read() and pread()).
std::uint64_t bytes_read() {
    std::ifstream io("/proc/self/io");
    std::string key;
    std::uint64_t value = 0;
    while (io >> key >> value)
        if (key == "rchar:") return value;
    return 0;
}

// A scene exported one OBJ file per object names one shared .mtl from each: it is read and
// checked once for the scene, not once for each OBJ file (100 OBJ files naming one 16 MiB
// library took 10 s to load, and each run again: small OBJ files are not in the mesh cache).
TEST(MeshLoader, ADotMtlThatSeveralObjFilesNameIsReadOnce) {
    TempFolder folder;
    std::string library = "newmtl red\nKd 1 0 0\n";
    while (library.size() < (std::size_t(4) << 20)) library += "# a long material library's comment\n";
    folder.write("shared.mtl", library);
    Json objects = Json::array();
    for (int i = 0; i < 20; ++i) {
        const std::string name = "part" + std::to_string(i) + ".obj";
        folder.write(name, "mtllib shared.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        objects.push_back({{"filename", name}, {"position", {i, 0, 0}}});
    }
    const std::uint64_t before = bytes_read();
    const Scene scene = load_in(folder, with_obj(objects));
    const std::uint64_t read = bytes_read() - before;
    ASSERT_EQ(scene.meshes.size(), 20u);
    for (const Mesh& mesh : scene.meshes) {
        EXPECT_EQ(mesh.ambient, (Vec3{1, 0, 0}));
        ASSERT_TRUE(mesh.material_paths);
        EXPECT_EQ(*mesh.material_paths, std::vector<std::string>{folder.file("shared.mtl")});
    }
    EXPECT_GT(read, library.size()) << "/proc/self/io does not count this process's reads";
    EXPECT_LT(read, 2 * library.size()) << "the .mtl was read about " << read / library.size() << " times";
}

// The process's CPU time, in seconds.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// The scene of the OBJ `objects`, and the CPU seconds that loading it took against loading the
// first object alone: what more objects cost, in a ratio that holds on a slow or busy machine.
struct LoadCost {
    Scene scene;
    double one = 0, all = 0;
};

LoadCost load_cost(const TempFolder& folder, const Json& objects) {
    LoadCost cost;
    double start = cpu_seconds();
    load_in(folder, with_obj(Json::array({objects[0]})));
    cost.one = cpu_seconds() - start;
    start = cpu_seconds();
    cost.scene = load_in(folder, with_obj(objects));
    cost.all = cpu_seconds() - start;
    return cost;
}

// A library of many materials, as an exporter writes one beside one OBJ file per object: its
// materials are listed once for the scene, not parsed by tinyobjloader again for each OBJ file
// (LoadMtl of 10,000 materials took 27 ms: 500 OBJ files naming the library loaded in 13.5 s).
TEST(MeshLoader, TheMaterialsOfADotMtlThatManyObjFilesNameAreListedOnce) {
    TempFolder folder;
    std::string library;
    for (int m = 0; m < 10000; ++m) {
        library += "newmtl material_" + std::to_string(m) + "\nNs 250\nKa 1 1 1\nKd " + std::to_string(m % 8 / 8.0) +
                   " 0.5 0.25\nKs 0.5 0.5 0.5\nNi 1.45\nd 1\nillum 2\n";
    }
    folder.write("library.mtl", library);
    Json objects = Json::array();
    for (int i = 0; i < 200; ++i) {
        const std::string name = "part" + std::to_string(i) + ".obj";
        folder.write(name, "mtllib library.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl material_" + std::to_string(i) +
                               "\nf 1 2 3\n");
        objects.push_back({{"filename", name}, {"position", {i, 0, 0}}});
    }
    const auto [scene, one, all] = load_cost(folder, objects);
    ASSERT_EQ(scene.meshes.size(), 200u);
    // Within a rounding: tinyobjloader's own reading of "0.375000" is a unit off.
    for (int i = 0; i < 200; ++i) EXPECT_NEAR(scene.meshes[i].ambient.x, i % 8 / 8.0, 1e-12) << i;
    EXPECT_LT(all, 10 * one + 0.5) << "one OBJ file: " << one << " s";
}

// "models/../m.obj" is the file the system opens: through a symbolic link `models`, the
// folder above the link's target; without a folder `models`, none. The same for `mtllib`.
TEST(MeshLoader, DotDotIsResolvedByTheSystemNotOnTheText) {
    TempFolder folder;
    fs::create_directories(folder.file("elsewhere/models"));
    fs::create_directory_symlink(folder.file("elsewhere/models"), folder.file("models"));
    folder.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");  // what the text would name
    folder.write("elsewhere/m.obj", "mtllib models/../c.mtl\nusemtl c\n" + kSquareObj);  // what the system opens
    folder.write("c.mtl", "newmtl c\nKd 1 0 0\n");
    folder.write("elsewhere/c.mtl", "newmtl c\nKd 0 0 1\n");
    const Scene scene = load_in(folder, with_obj({{"filename", "models/../m.obj"}}));
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.triangles.size(), 2u) << "the square of elsewhere/m.obj";
    EXPECT_EQ(scene.meshes[0].ambient, (Vec3{0, 0, 1})) << "elsewhere/c.mtl";
    EXPECT_EQ(scene.meshes[0].path, folder.file("models/../m.obj"));
    const std::string missing = error_of(folder, with_obj({{"filename", "nowhere/../m.obj"}}));
    EXPECT_NE(missing.find("cannot read OBJ '" + folder.file("nowhere/../m.obj") + "'"), std::string::npos) << missing;
}

TEST(MeshLoader, AMissingFileIsTheScenesErrorAtItsFilename) {
    TempFolder folder;
    const std::string error = error_of(folder, with_obj({{"filename", "gone.obj"}}));
    EXPECT_NE(error.find("/obj/filename: cannot read OBJ '"), std::string::npos) << error;
    EXPECT_NE(error.find("gone.obj"), std::string::npos) << error;
    const std::string listed = error_of(folder, with_obj(Json::array({{{"filename", "gone.obj"}}})));
    EXPECT_EQ(listed.rfind("/obj/0/filename: ", 0), 0u) << listed;
}

TEST(MeshLoader, ABadLineIsNamedWithTheScenesLocation) {
    TempFolder folder;
    folder.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    const std::string error = error_of(folder, with_obj({{"filename", "bad.obj"}}));
    EXPECT_NE(error.find("/obj/filename: cannot read OBJ"), std::string::npos) << error;
    EXPECT_NE(error.find("line 4"), std::string::npos) << error;
}

TEST(MeshLoader, PlaceholdersStandACubeInForAMissingFile) {
    TempFolder folder;
    LoadOptions options;
    options.placeholder_images = true;
    const Scene scene = load_in(folder, with_obj({{"filename", "gone.obj"}, {"position", {0, 0, -3}}, {"scale", 2}}),
                                options);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_TRUE(scene.meshes[0].placeholder);
    ASSERT_EQ(scene.triangles.size(), 12u);
    for (const Triangle& triangle : scene.triangles)
        for (const Vec3& corner : triangle.corners) {
            EXPECT_EQ(std::fabs(corner.x), 1.0);
            EXPECT_EQ(std::fabs(corner.z + 3), 1.0);
        }
    EXPECT_TRUE(testing::scene_json::has_warning(scene, "placeholder cube")) << testing::scene_json::all_warnings(scene);
}

// The files a placeholder stands in for are still the run's inputs (no output may replace
// them): the OBJ, and the .mtl files it names as far as they were read.
TEST(MeshLoader, PlaceholdersKeepTheFilesTheyStandInForAsInputs) {
    TempFolder folder;
    folder.write("bad.obj", "mtllib a.mtl\nmtllib b.mtl\nusemtl r\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    folder.write("a.mtl", "newmtl r\nKd 1 0 0\n");
    folder.write("b.mtl", "newmtl r\nKd 1 0 0 0.5\n");
    LoadOptions options;
    options.placeholder_images = true;
    const Scene scene = load_in(folder, with_obj(Json::array({{{"filename", "bad.obj"}}, {{"filename", "gone.obj"}}})),
                                options);
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_TRUE(scene.meshes[0].placeholder);
    EXPECT_EQ(scene.meshes[0].path, folder.file("bad.obj"));
    ASSERT_TRUE(scene.meshes[0].material_paths && scene.meshes[1].material_paths);
    EXPECT_EQ(*scene.meshes[0].material_paths, (std::vector<std::string>{folder.file("a.mtl"), folder.file("b.mtl")}));
    EXPECT_TRUE(scene.meshes[1].placeholder);
    EXPECT_EQ(scene.meshes[1].path, folder.file("gone.obj"));
    EXPECT_TRUE(scene.meshes[1].material_paths->empty());
}

// Whatever makes a model unusable, with --placeholders the .mtl files it names (on lines before
// or after the failing one) and the textures they name stay inputs no output may replace: the
// line checks, and the faces checked once read, failed before the list of its .mtl files was
// kept, and `-o wood.png` replaced the model's texture.
TEST(MeshLoader, PlaceholdersKeepTheMtlFilesAndTexturesOfAModelThatFailsAnyCheck) {
    const std::string triangle = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\n";
    std::string corners;
    for (int i = 0; i < 256; ++i) corners += " " + std::to_string(i % 3 + 1);
    const std::vector<std::string> broken = {
        triangle + "f 1 2 9\n",                          // a corner out of range
        "v nan 0 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n",    // a position that is no number
        triangle + "f" + corners + "\n",                  // more corners than a face may have
        triangle,                                         // no faces
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n",       // faces without area
    };
    for (const std::string& body : broken) {
        TempFolder folder;
        folder.write("lib.mtl", "newmtl red\nKd 1 0 0\nmap_Kd wood.png\n");
        folder.write("late.mtl", "newmtl blue\nKd 0 0 1\nbump late.png\n");
        folder.write("model.obj", "mtllib lib.mtl\n" + body + "mtllib late.mtl\n");
        LoadOptions options;
        options.placeholder_images = true;
        const Scene scene = load_in(folder, with_obj({{"filename", "model.obj"}}), options);
        ASSERT_EQ(scene.meshes.size(), 1u) << body;
        EXPECT_TRUE(scene.meshes[0].placeholder) << body;
        ASSERT_TRUE(scene.meshes[0].material_paths) << body;
        EXPECT_EQ(*scene.meshes[0].material_paths,
                  (std::vector<std::string>{folder.file("lib.mtl"), folder.file("late.mtl")}))
            << body;
        EXPECT_EQ(scene.mesh_texture_paths, (std::vector<std::string>{folder.file("wood.png"), folder.file("late.png")}))
            << body;
        for (const char* input : {"model.obj", "lib.mtl", "wood.png", "late.mtl", "late.png"}) {
            OutputRoles roles;
            add_scene_inputs(scene, roles);
            EXPECT_THROW(roles.add_output("image", folder.file(input)), OutputError) << input << " of " << body;
        }
    }
}

// The .mtl files of a model that fails are listed each file once, however many names reach it:
// the list held the first 1,024 names, so an OBJ naming one .mtl 1,024 ways before victim.mtl
// left victim.mtl out, and `-o victim.mtl` with --placeholders replaced it.
TEST(MeshLoader, PlaceholdersKeepEveryMtlFileHoweverManyNamesComeBefore) {
    TempFolder folder;
    folder.write("a.mtl", "newmtl red\nKd 1 0 0\n");
    folder.write("victim.mtl", "newmtl blue\nKd 0 0 1\nmap_Kd victim.png\n");
    std::string names;
    for (int i = 0; i < 1024; ++i) names += " ." + std::string(i + 1, '/') + "a.mtl";
    folder.write("bad.obj", "mtllib" + names + " victim.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    LoadOptions options;
    options.placeholder_images = true;
    const Scene scene = load_in(folder, with_obj({{"filename", "bad.obj"}}), options);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_TRUE(scene.meshes[0].placeholder);
    ASSERT_TRUE(scene.meshes[0].material_paths);
    EXPECT_EQ(*scene.meshes[0].material_paths,
              (std::vector<std::string>{folder.file("a.mtl"), folder.file("victim.mtl")}));
    for (const char* input : {"a.mtl", "victim.mtl", "victim.png"}) {
        OutputRoles roles;
        add_scene_inputs(scene, roles);
        EXPECT_THROW(roles.add_output("image", folder.file(input)), OutputError) << input;
    }
}

// Where the files a failing model names cannot all be kept as inputs (more .mtl files than an OBJ
// may read, textures of materials past an OBJ's limit), no placeholder stands in for it: the run
// stops rather than go on with a file of the model that an output may replace.
TEST(MeshLoader, NoPlaceholderStandsInForAModelWhoseFilesCannotAllBeKept) {
    LoadOptions options;
    options.placeholder_images = true;
    const std::string bad_face = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n";
    {
        TempFolder folder;
        std::string names;
        for (std::uint64_t i = 0; i <= kMaxMtlFiles; ++i) names += " m" + std::to_string(i) + ".mtl";
        folder.write("many.obj", bad_face + "mtllib" + names + "\n");
        EXPECT_EQ(error_of(folder, with_obj({{"filename", "many.obj"}}), options),
                  "/obj/filename: cannot read OBJ '" + folder.file("many.obj") +
                      "': line 4: corner 3: position index 4 is out of range: the file has 3; no placeholder can "
                      "stand in for it: it names more than 1024 .mtl files (line 5), more than a run keeps as inputs "
                      "that no output may replace");
        // 1,024 files are all kept, and the cube stands in.
        folder.write("most.obj", bad_face + "mtllib" + names.substr(0, names.rfind(' ')) + "\n");
        const Scene scene = load_in(folder, with_obj({{"filename", "most.obj"}}), options);
        ASSERT_TRUE(scene.meshes.at(0).material_paths);
        EXPECT_EQ(scene.meshes[0].material_paths->size(), kMaxMtlFiles);
        EXPECT_EQ(scene.meshes[0].material_paths->back(), folder.file("m1023.mtl"));
    }
    {
        TempFolder folder;
        std::string library;
        for (std::uint64_t m = 0; m <= kMaxObjMaterials; ++m) library += "newmtl m" + std::to_string(m) + "\n";
        folder.write("lib.mtl", library + "map_Kd late.png\n");
        folder.write("model.obj", "mtllib lib.mtl\n" + bad_face);
        const std::string error = error_of(folder, with_obj({{"filename", "model.obj"}}), options);
        EXPECT_NE(error.find("; no placeholder can stand in for it: its .mtl '" + folder.file("lib.mtl") +
                             "' names textures past its first 10000 materials, more than a run keeps"),
                  std::string::npos)
            << error;
    }
}

// The image files a model's .mtl names as textures are never read, but they are the model's:
// exported as table.obj, table.mtl and table.png beside a scene table.json, the default output
// table.png replaced the texture. Each file a material keeps (the last statement of each kind,
// as tinyobjloader reads it, past its options) is an input no output may replace, relative to
// the .mtl's folder, listed once for the scene however many OBJ files and names reach the .mtl.
TEST(MeshLoader, TheTexturesItsMtlNamesAreInputsNoOutputMayReplace) {
    TempFolder folder;
    fs::create_directories(folder.file("model/tex"));
    const std::string elsewhere = folder.file("spec.png");
    const std::string faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    folder.write("model/table.obj", "mtllib table.mtl\nusemtl wood\n" + faces);
    folder.write("model/chair.obj", "mtllib ./table.mtl tex/../table.mtl\nusemtl metal\n" + faces);
    folder.write("model/table.mtl", "newmtl wood\nKd 0.6 0.4 0.2\nmap_Kd old.png\nmap_Kd -s 1 1 1 -clamp on table.png\n"
                                    "bump tex/bump.png\t\nnewmtl metal\nKd 0.5 0.5 0.5\nmap_Ks " +
                                        elsewhere + "\nnorm tex/bump.png\nmap_Kd\n");
    const Scene scene = load_in(folder, with_obj(Json::array({{{"filename", "model/table.obj"}},
                                                              {{"filename", "model/chair.obj"}},
                                                              {{"filename", "model/table.obj"}, {"position", {2, 0, 0}}}})));
    ASSERT_EQ(scene.meshes.size(), 3u);
    EXPECT_EQ(scene.mesh_texture_paths,
              (std::vector<std::string>{folder.file("model/table.png"), folder.file("model/tex/bump.png"), elsewhere}));
    for (const char* texture : {"model/table.png", "model/tex/bump.png", "spec.png"}) {
        OutputRoles roles;
        add_scene_inputs(scene, roles);
        EXPECT_THROW(roles.add_output("image", folder.file(texture)), OutputError) << texture << " is an input";
    }
}

// A texture named two ways ("wood.png", "./wood.png") is one file, listed once.
TEST(MeshLoader, ATextureNamedTwoWaysIsListedOnce) {
    TempFolder folder;
    folder.write("m.mtl", "newmtl a\nKd 1 0 0\nmap_Kd wood.png\nnewmtl b\nKd 0 1 0\nmap_Kd ./wood.png\n"
                          "bump .//wood.png\n");
    folder.write("m.obj", "mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Scene scene = load_in(folder, with_obj({{"filename", "m.obj"}}));
    EXPECT_EQ(scene.mesh_texture_paths, (std::vector<std::string>{folder.file("wood.png")}));
}

// With --placeholders a model whose .mtl cannot be used becomes a cube and the run goes on:
// table.json beside table.obj, a table.mtl with a bad colour line naming map_Kd table.png, and
// the default output table.png replaced the texture.
TEST(MeshLoader, TheTexturesOfAnMtlThatCannotBeUsedAreStillInputs) {
    TempFolder folder;
    const std::string faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    folder.write("table.obj", "mtllib table.mtl\nusemtl wood\n" + faces);
    folder.write("table.mtl", "newmtl wood\nKd 1 0 0 0.5\nmap_Kd table.png\n");
    folder.write("latin1.obj", "mtllib latin1.mtl\nusemtl wood\n" + faces);
    folder.write("latin1.mtl", "newmtl wood\nmap_Kd caf\xe9.png\nKd 1 nan 0\nbump bump.png\n");
    LoadOptions options;
    options.placeholder_images = true;
    const Scene scene =
        load_in(folder, with_obj(Json::array({{{"filename", "table.obj"}}, {{"filename", "latin1.obj"}}})), options);
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_TRUE(scene.meshes[0].placeholder);
    EXPECT_TRUE(scene.meshes[1].placeholder);
    EXPECT_EQ(scene.mesh_texture_paths, (std::vector<std::string>{folder.file("table.png"), folder.file("caf\xe9.png"),
                                                                   folder.file("bump.png")}));
    OutputRoles roles;
    add_scene_inputs(scene, roles);
    EXPECT_THROW(roles.add_output("image", folder.file("table.png")), OutputError);
}

// The textures of a file of more materials than an OBJ may have: those of its first
// kMaxObjMaterials materials, no more (a bounded list for a refused file).
TEST(MeshLoader, TheTexturesOfMaterialsPastTheLimitAreNotListed) {
    std::string text;
    for (std::uint64_t m = 0; m <= kMaxObjMaterials; ++m)
        text += "newmtl m" + std::to_string(m) + "\nmap_Kd t" + std::to_string(m) + ".png\n";
    bool cut = false;
    const std::vector<std::string> files = mtl_texture_files(text, &cut);
    ASSERT_EQ(files.size(), kMaxObjMaterials);
    EXPECT_EQ(files.back(), "t" + std::to_string(kMaxObjMaterials - 1) + ".png");
    EXPECT_TRUE(cut);
    cut = false;
    mtl_texture_files("newmtl a\nmap_Kd a.png\n", &cut);
    EXPECT_FALSE(cut);
}

// A placement that even the cube cannot take says why the cube is there: the file's problem.
TEST(MeshLoader, APlaceholderOutOfRangeNamesTheFilesProblem) {
    TempFolder folder;
    LoadOptions options;
    options.placeholder_images = true;
    const std::string error =
        error_of(folder, with_obj({{"filename", "gone.obj"}, {"scale", 1e15}, {"position", {1e15, 0, 0}}}), options);
    EXPECT_EQ(error.rfind("/obj/filename: the placeholder cube for mesh 'gone.obj' (cannot read OBJ '", 0), 0u) << error;
    EXPECT_NE(error.find("gone.obj': no such file"), std::string::npos) << error;
    EXPECT_NE(error.find("): vertex 2 lies at "), std::string::npos) << error;
}

TEST(MeshLoader, BadSettingsAreRefusedWhereTheyAreWritten) {
    TempFolder folder;
    folder.write("square.obj", kSquareObj);
    const auto fails = [&](const Json& obj, const std::string& expected) {
        const std::string error = error_of(folder, with_obj(obj));
        EXPECT_EQ(error.rfind(expected, 0), 0u) << error;
    };
    fails({{"filename", "square.obj"}, {"scale", 0}}, "/obj/scale: scale must be a non-zero factor on every axis, of "
                                                     "magnitude from 1e-15 to 1e16 (got 0)");
    fails({{"filename", "square.obj"}, {"scale", "2"}}, "/obj/scale: scale must be a number or [sx, sy, sz], got \"2\"");
    fails({{"filename", "square.obj"}, {"scale", {1, -1e-300, 1}}}, "/obj/scale: scale must be a non-zero factor");
    fails({{"filename", "square.obj"}, {"scale", {1, 2}}}, "/obj/scale: ");
    fails({{"filename", "square.obj"}, {"position", {0, 1e300, 0}}}, "/obj/position/1: ");
    fails({{"filename", ""}}, "/obj/filename: filename must not be empty");
    fails({{"type", "sphere"}, {"filename", "square.obj"}}, "/obj/type: type must be \"obj\"");
    fails({{"position", {0, 0, 0}}}, "/obj: ");
    fails({{"filename", "square.obj"}, {"IsMirror", 2}}, "/obj/IsMirror: ");
    // Within the range on its own, but out of it once scaled.
    fails({{"filename", "square.obj"}, {"scale", 1e16}}, "/obj/filename: mesh 'square.obj': vertex 2 lies at 1e16");
}

TEST(MeshLoader, AFolderOrAFifoIsNoMesh) {
    TempFolder folder;
    folder.write("sub/x", "");
    EXPECT_NE(error_of(folder, with_obj({{"filename", "sub"}})).find("cannot read OBJ"), std::string::npos);
}

// Any text parses as an OBJ of unknown statements: a file without a face is refused, not
// drawn as nothing.
TEST(MeshLoader, AFileWithoutFacesIsNoMesh) {
    TempFolder folder;
    folder.write("passwd.obj", "root:x:0:0:root:/root:/bin/bash\n");
    folder.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    const char binary[] = "\x7f" "ELF\x02\x01\x01\0\0\0\xff\xfe";
    folder.write("binary.obj", std::string(binary, sizeof binary - 1));
    for (const char* name : {"passwd.obj", "points.obj", "binary.obj"}) {
        const std::string error = error_of(folder, with_obj({{"filename", name}}));
        EXPECT_NE(error.find("/obj/filename: cannot read OBJ"), std::string::npos) << name << ": " << error;
        EXPECT_NE(error.find("it has no faces"), std::string::npos) << name << ": " << error;
    }
}

// One model placed many times (a forest of one tree) is one file: read once, not once a copy.
TEST(MeshLoader, AFilePlacedManyTimesIsReadOnce) {
    TempFolder folder;
    const std::string obj = strip_obj(2000);
    folder.write("strip.obj", obj);
    Json copies = Json::array();
    for (int i = 0; i < 40; ++i) copies.push_back({{"filename", "strip.obj"}, {"position", {0, 0, -i}}});
    copies.push_back({{"filename", "./strip.obj"}, {"position", {0, 5, 0}}});  // the same file, named otherwise
    const std::string scene_file = folder.write("scene.json", with_obj(copies).dump());
    LoadOptions options;
    const std::uint64_t before = bytes_read();
    const Scene scene = load_scene(scene_file, options);
    const std::uint64_t read = bytes_read() - before;
    if (before == 0) GTEST_SKIP() << "no /proc/self/io here";
    ASSERT_EQ(scene.meshes.size(), 41u);
    for (const Mesh& mesh : scene.meshes) EXPECT_EQ(mesh.triangle_count, 1999u);
    EXPECT_EQ(scene.triangles[1999].corners[0], (scene.triangles[0].corners[0] + Vec3{0, 0, -1})) << "the second copy";
    EXPECT_EQ(scene.triangles[40 * 1999].corners[2], (scene.triangles[0].corners[2] + Vec3{0, 5, 0})) << "the last";
    EXPECT_LT(read, 3 * obj.size()) << "strip.obj (" << obj.size() << " bytes) read more than once";
}

// One file named several ways ("strip.obj", "d/../strip.obj", a link beside it) is one model,
// read once: each spelling read it again (20 spellings of a 100 MB OBJ took 20 reads). A link
// from another folder reads its .mtl from that folder, as the system resolves its name, so it
// is another model with that folder's colour.
TEST(MeshLoader, AFileNamedSeveralWaysIsReadOnce) {
    TempFolder folder;
    const std::string obj = strip_obj(2000, "mtllib m.mtl\nusemtl c\n");
    folder.write("strip.obj", obj);
    folder.write("m.mtl", "newmtl c\nKd 1 0 0\n");
    fs::create_directory(folder.file("d"));
    folder.write("d/m.mtl", "newmtl c\nKd 0 0 1\n");
    fs::create_symlink("strip.obj", folder.file("link.obj"));
    fs::create_symlink("../strip.obj", folder.file("d/link.obj"));
    Json copies = Json::array();
    std::string spelt = "strip.obj";
    for (int i = 0; i < 12; ++i, spelt = "d/../" + spelt)
        copies.push_back({{"filename", spelt}, {"position", {0, 0, -i}}});
    copies.push_back({{"filename", "link.obj"}, {"position", {0, 5, 0}}});
    copies.push_back({{"filename", "d/link.obj"}, {"position", {0, 9, 0}}});  // its .mtl: d/m.mtl
    const std::string scene_file = folder.write("scene.json", with_obj(copies).dump());
    const std::uint64_t before = bytes_read();
    const Scene scene = load_scene(scene_file, LoadOptions{});
    const std::uint64_t read = bytes_read() - before;
    if (before == 0) GTEST_SKIP() << "no /proc/self/io here";
    ASSERT_EQ(scene.meshes.size(), 14u);
    for (std::size_t m = 0; m < 14; ++m) {
        EXPECT_EQ(scene.meshes[m].triangle_count, 1999u) << m;
        EXPECT_EQ(scene.meshes[m].ambient, m < 13 ? (Vec3{1, 0, 0}) : (Vec3{0, 0, 1})) << m;
    }
    EXPECT_EQ(scene.meshes[12].path, folder.file("link.obj")) << "each placement keeps its own name";
    EXPECT_EQ(scene.triangles[12 * 1999].corners[2], (scene.triangles[0].corners[2] + Vec3{0, 5, 0})) << "the link";
    EXPECT_EQ(scene.triangles[13 * 1999].corners[2], (scene.triangles[0].corners[2] + Vec3{0, 9, 0})) << "d/link";
    EXPECT_LT(read, 3 * obj.size()) << "strip.obj (" << obj.size() << " bytes) read about " << read / obj.size()
                                    << " times";
}

// An `mtllib` line may name one .mtl thousands of ways (`./a.mtl`, `d/../a.mtl`, ...): the
// placements of the file share one list of its names, not a copy each (131,072 names placed 300
// times took 4.4 GB, and the output check 88 s to look at every name of every copy), and the
// names stay inputs that no output may replace.
TEST(MeshLoader, PlacementsOfAFileShareItsListOfMtlNames) {
    TempFolder folder;
    fs::create_directory(folder.file("d"));
    folder.write("a.mtl", "newmtl c\nKd 1 0 0\n");
    std::string line = "mtllib";
    for (int n = 0; n < 2048; ++n) {
        line += ' ';
        for (int bit = 0; bit < 11; ++bit) line += ((n >> bit) & 1) ? "d/../" : "./";
        line += "a.mtl";
    }
    folder.write("t.obj", line + "\nusemtl c\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Json copies = Json::array();
    for (int i = 0; i < 100; ++i) copies.push_back({{"filename", "t.obj"}, {"position", {0, 0, -i}}});
    const Scene scene = load_in(folder, with_obj(copies));
    ASSERT_EQ(scene.meshes.size(), 100u);
    ASSERT_TRUE(scene.meshes[0].material_paths);
    EXPECT_EQ(scene.meshes[0].material_paths->size(), 2048u);
    for (const Mesh& mesh : scene.meshes) {
        EXPECT_EQ(mesh.ambient, (Vec3{1, 0, 0}));
        EXPECT_EQ(mesh.material_paths.get(), scene.meshes[0].material_paths.get()) << "a copy of the list";
    }
    OutputRoles roles;
    add_scene_inputs(scene, roles);
    EXPECT_THROW(roles.add_output("image", folder.file("d/../a.mtl")), OutputError) << "the .mtl is an input";
}

// With placeholders, a file that cannot be read is read once for all its placements, as one that
// loads is: 40 placements of a broken 50 MB OBJ read it 40 times. Each placement is still a
// placeholder with the file's problem (here its .mtl's), and the .mtl stays an input of each.
TEST(MeshLoader, ABrokenFilePlacedManyTimesIsReadOnce) {
    TempFolder folder;
    const std::string obj = strip_obj(4000, "mtllib a.mtl\nusemtl c\n");
    folder.write("bad.obj", obj);
    folder.write("a.mtl", "newmtl c\nKd 1 0\n");  // a colour of two numbers: the OBJ cannot be read
    Json copies = Json::array();
    for (int i = 0; i < 20; ++i) copies.push_back({{"filename", "bad.obj"}, {"position", {0, 0, -i}}});
    LoadOptions options;
    options.placeholder_images = true;
    const std::string scene_file = folder.write("scene.json", with_obj(copies).dump());
    const std::uint64_t before = bytes_read();
    const Scene scene = load_scene(scene_file, options);
    const std::uint64_t read = bytes_read() - before;
    if (before == 0) GTEST_SKIP() << "no /proc/self/io here";
    ASSERT_EQ(scene.meshes.size(), 20u);
    for (const Mesh& mesh : scene.meshes) {
        EXPECT_TRUE(mesh.placeholder);
        ASSERT_TRUE(mesh.material_paths);
        EXPECT_EQ(*mesh.material_paths, std::vector<std::string>{folder.file("a.mtl")});
    }
    const std::string warnings = testing::scene_json::all_warnings(scene);
    std::size_t placeholders = 0;
    for (std::size_t at = warnings.find("'Kd' needs 3 numbers"); at != std::string::npos;
         at = warnings.find("'Kd' needs 3 numbers", at + 1))
        ++placeholders;
    EXPECT_EQ(placeholders, 20u) << warnings;
    EXPECT_LT(read, 3 * obj.size()) << "bad.obj (" << obj.size() << " bytes) read about " << read / obj.size()
                                    << " times";
}

// A file of many positions that no face uses (a point cloud or a scan with one face) costs its
// placements what its faces use: each placement scaled, placed and checked every position of the
// file (400 placements of a million such positions and one face took 6 s, one 0.6 s), which the
// scene's triangle limit does not bound. A position no face uses is not placed, so it is not
// refused out of range either; one a face uses is still named by its number in the file.
TEST(MeshLoader, APositionNoFaceUsesIsNotPlaced) {
    TempFolder folder;
    std::string cloud = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    for (int i = 0; i < 1000000; ++i) cloud += "v 0.5 0.25 0.125\n";
    folder.write("cloud.obj", cloud);
    Json copies = Json::array();
    for (int i = 0; i < 400; ++i) copies.push_back({{"filename", "cloud.obj"}, {"position", {0, 0, -i}}});
    const auto [scene, one, all] = load_cost(folder, copies);
    ASSERT_EQ(scene.triangles.size(), 400u);
    EXPECT_EQ(scene.triangles[399].corners[1], (Vec3{1, 0, -399}));
    EXPECT_LT(all, 2 * one + 0.2) << "placed once: " << one << " s";

    // Position 1 lies beyond the range once scaled, and no face uses it; position 4 does too, and
    // face 2 uses it.
    folder.write("far.obj", "v 1e14 0 0\nv 0 0 0\nv 1 0 0\nv 0 1e14 0\nf 2 3 4\nv 0 1 0\nf 2 3 5\n");
    const Json far = {{"filename", "far.obj"}, {"scale", 100}};
    const std::string error = error_of(folder, with_obj(far));
    EXPECT_EQ(error.rfind("/obj/filename: mesh 'far.obj': vertex 4 lies at 1e16 once scaled and placed", 0), 0u)
        << error;
    folder.write("far.obj", "v 1e14 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n");
    const Scene placed = load_in(folder, with_obj(far));
    ASSERT_EQ(placed.triangles.size(), 1u);
    EXPECT_EQ(placed.triangles[0].corners[2], (Vec3{0, 100, 0}));
}

TEST(MeshLoader, MeshesChangeTheScenesDigest) {
    TempFolder folder;
    folder.write("square.obj", kSquareObj);
    const Json scene = with_obj({{"filename", "square.obj"}});
    const std::string before = load_in(folder, scene).digest;
    folder.write("square.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");  // the normals gone
    const std::string after = load_in(folder, scene).digest;
    EXPECT_FALSE(before.empty());
    EXPECT_NE(before, after);
}

TEST(MeshLoader, ObjIsNoLongerAnIgnoredKey) {
    TempFolder folder;
    folder.write("square.obj", kSquareObj);
    const Scene scene = load_in(folder, with_obj({{"filename", "square.obj"}}));
    EXPECT_EQ(testing::scene_json::all_warnings(scene), "");
}

}  // namespace
}  // namespace clr
