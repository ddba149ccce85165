// The catalogue of bad input: every way a user (or a hostile file) can hand clrender something
// wrong, each run through the real binary as a user would run it. For every case clrender
// must exit with the documented code (1 usage, 2 scene or input, 3 device, 4 output), print
// exactly one error naming the file, the JSON location where one applies and the problem,
// and leave nothing behind: no image, no video, no temporary file.
//
// Adding a case: append it to catalogue() with the files it needs, the arguments and what
// the error must say. docs/robustness.md lists the cases by kind.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/command.h"
#include "support/shell.h"
#include "support/png_header.h"
#include "support/temp_folder.h"
#include "support/tile_files.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

struct File {
    std::string name;
    std::string bytes;
};

struct BadInput {
    std::string name;                    // the test's name: what is wrong
    std::vector<File> files;             // written into a fresh folder, where clrender runs
    std::vector<std::string> folders;    // made there too (paths that must be folders)
    std::string arguments;               // clrender's command line
    int exit_code;                       // 1 usage, 2 scene or input, 3 device, 4 output
    std::vector<std::string> fragments;  // each must appear in the error message
    std::string environment = "";        // "NAME=value" before the command
    // Errors found by the command-line parser (CLI11) add the hint
    // "Run with --help for more information." after the error line.
    bool parser_error = false;
    // Makes what `files` cannot hold (FIFOs, sparse files) in the folder, before clrender runs.
    std::function<void(const std::string& folder)> prepare = nullptr;
};

// ---------------------------------------------------------------------------------------
// Scene text. Every case starts from a small valid scene and breaks one thing.

const std::string kCamera = R"("eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60)";
const std::string kSize = R"("width": 8, "height": 6)";
const std::string kSquare = R"("UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0], "UpperRight": [1, 1, 0])";

// A valid scene with `extra` members added. A key given twice takes its last value (with a
// warning), so `extra` can also replace one of the camera's or the size's members.
std::string scene_with(const std::string& extra) {
    return "{" + kCamera + ", " + kSize + (extra.empty() ? "" : ", " + extra) + "}";
}

// A scene showing the OBJ mesh `filename`, with `settings` added to its object.
// A scene of the fall 2019 format whose one surface is `surface`.
std::string surfaces_scene(const std::string& surface) { return scene_with(R"("surfaces": [)" + surface + "]"); }

// `count` point lights, as the members of a `lights` array.
std::string many_lights(int count) {
    std::string lights;
    for (int i = 0; i < count; ++i) lights += std::string(i ? ", " : "") + R"({"position": [0, 9, 0], "color": [1, 1, 1]})";
    return lights;
}

// `count` planes, as the members of a `surfaces` array.
std::string many_planes(int count) {
    std::string planes;
    for (int i = 0; i < count; ++i)
        planes += std::string(i ? ", " : "") + R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "ambient": [1, 1, 1]})";
    return planes;
}

std::string mesh_scene(const std::string& filename, const std::string& settings = "") {
    return scene_with(R"("obj": {"filename": ")" + filename + "\"" + settings + "}");
}

// A scene without the top-level key `missing`, the others as in scene_with("").
std::string scene_without(const std::string& missing) {
    const std::vector<std::pair<std::string, std::string>> members = {
        {"eye", "[0, 0, 6]"}, {"lookat", "[0, 0, 0]"}, {"up", "[0, 1, 0]"},
        {"fov_angle", "60"},  {"width", "8"},          {"height", "6"},
    };
    std::string text = "{";
    for (const auto& [key, value] : members) {
        if (key == missing) continue;
        text += (text.size() > 1 ? ", \"" : "\"") + key + "\": " + value;
    }
    return text + "}";
}

// A scene with the camera given by its members (eye or eyeLocations, lookat or
// lookatLocations, up, fov_angle), written out in full.
std::string camera_scene(const std::string& eye, const std::string& lookat, const std::string& up = "\"up\": [0, 1, 0]",
                         const std::string& fov = "\"fov_angle\": 60") {
    return "{" + eye + ", " + lookat + ", " + up + ", " + fov + ", " + kSize + "}";
}

// A scene with one sphere: centre and colour given, then `members`.
std::string sphere_scene(const std::string& members) {
    return scene_with(R"("spheres": [{"center": [0, 0, 0], "ambient": [1, 0, 0], )" + members + "}]");
}

// A scene with one billboard: its corners and an `extra` member.
std::string billboard_scene(const std::string& corners, const std::string& extra = R"("ambient": [0, 1, 0])") {
    return scene_with("\"billboards\": [{" + corners + ", " + extra + "}]");
}

std::string image_scene(const std::string& filename) { return billboard_scene(kSquare, "\"filename\": \"" + filename + "\""); }

// A two-key camera path, which renders to a video by default.
std::string animation_scene() {
    return camera_scene(R"("eyeLocations": [[0, 0, 6], [1, 0, 6]])", R"("lookat": [0, 0, 0])");
}

std::string repeated(const std::string& text, int count) {
    std::string out;
    out.reserve(text.size() * count);
    for (int i = 0; i < count; ++i) out += text;
    return out;
}

// Bytes that are neither text nor any image format, the same on every run.
std::string binary_garbage(std::size_t size) {
    std::string bytes;
    unsigned state = 12345;
    for (std::size_t i = 0; i < size; ++i) {
        state = state * 1103515245u + 12345u;
        bytes += static_cast<char>((state >> 16) & 0xFF);
    }
    bytes[0] = '\x01';  // not '{', 'P', 0x89 or 0xFF: no format starts this way
    return bytes;
}

std::string source_file(const std::string& relative) {
    return read_bytes(fs::path(CLRENDER_SOURCE_DIR) / relative);
}

// The JPEG that fuzz/image_fuzzer.cpp found to overflow stb_image's Huffman tables (clrender's
// JPEG decoder then), cut to
// what matters: a start-of-image marker and one DHT segment whose table declares 16 x 255
// codes. See tests/scene/fuzz_regressions_test.cpp for the whole finding.
std::string jpeg_with_oversized_huffman_table() {
    return std::string("\xFF\xD8\xFF\xC4\x01\x13\x00", 7) + std::string(16, '\xFF') + std::string(256, '\x01');
}

// The start of a JPEG whose frame header claims 20000 x 20000 pixels, 400 million: a few
// bytes that would cost gigabytes to decode.
std::string jpeg_claiming_20000_squared() {
    return std::string("\xFF\xD8\xFF\xC0\x00\x11\x08\x4E\x20\x4E\x20\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01", 21);
}

// A lossless JPEG's frame header (SOF3, 16 x 16, 3 components) and its end: valid JPEG of a
// kind clrender does not decode.
std::string lossless_jpeg_frame() {
    return std::string("\xFF\xD8\xFF\xC3\x00\x11\x08\x00\x10\x00\x10\x03\x01\x11\x00\x02\x11\x00\x03\x11\x00\xFF\xD9", 23);
}

// The commonest kind of case: `clrender bad.json` with bad.json holding `text` (and `files`
// beside it) must fail as a scene error whose message holds `fragments`.
BadInput bad_scene(std::string name, std::string text, std::vector<std::string> fragments, std::vector<File> files = {}) {
    files.insert(files.begin(), File{"bad.json", std::move(text)});
    return {std::move(name), std::move(files), {}, "bad.json", 2, std::move(fragments)};
}

// A case for a bad billboard image named `name` holding `bytes`, whose message names the
// image and says `problem`.
BadInput bad_image(std::string case_name, const std::string& name, std::string bytes, const std::string& problem) {
    return bad_scene(std::move(case_name), image_scene(name),
                     {"bad.json: /billboards/0/filename: cannot read image", name + "': " + problem},
                     {{name, std::move(bytes)}});
}

// --- Input limits: helpers for the cases of files that must be refused before reading them.

// A folder preparation that makes a FIFO (named pipe) `name`, which no process writes to.
std::function<void(const std::string&)> make_fifo(const std::string& name) {
    return [name](const std::string& folder) { ::mkfifo((folder + "/" + name).c_str(), 0600); };
}

// A folder preparation that makes `name` a sparse file of `bytes` starting with `start`.
std::function<void(const std::string&)> make_sparse(const std::string& name, const std::string& start, std::uint64_t bytes) {
    return [=](const std::string& folder) {
        const fs::path path = fs::path(folder) / name;
        std::ofstream(path, std::ios::binary) << start;
        fs::resize_file(path, bytes);
    };
}

std::string as_utf16le(const std::string& ascii) {
    std::string wide = "\xFF\xFE";
    for (char c : ascii) wide += {c, '\0'};
    return wide;
}

// A camera path of `keys` positions at `per_segment` frames a segment.
std::string long_animation_scene(int keys, int per_segment) {
    std::string eyes;
    for (int i = 0; i < keys; ++i) eyes += (i ? ", [0, 0, " : "[0, 0, ") + std::to_string(6 + i) + "]";
    return "{\"eyeLocations\": [" + eyes + "], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0], \"fov_angle\": 60, " + kSize +
           ", \"clrender\": {\"frames_per_segment\": " + std::to_string(per_segment) + "}}";
}

// The kernel sources with `broken` (a path under kernels/) ending in `appended`: by default
// a line that is not C.
std::vector<File> kernels_with_broken(const std::string& broken, const std::string& appended = "\nthis is not C;\n") {
    std::vector<File> files = {{"scene.json", "{" + kCamera + ", " + kSize + "}"}};
    const fs::path root = fs::path(CLRENDER_SOURCE_DIR) / "kernels";
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file()) continue;
        const std::string relative = fs::relative(entry.path(), root).string();
        files.push_back({"kd/" + relative, read_bytes(entry.path()) + (relative == broken ? appended : "")});
    }
    return files;
}

// Folders that kernels_with_broken()'s files need.
std::vector<std::string> kernel_folders() {
    std::vector<std::string> folders = {"kd"};
    const fs::path root = fs::path(CLRENDER_SOURCE_DIR) / "kernels";
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (entry.is_directory()) folders.push_back("kd/" + fs::relative(entry.path(), root).string());
    }
    return folders;
}

// ---------------------------------------------------------------------------------------

std::vector<BadInput> catalogue() {
    const std::string png = source_file("scenes/demo/checker.png");
    const std::string ppm = source_file("scenes/demo/sign.ppm");
    const std::string overflowing = scene_with(R"("SunLocation": [0, 1e999, 0])");
    const std::string nesting = repeated("[", 100000) + repeated("]", 100000);
    const std::string at_origin = R"("eye": [0, 0, 6])", look_at_origin = R"("lookat": [0, 0, 0])";
    const std::string png_deep_and_huge = testing::png_header_only(8192, 8192, 16);
    return {
        // --- The file as JSON
        bad_scene("SyntaxErrorGivesLineAndColumn", "{\n  \"eye\": [0, 0, 1],\n  \"lookat\": [0, 0, 0]\n  \"up\": [0, 1, 0]\n}",
                  {"bad.json: line 4, column 6:", "syntax error", "unexpected string literal; expected '}'"}),
        bad_scene("TrailingCommaIsExplained", "{\"eye\": [0, 0, 1],\n}",
                  {"bad.json: line 2, column 1:", "JSON allows no comma before '}' or ']'"}),
        bad_scene("EmptyFile", "", {"bad.json: the file is empty"}),
        bad_scene("OnlyWhitespaceAndByteOrderMark", "\xEF\xBB\xBF \r\n\t\n", {"bad.json: the file is empty"}),
        bad_scene("NotAnObject", "[1, 2, 3]", {"bad.json: scene must be a JSON object { ... }, got an array of 3 values"}),
        bad_scene("BinaryGarbageSceneFile", binary_garbage(300), {"bad.json: line 1, column 1:", "syntax error"}),
        bad_scene("UnclosedObjectAtEndOfFile", "{\"eye\": [0, 0, 1]",
                  {"bad.json: line 1, column 18:", "unexpected end of input"}),
        bad_scene("NanIsNotJson", scene_with(R"("MaxDepth": NaN)"), {"bad.json: line 1, column", "syntax error"}),
        bad_scene("NumberOverflowingToInfinity", overflowing,
                  {"bad.json: line 1, column " + std::to_string(overflowing.find("1e999") + 1) + ":",
                   "number 1e999 is too large (numbers must be finite)"}),
        // 100000 nested arrays: the parser must not recurse once per level (a stack overflow).
        bad_scene("DeepNestingAsTheScene", nesting, {"bad.json: scene must be a JSON object"}),
        bad_scene("DeepNestingInAValue", "{\"eye\": " + nesting + "}",
                  {"bad.json: /eye: eye must be an array [x, y, z] of 3 numbers, got an array of 1 value"}),
        bad_scene("DeepNestingNeverClosed", repeated("[", 100000),
                  {"bad.json: line 1, column 100001:", "unexpected end of input"}),

        // --- Missing required keys
        bad_scene("MissingEye", scene_without("eye"), {"bad.json: scene needs 'eye' (a camera position) or 'eyeLocations'"}),
        bad_scene("MissingLookat", scene_without("lookat"), {"bad.json: scene needs 'lookat'"}),
        bad_scene("MissingUp", scene_without("up"), {"bad.json: scene is missing required key 'up'"}),
        bad_scene("MissingFovAngle", scene_without("fov_angle"), {"bad.json: scene is missing required key 'fov_angle'"}),
        bad_scene("MissingWidth", scene_without("width"), {"bad.json: scene is missing required key 'width'", "--size WxH"}),
        bad_scene("MissingHeight", scene_without("height"), {"bad.json: scene is missing required key 'height'"}),
        bad_scene("MissingSphereRadius", sphere_scene(R"("IsMirror": 0)"),
                  {"bad.json: /spheres/0: sphere is missing required key 'radius'"}),

        // --- Wrong types and values
        bad_scene("RadiusAsString", sphere_scene(R"("radius": "2")"),
                  {"bad.json: /spheres/0/radius: radius must be a number, got \"2\""}),
        bad_scene("VectorOfTwoNumbers", scene_with(R"("SunLocation": [1, 2])"),
                  {"bad.json: /SunLocation:", "3 numbers, got an array of 2 values"}),
        bad_scene("ColourComponentNotANumber", scene_with(R"("DefaultColor": [0, null, 0])"),
                  {"bad.json: /DefaultColor/1:", "must be a number, got null"}),
        bad_scene("WidthAsString", scene_with(R"("width": "600")"),
                  {"bad.json: /width: width must be a number, got \"600\""}),
        bad_scene("SpheresNotAnArray", scene_with(R"("spheres": {"center": [0, 0, 0]})"),
                  {"bad.json: /spheres: spheres must be an array"}),
        bad_scene("FlagOtherThanZeroOrOne", scene_with(R"("OnlyAmbient": 2)"),
                  {"bad.json: /OnlyAmbient: OnlyAmbient must be 0, 1, false or true (got 2)"}),
        bad_scene("NegativeRadius", sphere_scene(R"("radius": -1)"),
                  {"bad.json: /spheres/0/radius: radius must be > 0 (got -1)"}),
        bad_scene("ZeroRadius", sphere_scene(R"("radius": 0)"), {"bad.json: /spheres/0/radius: radius must be > 0 (got 0)"}),
        bad_scene("MaxDepthTooLarge", scene_with(R"("MaxDepth": 65)"),
                  {"bad.json: /MaxDepth: MaxDepth must be a whole number from 0 to 64 (got 65)"}),
        bad_scene("WrongObjectType", sphere_scene(R"("type": "cube", "radius": 1)"),
                  {"bad.json: /spheres/0/type: type must be \"sphere\" here, got \"cube\""}),

        // --- Degenerate geometry and camera
        bad_scene("BillboardCollinearCorners",
                  billboard_scene(R"("UpperLeft": [0, 0, 0], "LowerLeft": [1, 1, 1], "UpperRight": [2, 2, 2])"),
                  {"bad.json: /billboards/0: billboard has no area:", "collinear"}),
        bad_scene("BillboardCoincidentCorners",
                  billboard_scene(R"("UpperLeft": [1, 2, 3], "LowerLeft": [0, 0, 0], "UpperRight": [1, 2, 3])"),
                  {"bad.json: /billboards/0: billboard has no area: UpperRight is the same point as UpperLeft"}),
        bad_scene("BillboardWithoutImageOrColour", billboard_scene(kSquare, R"("IsMirror": 0)"),
                  {"bad.json: /billboards/0: billboard needs 'filename' (an image) or 'ambient'"}),
        bad_scene("UpParallelToTheView", camera_scene(at_origin, look_at_origin, R"("up": [0, 0, -2])"),
                  {"bad.json: /up: up [0, 0, -2] is parallel to the view direction"}),
        bad_scene("ZeroUp", camera_scene(at_origin, look_at_origin, R"("up": [0, 0, 0])"),
                  {"bad.json: /up: up must not be the zero vector"}),
        bad_scene("EyeEqualsLookat", camera_scene(R"("eye": [1, 2, 3])", R"("lookat": [1, 2, 3])"),
                  {"bad.json: /eye: eye and lookat are the same point [1, 2, 3]"}),
        bad_scene("EyeEqualsLookatOnAPath", camera_scene(R"("eyeLocations": [[0, 0, 6], [0, 0, 0]])", look_at_origin),
                  {"bad.json: /eyeLocations/1: eye and lookat are the same point", "at camera key 1"}),
        bad_scene("FovZero", camera_scene(at_origin, look_at_origin, R"("up": [0, 1, 0])", R"("fov_angle": 0)"),
                  {"bad.json: /fov_angle: fov_angle must be between 0 and 180 degrees, both excluded (got 0)"}),
        bad_scene("Fov180", camera_scene(at_origin, look_at_origin, R"("up": [0, 1, 0])", R"("fov_angle": 180)"),
                  {"bad.json: /fov_angle:", "(got 180)"}),
        bad_scene("MismatchedEyeAndLookatLocations",
                  camera_scene(R"("eyeLocations": [[0, 0, 6], [1, 0, 6]])",
                               R"("lookatLocations": [[0, 0, 0], [0, 0, 1], [0, 0, 2]])"),
                  {"bad.json: /lookatLocations: lookatLocations has 3 entries but eyeLocations has 2 entries"}),
        bad_scene("EyeAndEyeLocationsBoth", scene_with(R"("eyeLocations": [[0, 0, 6]])"),
                  {"bad.json: /eyeLocations: give either 'eye' or 'eyeLocations', not both"}),

        // --- Resolution
        bad_scene("ZeroWidth", scene_with(R"("width": 0)"),
                  {"bad.json: /width: width must be a whole number from 1 to 16384 (got 0)"}),
        bad_scene("NegativeHeight", scene_with(R"("height": -5)"),
                  {"bad.json: /height: height must be a whole number from 1 to 16384 (got -5)"}),
        bad_scene("FractionalWidth", scene_with(R"("width": 600.5)"), {"bad.json: /width:", "(got 600.5)"}),
        bad_scene("AbsurdResolutionInTheScene", scene_with(R"("width": 100000, "height": 100000)"),
                  {"bad.json: /width: width must be a whole number from 1 to 16384 (got 100000)"}),
        bad_scene("ResolutionOverThePixelLimit", scene_with(R"("width": 16384, "height": 16384)"),
                  {"bad.json: /height: the image has 16384 x 16384 = 268435456 pixels, more than the limit of 67108864"}),
        {"AbsurdResolutionOnTheCommandLine", {{"scene.json", scene_with("")}}, {}, "scene.json --size 100000x100000", 2,
         {"scene.json: image width 100000 given on the command line must be from 1 to 16384"}},

        // --- Images
        bad_scene("MissingImage", image_scene("nowhere.png"),
                  {"bad.json: /billboards/0/filename: cannot read image", "nowhere.png': no such file"}),
        bad_image("GarbageBytesNamedPng", "garbage.png", binary_garbage(200), "unsupported image format"),
        bad_image("TruncatedPng", "cut.png", png.substr(0, png.size() / 2), "corrupt PNG"),
        bad_image("TruncatedPpm", "cut.ppm", ppm.substr(0, ppm.size() / 2), "truncated PPM data"),
        bad_image("EmptyImageFile", "empty.png", "", "empty file"),
        bad_image("JpegWithOversizedHuffmanTable", "photo.jpg", jpeg_with_oversized_huffman_table(),
                  "corrupt JPEG: Bogus Huffman table definition"),
        bad_image("ImageDimensionsOverTheLimit", "huge.jpg", jpeg_claiming_20000_squared(),
                  "JPEG image of 20000 x 20000 pixels is larger than the limit"),
        {"ImagePathIsAFolder", {{"bad.json", image_scene("textures")}}, {"textures"}, "bad.json", 2,
         {"bad.json: /billboards/0/filename:", "textures': not a file"}},
        bad_scene("EmptyImageFileName", image_scene(""), {"bad.json: /billboards/0/filename: filename must not be empty"}),

        // --- OBJ meshes: the same errors as images, with the file's line
        bad_scene("MissingObj", mesh_scene("nowhere.obj"),
                  {"bad.json: /obj/filename: cannot read OBJ", "nowhere.obj': no such file"}),
        {"ObjIndexOutOfRange", {{"bad.json", mesh_scene("m.obj")}, {"m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"}}, {},
         "bad.json", 2, {"bad.json: /obj/filename: cannot read OBJ", "line 4: corner 3: position index 4 is out of range"}},
        {"ObjNotANumber", {{"bad.json", mesh_scene("m.obj")}, {"m.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"}}, {},
         "bad.json", 2, {"bad.json: /obj/filename: cannot read OBJ", "line 2:", "not a finite number"}},
        {"ObjWithoutFaces", {{"bad.json", mesh_scene("m.obj")}, {"m.obj", binary_garbage(300)}}, {}, "bad.json", 2,
         {"bad.json: /obj/filename: cannot read OBJ", "it has no faces"}},
        {"ObjFacesWithoutArea", {{"bad.json", mesh_scene("m.obj")}, {"m.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"}},
         {}, "bad.json", 2, {"bad.json: /obj/filename: cannot read OBJ", "all its faces have zero area"}},
        {"ObjPathIsAFolder", {{"bad.json", mesh_scene("models")}}, {"models"}, "bad.json", 2,
         {"bad.json: /obj/filename: cannot read OBJ"}},
        bad_scene("ObjScaleZero", mesh_scene("m.obj", R"(, "scale": 0)"), {"bad.json: /obj/scale: scale must be a non-zero factor"}),

        // --- the fall 2019 format: surfaces and lights
        bad_scene("SurfaceOfAnUnknownType", surfaces_scene(R"({"type": "cone", "ambient": [1, 0, 0]})"),
                  {"bad.json: /surfaces/0/type: surface type must be \"sphere\", \"plane\", \"triangle\" or \"mesh\" (got \"cone\")"}),
        bad_scene("SurfaceWithoutAmbient", surfaces_scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})"),
                  {"bad.json: /surfaces/0: surface is missing required key 'ambient'"}),
        bad_scene("PlaneWithAZeroNormal",
                  surfaces_scene(R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0], "ambient": [1, 1, 1]})"),
                  {"bad.json: /surfaces/0/normal: normal must be a non-zero direction"}),
        bad_scene("NegativePhongExponent",
                  surfaces_scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0], "phong_exponent": -2})"),
                  {"bad.json: /surfaces/0/phong_exponent: phong_exponent must be from 0 to 1e6, got -2"}),
        bad_scene("SpecularColourNearFloatOverflow",
                  surfaces_scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0], "specular": [1e30, 0, 0]})"),
                  {"bad.json: /surfaces/0/specular: each channel must be from -1e6 to 1e6, got 1e30"}),
        bad_scene("LightsAndASun", scene_with(R"("SunLocation": [0, 9, 0], "lights": [{"position": [0, 9, 0], "color": [1, 1, 1]}])"),
                  {"bad.json: /lights: 'lights' (point lights with Blinn-Phong materials) and 'SunLocation' are two lighting models"}),
        bad_scene("LightWithoutColour", scene_with(R"("lights": [{"position": [0, 9, 0]}])"),
                  {"bad.json: /lights/0: light is missing required key 'color'"}),
        bad_scene("NegativeNear", scene_with(R"("near": -1, "far": 20)"), {"bad.json: /near: near must be from 0 to 1e16, got -1"}),
        bad_scene("FarNotBeyondNear", scene_with(R"("near": 30, "far": 20)"),
                  {"bad.json: /far: far must be greater than near (30) and at most 1e16, got 20"}),
        bad_scene("TooManyPlanes", scene_with(R"("surfaces": [)" + many_planes(257) + "]"),
                  {"bad.json: /surfaces/256: a scene may have at most 256 planes"}),
        bad_scene("TooManyLights", scene_with(R"("lights": [)" + many_lights(257) + "]"),
                  {"bad.json: /lights: a scene may have at most 256 lights, this one has 257"}),
        bad_image("PngDimensionsOverTheLimit", "huge.png", testing::png_header_only(100000, 100000, 8),
                  "PNG image of 100000 x 100000 pixels is larger than the limit of 67108864 pixels"),
        bad_image("LosslessJpegIsNamed", "lossless.jpg", lossless_jpeg_frame(),
                  "unsupported JPEG: lossless JPEG (SOF3) is not supported"),
        bad_image("PpmCommentAfterMaxvalRunningToTheEnd", "c.ppm", "P6 1 1 255#comment",
                  "truncated PPM data: the comment after maxval runs to the end of the file"),

        // --- Impostors (clrender extension)
        bad_scene("ImpostorViewImageMissing",
                  scene_with(R"("clrender": {"view_sets": {"pine": [{"filename": "pine_0.png", "direction": [0, 0, 1]}]},
                                "impostors": [{"center": [0, 1, 0], "width": 1, "height": 2, "views": "pine"}]})"),
                  {"bad.json: /clrender/view_sets/pine/0/filename: cannot read image", "pine_0.png': no such file"}),
        bad_scene("ImpostorNamesAnUnknownViewSet",
                  scene_with(R"("clrender": {"impostors": [{"center": [0, 1, 0], "width": 1, "height": 2, "views": "oak"}]})"),
                  {"bad.json: /clrender/impostors/0/views: no view set named \"oak\""}),
        bad_scene("ImpostorViewDirectionZero",
                  scene_with(R"("clrender": {"impostors": [{"center": [0, 1, 0], "width": 1, "height": 2,
                                "views": [{"filename": "a.png", "direction": [0, 0, 0]}]}]})"),
                  {"bad.json: /clrender/impostors/0/views/0/direction: direction must not be the zero vector"}),
        bad_scene("ImpostorWithoutWidth",
                  scene_with(R"("clrender": {"impostors": [{"center": [0, 1, 0], "height": 2, "ambient": [1, 0, 0]}]})"),
                  {"bad.json: /clrender/impostors/0: impostor is missing required key 'width'"}),

        // --- The scene path
        {"ScenePathIsAFolder", {}, {"scene.json"}, "scene.json", 2, {"scene.json: cannot read scene file: it is a folder"}},
        {"MissingSceneFile", {}, {}, "nowhere.json", 2, {"nowhere.json: cannot read scene file: no such file"}},

        // --- Device
        {"UnknownDevice", {{"scene.json", scene_with("")}}, {}, "scene.json -d no-such-device", 3,
         {"unknown OpenCL device 'no-such-device'"}},
        {"UnknownDeviceFromTheEnvironment", {{"scene.json", scene_with("")}}, {}, "scene.json", 3,
         {"unknown OpenCL device '42'"}, "CLRENDER_DEVICE=42"},

        // --- Outputs
        {"OutputUnderAFile", {{"scene.json", scene_with("")}}, {}, "scene.json -o scene.json/out.png -q", 4,
         {"scene.json/out.png: cannot create a file in its folder: Not a directory"}},
        {"OutputIsAFolder", {{"scene.json", scene_with("")}}, {"out.png"}, "scene.json -o out.png -q", 4,
         {"out.png: is a folder; clrender writes outputs only to regular files"}},
        {"UnsupportedOutputExtension", {{"scene.json", scene_with("")}}, {}, "scene.json -o out.bmp", 1,
         {"out.bmp: unsupported extension '.bmp' for an image (supported: .png, .ppm, .exr)"}},
        {"UnsupportedVideoExtension", {{"path.json", animation_scene()}}, {}, "path.json --video out.avi", 1,
         {"'out.avi': unsupported video format; use a .mp4 or .gif file name"}},
        {"MissingFfmpegForAVideo", {{"path.json", animation_scene()}}, {}, "path.json --video out.mp4 -q", 4,
         {"video encoder '/nonexistent/ffmpeg' (from CLRENDER_FFMPEG) not found or not executable"},
         "CLRENDER_FFMPEG=/nonexistent/ffmpeg"},
        {"VideoOfAStill", {{"scene.json", scene_with("")}}, {}, "scene.json --video out.mp4", 1,
         {"scene.json is a still (one camera key)"}},

        // --- The command line itself
        {"NoSceneArgument", {}, {}, "", 1, {"a scene file is required"}, "", true},
        {"UnknownOption", {{"scene.json", scene_with("")}}, {}, "scene.json --no-such-option", 1, {"--no-such-option"}, "",
         true},
        {"MalformedSize", {{"scene.json", scene_with("")}}, {}, "scene.json --size 12by3", 1,
         {"--size: expected WIDTHxHEIGHT", "'12by3'"}, "", true},

        // --- Output safety: no output replaces an input or another output, or a non-file
        {"StatsReplacesTheScene", {{"scene.json", scene_with("")}}, {}, "scene.json -o out.png --stats scene.json -q", 4,
         {"scene.json: the --stats report would replace the scene file 'scene.json'"}},
        {"OutputReplacesATexture", {{"bad.json", image_scene("tex.png")}, {"tex.png", source_file("scenes/demo/checker.png")}},
         {}, "bad.json -o tex.png -q", 4, {"tex.png: the image (-o) would replace the texture"}},
        {"DefaultOutputReplacesATexture",
         {{"tex.json", image_scene("tex.png")}, {"tex.png", source_file("scenes/demo/checker.png")}}, {}, "tex.json -q", 4,
         {"tex.png: the image (the default output name) would replace the texture"}},
        {"StatsReplacesTheImage", {{"scene.json", scene_with("")}}, {}, "scene.json -o out.png --stats out.png -q", 4,
         {"out.png: the --stats report would replace the image (-o) 'out.png'"}},
        {"StatsReplacesAFrame", {{"path.json", animation_scene()}}, {}, "path.json -o f_%04d.png --stats f_0001.png -q", 4,
         {"f_0001.png: the --stats report would replace the frame 1 (-o)"}},
        {"StatsIsAFolder", {{"scene.json", scene_with("")}}, {"report"}, "scene.json -o out.png --stats report -q", 4,
         {"report: is a folder"}},
        // --- Numeric ranges: finite numbers beyond what the float kernels render right
        // (docs/scene-format.md, Numeric ranges). Each message names the value and the range.
        bad_scene("CoordinateNear1e38", sphere_scene(R"("radius": 1, "center": [0, 1e38, 0])"),
                  {"bad.json: /spheres/0/center/1: center[1] is 1e38, outside the range clrender renders exactly "
                   "enough: every coordinate must be from -1e15 to 1e15"}),
        bad_scene("EyeCoordinateJustOutside", camera_scene(R"("eye": [0, 0, 1.000001e15])", look_at_origin),
                  {"bad.json: /eye/2: eye[2] is 1.000001e15, outside the range", "from -1e15 to 1e15"}),
        bad_scene("SunFarBeyondTheRange", scene_with(R"("SunLocation": [-1e20, 5, 5])"),
                  {"bad.json: /SunLocation/0: SunLocation[0] is -1e20, outside the range", "from -1e15 to 1e15"}),
        bad_scene("SphereOfRadius1e300", sphere_scene(R"("radius": 1e300)"),
                  {"bad.json: /spheres/0/radius: radius 1e300 is outside the range clrender renders exactly enough: "
                   "lengths must be from 1e-15 to 1e16"}),
        bad_scene("SphereRadiusJustAboveTheRange", sphere_scene(R"("radius": 1.001e16)"),
                  {"bad.json: /spheres/0/radius: radius 1.001e16 is outside", "from 1e-15 to 1e16"}),
        bad_scene("SphereOfRadius1eMinus38", sphere_scene(R"("radius": 1e-38)"),
                  {"bad.json: /spheres/0/radius: radius 1e-38 is outside", "from 1e-15 to 1e16"}),
        bad_scene("SphereRadiusJustBelowTheRange", sphere_scene(R"("radius": 9.99e-16)"),
                  {"bad.json: /spheres/0/radius: radius 9.99e-16 is outside", "from 1e-15 to 1e16"}),
        bad_scene("BillboardEdgeOf1eMinus200",
                  billboard_scene(R"("UpperLeft": [0, 0, 0], "LowerLeft": [0, -1, 0], "UpperRight": [1e-200, 0, 0])"),
                  {"bad.json: /billboards/0: billboard edge from UpperLeft to UpperRight is 1e-200 long, outside the "
                   "range clrender renders exactly enough: lengths must be from 1e-15 to 1e16"}),
        bad_scene("BillboardCornerBeyondTheRange",
                  billboard_scene(R"("UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0], "UpperRight": [1e300, 1, 0])"),
                  {"bad.json: /billboards/0/UpperRight/0: UpperRight[0] is 1e300, outside the range"}),
        bad_scene("ImpostorWidthBelowTheRange",
                  scene_with(R"("clrender": {"impostors": [{"center": [0, 1, 0], "width": 1e-20, "height": 2, "ambient": [1, 0, 0]}]})"),
                  {"bad.json: /clrender/impostors/0/width: width 1e-20 is outside", "from 1e-15 to 1e16"}),
        // --- The video encoder (fake encoders chosen through CLRENDER_FFMPEG)
        {"EncoderFailing", {{"path.json", animation_scene()}}, {}, "path.json --video out.mp4 -q", 4,
         {"out.mp4: video encoding failed: ", "false' exited with status 1"}, "CLRENDER_FFMPEG=false"},
        {"EncoderExitingZeroWithoutAVideo", {{"path.json", animation_scene()}}, {}, "path.json --video out.mp4 -q", 4,
         {"out.mp4: video encoding failed: "}, "CLRENDER_FFMPEG=true"},
        {"EncoderTimeoutNotANumber", {{"path.json", animation_scene()}}, {}, "path.json --video out.mp4 -q", 1,
         {"CLRENDER_ENCODER_TIMEOUT must be a number of seconds above 0 and at most 86400 (got 'soon')"},
         "CLRENDER_ENCODER_TIMEOUT=soon"},
        {"MissingFfprobeForAVideo", {{"path.json", animation_scene()}}, {}, "path.json --video out.mp4 -q", 4,
         {"video checker '/nonexistent/ffprobe' (from CLRENDER_FFPROBE) not found or not executable"},
         "CLRENDER_FFPROBE=/nonexistent/ffprobe"},
        // --- Input limits: files refused before they are read, sizes and counts checked,
        // encodings and names that would be misread, empty option values
        {"SceneIsAFifo", {}, {}, "scene.json", 2, {"scene.json: cannot read scene file: it is a FIFO (named pipe)"}, "",
         false, make_fifo("scene.json")},
        {"SceneIsADevice", {}, {}, "/dev/zero", 2,
         {"/dev/zero: cannot read scene file: it is a character device, not a regular file"}},
        {"SparseHugeScene", {}, {}, "scene.json", 2,
         {"scene.json: cannot read scene file: the file is 5 GiB, more than the limit of 64 MiB"}, "", false,
         make_sparse("scene.json", "{", std::uint64_t(5) << 30)},
        {"SparseHugeImage", {{"bad.json", image_scene("huge.png")}}, {}, "bad.json", 2,
         {"bad.json: /billboards/0/filename: cannot read image", "huge.png': the file is 3 GiB, more than the limit of 1 GiB"},
         "", false, make_sparse("huge.png", "\x89PNG", std::uint64_t(3) << 30)},
        bad_scene("Utf16Scene", as_utf16le(scene_with("")),
                  {"bad.json: the file is UTF-16 (little-endian) text; save it as UTF-8"}),
        bad_scene("NulInImageFileName", image_scene("checker.png\\u0000.txt"),
                  {"bad.json: /billboards/0/filename: filename contains a NUL character (\\u0000)"},
                  {{"checker.png", png}}),
        {"DefineNumberOutOfRange", {{"scene.json", scene_with("")}}, {}, "scene.json -D 'eye=[1e400,0,0]'", 1,
         {"-D eye=[1e400,0,0]: /eye/0: column 2: number 1e400 is out of range"}, "", true},
        {"DefineArrayThatIsNotJson", {{"scene.json", scene_with("")}}, {}, "scene.json -D 'eye=[0,0'", 1,
         {"-D eye=[0,0: /eye/2: the value is not valid JSON"}, "", true},
        {"GifFrameRateItsDelaysCannotHold",
         {{"path.json", camera_scene(R"("eyeLocations": [[0, 0, 6], [1, 0, 6]], "clrender": {"fps": 60})",
                                     R"("lookat": [0, 0, 0])")}},
         {}, "path.json --video v.gif", 2, {"path.json: /clrender/fps: fps: --video v.gif: a GIF takes from 0.001526 to 50"}},
        {"AnimationFrameCountOverflow", {{"path.json", long_animation_scene(30000, 100000)}}, {}, "path.json --frame-count",
         2, {"path.json: /clrender/frames_per_segment: the animation would have (30000 keys - 1) x 100000 frames per segment"}},
        bad_scene("DecodedImagesOverTheMemoryLimit",
                  scene_with("\"billboards\": [{" + kSquare + ", \"filename\": \"a.png\"}, {" + kSquare +
                             ", \"filename\": \"b.png\"}, {" + kSquare + ", \"filename\": \"c.png\"}]"),
                  {"bad.json: /billboards/2/filename: image", "c.png' (8192 x 8192, 16-bit) needs 1 GiB to decode",
                   "more than the limit of 2 GiB", "CLRENDER_IMAGE_MEMORY_MIB"},
                  {{"a.png", png_deep_and_huge}, {"b.png", png_deep_and_huge}, {"c.png", png_deep_and_huge}}),
        {"ImageMemoryLimitNotANumber", {{"scene.json", scene_with("")}}, {}, "scene.json", 1,
         {"CLRENDER_IMAGE_MEMORY_MIB='lots': expected the memory for decoded images in MiB"}, "CLRENDER_IMAGE_MEMORY_MIB=lots"},
        {"EmptyFrameList", {{"path.json", animation_scene()}}, {}, "path.json --frames ''", 1,
         {"--frames: the value is empty"}, "", true},
        {"EmptyOutputPath", {{"scene.json", scene_with("")}}, {}, "scene.json -o ''", 1, {"--output: the value is empty"}, "",
         true},
        {"EmptyVideoPath", {{"path.json", animation_scene()}}, {}, "path.json --video ''", 1, {"--video: the value is empty"},
         "", true},
        {"EmptyStatsPath", {{"scene.json", scene_with("")}}, {}, "scene.json --stats ''", 1, {"--stats: the value is empty"},
         "", true},
        {"EmptyKernelDir", {{"scene.json", scene_with("")}}, {}, "scene.json --kernel-dir ''", 1,
         {"--kernel-dir: the value is empty"}, "", true},
        {"EmptyDevice", {{"scene.json", scene_with("")}}, {}, "scene.json -d ''", 1, {"--device: the value is empty"}, "",
         true},
        {"EmptySceneName", {}, {}, "''", 1, {"scene: the scene file name is empty"}, "", true},
        {"KernelBuildErrorComesBeforeTheCompilersOutput", kernels_with_broken("intersect.cl"), kernel_folders(),
         "scene.json -q --kernel-dir kd", 3, {"building the OpenCL program", "kernels/intersect.cl:", "this"}},
        // --- Output names and files under odd names: control characters in a name are escaped
        // (the message stays one line and sends no escape sequence), and --resume skips only
        // frames that are regular files
        {"OutputNameWithControlCharacters", {{"scene.json", scene_with("")}}, {},
         R"cmd(scene.json -o "$(printf 'a\nb\033[31m.bmp')")cmd", 1, {"a\\x0Ab\\x1B[31m.bmp: unsupported extension"}},
        {"ResumeOverAFolderNamedAsAFrame", {{"path.json", animation_scene()}}, {"f_0001.png"},
         "path.json -q --reference --resume -o f_%04d.png", 4,
         {"f_0001.png: is a folder; clrender writes outputs only to regular files"}},
        {"ResumeOverAFifoNamedAsAFrame", {{"path.json", animation_scene()}}, {},
         "path.json -q --reference --resume -o f_%04d.png --video v.mp4", 4,
         {"f_0001.png: is a named pipe (FIFO)"}, "", false, make_fifo("f_0001.png")},
        // --- Scene inputs, second round: cameras between path keys, the field of view against
        // the image size, and messages quoting hostile text (escaped, shortened)
        bad_scene("EyeMeetsTheLookatPointBetweenKeys",
                  camera_scene(R"("eyeLocations": [[0, 0, 0], [2, 0, 0]])", R"("lookatLocations": [[2, 0, 0], [0, 0, 0]])"),
                  {"bad.json: /eyeLocations/0: eye and lookat are the same point [1, 0, 0] at frame 5, between camera keys 0 and 1",
                   "move key 0 or 1"}),
        bad_scene("ViewTurnsParallelToUpBetweenKeys",
                  camera_scene(R"("eyeLocations": [[-1, 0, 5], [1, 0, 5]])", R"("lookatLocations": [[1, -5, 5], [-1, -5, 5]])"),
                  {"bad.json: /eyeLocations/0: up [0, 1, 0] is parallel to the view direction [0, -1, 0] at frame 5",
                   "change 'up', or move key 0 or 1"}),
        bad_scene("FovNarrowerThanFloatRaysResolve",
                  camera_scene(at_origin, look_at_origin, R"("up": [0, 1, 0])", R"("fov_angle": 1e-300)"),
                  {"bad.json: /fov_angle: fov_angle 1e-300 is too narrow for a 8 x 6 image",
                   "use a fov_angle of at least 0.00046 degrees for this size"}),
        {"FovTooNarrowForTheSizeOnTheCommandLine",
         {{"scene.json", camera_scene(at_origin, look_at_origin, R"("up": [0, 1, 0])", R"("fov_angle": 0.5)")}}, {},
         "scene.json --size 16384x4096", 2,
         {"scene.json: /fov_angle: fov_angle 0.5 is too narrow for a 16384 x 4096 image", "at least 0.94 degrees"}},
        bad_scene("TerminalControlsInAValueAreEscaped", sphere_scene(R"("radius": 1, "type": "\u009b31m\u202e")"),
                  {"bad.json: /spheres/0/type: type must be \"sphere\" here, got \"\\xC2\\x9B31m\\xE2\\x80\\xAE\""}),
        bad_scene("InvalidUtf8InAKeyIsEscaped", "{\"ty\xFF\xFEpe\": 1}",
                  {"bad.json: line 1, column 5:", "ill-formed UTF-8 byte; last read: '\"ty\\xFF'"}),
        bad_scene("MegabyteStringBeforeASyntaxError", "{\"eye\": \"" + std::string(1000000, 'a') + "\xFF\"}",
                  {"bad.json: line 1, column 1000010:", "aaa ... aaa", "aaa\\xFF'"}),
        {"ScenePathWithANewline", {}, {}, "'two\nlines.json'", 2,
         {"two\\x0Alines.json: cannot read scene file: no such file"}},
        // --- Kernel sources: an #include that names no file of the kernel folder is refused
        // before anything is compiled, naming the including file and line
        {"KernelIncludeOfNoFile", kernels_with_broken("intersect.cl", "\n#include \"common/nothing.cl\"\n"),
         kernel_folders(), "scene.json -q --kernel-dir kd", 3,
         {"kernels/intersect.cl:", "#include \"common/nothing.cl\" names no kernel source", "kd/common/nothing.cl"}},
        // --- Outputs: missing folders are made only for a run that passes every check (none
        // for a refused one), never through a file; "-" is standard output for --stats only
        {"OutputFolderThroughAFile", {{"scene.json", scene_with("")}, {"a.png", "not a folder"}}, {},
         "scene.json -q -o a.png/frames/x.png", 4,
         {"a.png/frames/x.png: cannot create the folder 'a.png/frames': 'a.png' is not a folder"}},
        {"NewOutputFolderWithAnUnknownDevice", {{"scene.json", scene_with("")}}, {},
         "scene.json -q -o new/out.png --stats new/stats/run.json -d no-such-device", 3,
         {"unknown OpenCL device 'no-such-device'"}},
        {"NewFramesFolderWithAFrameOutOfRange", {{"path.json", animation_scene()}}, {},
         "path.json -q --frames 99 -o 'frames/f_%04d.png'", 1, {"frame 99 is out of range"}},
        {"ImageToStandardOutput", {{"scene.json", scene_with("")}}, {}, "scene.json -o -", 1,
         {"-o -: clrender writes images and videos only to files", "./- for a file named '-'"}},
        {"VideoToStandardOutput", {{"path.json", animation_scene()}}, {}, "path.json --video -", 1,
         {"--video -: clrender writes images and videos only to files"}},
        {"ResumeWithoutFramesToLookFor", {{"path.json", animation_scene()}}, {}, "path.json --resume", 1,
         {"--resume needs -o with a frame pattern (or --frames without -o and --video)"}},
        // --- The pixel explainer (--explain-pixel): a pixel outside the image, coordinates that
        // are not X,Y, more than one frame, or an output file named with it (it writes none)
        {"ExplainPixelOutsideTheImage", {{"scene.json", scene_with("")}}, {}, "scene.json --reference --explain-pixel 8,0", 1,
         {"--explain-pixel 8,0 is outside the 8x6 image (X from 0 to 7, Y from 0 to 5)"}},
        {"ExplainPixelRowOutsideTheImage", {{"scene.json", scene_with("")}}, {}, "scene.json --explain-pixel 0,6", 1,
         {"--explain-pixel 0,6 is outside the 8x6 image"}},
        {"ExplainPixelWithoutTheRow", {{"scene.json", scene_with("")}}, {}, "scene.json --explain-pixel 3", 1,
         {"--explain-pixel: expected X,Y with non-negative integers (column,row), got '3'"}, "", true},
        {"ExplainPixelNegative", {{"scene.json", scene_with("")}}, {}, "scene.json --explain-pixel=-1,2", 1,
         {"expected X,Y with non-negative integers (column,row), got '-1,2'"}, "", true},
        {"ExplainPixelEmpty", {{"scene.json", scene_with("")}}, {}, "scene.json --explain-pixel ''", 1,
         {"expected X,Y with non-negative integers (column,row), got ''"}, "", true},
        {"ExplainPixelOfTwoFrames", {{"path.json", animation_scene()}}, {}, "path.json --explain-pixel 0,0 --frames 0-1", 1,
         {"--explain-pixel explains one frame; --frames '0-1' names 2"}},
        {"ExplainPixelWithAnOutput", {{"scene.json", scene_with("")}}, {}, "scene.json --explain-pixel 0,0 -o x.png", 1,
         {"--output excludes --explain-pixel"}, "", true},
        // A device failure comes after the reference's part is computed: still only the error
        // line, no half explanation before it.
        {"ExplainPixelOnAnUnknownDevice", {{"scene.json", scene_with("")}}, {},
         "scene.json --explain-pixel 0,0 -d nosuchdevice", 3, {"unknown OpenCL device 'nosuchdevice'"}},
        // --- Progress and control: --progress, -t/--threads and --crop take only what they
        // document; a crop must lie inside the image (after --size)
        {"ProgressStyleUnknown", {{"scene.json", scene_with("")}}, {}, "scene.json --progress xml", 1,
         {"--progress: xml not in {bar,none,json}"}, "", true},
        {"ThreadsZero", {{"scene.json", scene_with("")}}, {}, "scene.json -t 0", 1, {"--threads: Value 0 not in range"},
         "", true},
        {"ThreadsNotANumber", {{"scene.json", scene_with("")}}, {}, "scene.json --threads many", 1,
         {"--threads", "many"}, "", true},
        {"CropEmptyRectangle", {{"scene.json", scene_with("")}}, {}, "scene.json --crop 4,4,0,6", 1,
         {"--crop: expected x0,x1,y0,y1 with 0 <= x0 < x1 and 0 <= y0 < y1, got '4,4,0,6'"}, "", true},
        {"CropThreeNumbers", {{"scene.json", scene_with("")}}, {}, "scene.json --crop 1,2,3", 1,
         {"--crop: expected x0,x1,y0,y1", "got '1,2,3'"}, "", true},
        {"CropNegative", {{"scene.json", scene_with("")}}, {}, "scene.json --crop=-1,4,0,6", 1,
         {"--crop: expected x0,x1,y0,y1", "got '-1,4,0,6'"}, "", true},
        {"CropEmptyValue", {{"scene.json", scene_with("")}}, {}, "scene.json --crop ''", 1,
         {"--crop: the value is empty"}, "", true},
        {"CropOutsideTheImage", {{"scene.json", scene_with("")}}, {}, "scene.json --crop 0,9,0,6", 1,
         {"--crop 0,9,0,6 reaches outside the 8x6 image"}},
        {"CropOutsideTheSizeOverride", {{"scene.json", scene_with("")}}, {}, "scene.json --size 4x4 --crop 0,8,0,6", 1,
         {"--crop 0,8,0,6 reaches outside the 4x4 image"}},
        // --- Scene overrides and checks: -D values are checked like the file's and say where
        // they came from; a -D path that leads nowhere, a malformed -D or --seed, and a
        // mistyped option are usage errors; --check fails as a render would, without a device
        {"DefinedValueOutOfRange", {{"scene.json", scene_with("")}}, {}, "scene.json -q -D MaxDepth=65", 2,
         {"scene.json: /MaxDepth: MaxDepth must be a whole number from 0 to 64 (got 65) (set on the command line: -D MaxDepth=65)"}},
        {"DefineIntoAMissingArrayElement", {{"scene.json", sphere_scene(R"("radius": 1)")}}, {}, "scene.json -q -D spheres.1.radius=2",
         1, {"scene.json: -D spheres.1.radius=2: /spheres has 1 element, so there is no element 1"}},
        {"DefineThroughANumber", {{"scene.json", scene_with("")}}, {}, "scene.json -q -D /fov_angle/x=1", 1,
         {"scene.json: -D /fov_angle/x=1: /fov_angle is a number, not an object or array, so it has no 'x'"}},
        {"DefineWithoutAValue", {{"scene.json", scene_with("")}}, {}, "scene.json -q -D MaxDepth", 1,
         {"-D MaxDepth: expected key=value"}, "", true},
        {"SeedOutOfRange", {{"scene.json", scene_with("")}}, {}, "scene.json -q --seed 4294967296", 1, {"--seed"}, "", true},
        {"MistypedOption", {{"scene.json", scene_with("")}}, {}, "scene.json --sp 4", 1,
         {"unknown option '--sp'; did you mean --spp?"}, "", true},
        {"CheckOfAMissingImage", {{"bad.json", image_scene("nowhere.png")}}, {}, "bad.json --check", 2,
         {"bad.json: /billboards/0/filename: cannot read image", "nowhere.png': no such file"}},
        {"CheckOfAnImageOverThePixelLimit", {{"bad.json", image_scene("huge.jpg")}, {"huge.jpg", jpeg_claiming_20000_squared()}},
         {}, "bad.json --check", 2, {"bad.json: /billboards/0/filename:", "20000 x 20000 pixels is larger than the limit"}},
        // --- HDR and alpha outputs: --alpha only where the output has an alpha channel, EXR
        // frames never read back into a video
        {"AlphaWithAVideo", {{"path.json", animation_scene()}}, {}, "path.json -q --alpha -o f_%04d.png --video v.mp4", 1,
         {"--alpha: the video v.mp4 would have no alpha channel"}},
        {"AlphaWithTheDefaultVideo", {{"path.json", animation_scene()}}, {}, "path.json -q --alpha", 1,
         {"--alpha: the video path.mp4 would have no alpha channel"}},
        {"AlphaIntoAPpm", {{"scene.json", scene_with("")}}, {}, "scene.json -q --alpha -o out.ppm", 1,
         {"--alpha: out.ppm is a PPM, which has no alpha channel"}},
        {"AssembleFromExrFrames", {{"path.json", animation_scene()}}, {}, "path.json -q --assemble -o f_%04d.exr --video v.mp4",
         1, {"-o f_%04d.exr: EXR frames cannot be read back into a video (--assemble)"}},
        {"ResumeExrFramesIntoAVideo", {{"path.json", animation_scene()}}, {}, "path.json -q --resume -o f_%04d.exr --video v.mp4",
         1, {"-o f_%04d.exr: EXR frames cannot be read back into a video (--resume)"}},
        {"ExplainPixelWithAlpha", {{"scene.json", scene_with("")}}, {}, "scene.json --explain-pixel 0,0 --alpha", 1,
         {"--alpha excludes --explain-pixel"}, "", true},
        // --- Joining tiles and resume checks: --join only where the run writes one image that
        // tiles can make; each tile a PNG that clrender --crop wrote for this same render, of its
        // Crop's size, inside the frame, the tiles covering it once; --assemble refuses a PNG
        // frame of another render. Tiles of the 8x6 scene: top.png rows 0-2, bottom.png rows 3-5.
        {"JoinWithCrop", {{"scene.json", scene_with("")}}, {}, "scene.json --join top.png --crop 0,8,0,3", 1,
         {"--crop cannot be used with --join"}, "", true},
        {"JoinWithAssemble", {{"scene.json", scene_with("")}}, {}, "scene.json --join top.png --assemble", 1,
         {"--assemble cannot be used with --join"}, "", true},
        {"JoinWithResume", {{"scene.json", scene_with("")}}, {}, "scene.json --resume --join top.png", 1,
         {"--resume cannot be used with --join"}, "", true},
        {"JoinWithAVideo", {{"path.json", animation_scene()}}, {}, "path.json --join top.png --video v.mp4", 1,
         {"--video cannot be used with --join"}, "", true},
        {"JoinWithExplainPixel", {{"scene.json", scene_with("")}}, {}, "scene.json --join top.png --explain-pixel 0,0", 1,
         {"--explain-pixel cannot be used with --join"}, "", true},
        {"JoinWithAnEmptyTileName", {{"scene.json", scene_with("")}}, {}, "scene.json --join ''", 1,
         {"--join: the value is empty"}, "", true},
        {"JoinOfSeveralFrames", {{"path.json", animation_scene()}}, {}, "path.json --join top.png", 1,
         {"--join makes one image, and this run writes 11 frames: name one with --frames N"}},
        {"JoinIntoAFramePattern", {{"path.json", animation_scene()}}, {}, "path.json --frames 1 --join top.png -o f_%04d.png",
         1, {"--join makes one image: -o f_%04d.png is a frame pattern"}},
        {"JoinIntoAnExr", {{"scene.json", scene_with("")}}, {}, "scene.json --join top.png -o out.exr", 1,
         {"--join: -o out.exr is an EXR, and tiles hold display colours"}},
        {"JoinOfAMissingTile", {{"scene.json", scene_with("")}}, {}, "--join top.png scene.json", 2,
         {"top.png: cannot read the tile: cannot open: No such file or directory"}},
        {"JoinOfATileThatIsNoPng", {{"scene.json", scene_with("")}, {"top.png", "tile\n"}}, {}, "--join top.png scene.json", 2,
         {"top.png: cannot read the tile: not a PNG file"}},
        {"JoinOfAPngWithoutDescription", {{"scene.json", scene_with("")}, {"top.png", png}}, {}, "scene.json --join top.png", 2,
         {"top.png: the tile has no clrender description (PNG text chunks)"}},
        {"JoinOfAWholeImage", {{"scene.json", scene_with("")}}, {}, "scene.json -q --join whole.png -o out.png", 2,
         {"whole.png: the tile's description has no Crop"}, "", false,
         testing::clrender_writes({"scene.json -q -o whole.png"})},
        {"JoinOfATileOfAnotherRender", {{"scene.json", scene_with("")}}, {}, "scene.json -q --join top.png --join bottom.png", 2,
         {"top.png: the tile is of another render: Samples per pixel is 2 in the tile, this render's is 1"}, "", false,
         testing::clrender_writes({"scene.json -q --spp 2 --crop 0,8,0,3 -o top.png",
                                   "scene.json -q --crop 0,8,3,6 -o bottom.png"})},
        {"JoinOfATileNotOfItsCropsSize", {{"scene.json", scene_with("")}}, {}, "scene.json -q --join top.png --join bottom.png",
         2, {"top.png: the tile is 8x2, its Crop 0,8,0,3 is 8x3"}, "", false,
         testing::clrender_writes({"scene.json -q --crop 0,8,0,3 -o top.png",
                                   "scene.json -q --crop 0,8,3,6 -o bottom.png"},
                                  [](const std::string& folder) { testing::cut_png(folder + "/top.png", {0, 8, 0, 2}); })},
        {"JoinOfATileOutsideTheFrame", {{"scene.json", scene_with("")}}, {}, "scene.json -q --join top.png --join bottom.png",
         2, {"top.png: the tile's Crop 2,10,0,3 reaches outside the 8x6 frame"}, "", false,
         testing::clrender_writes({"scene.json -q --crop 0,8,0,3 -o top.png",
                                   "scene.json -q --crop 0,8,3,6 -o bottom.png"},
                                  [](const std::string& folder) { testing::set_png_text(folder + "/top.png", "Crop", "2,10,0,3"); })},
        {"JoinOfOverlappingTiles", {{"scene.json", scene_with("")}}, {}, "scene.json -q --join top.png --join bottom.png", 2,
         {"bottom.png: the tile overlaps top.png (given earlier): both cover pixel 0,3"}, "", false,
         testing::clrender_writes({"scene.json -q --crop 0,8,0,4 -o top.png",
                                   "scene.json -q --crop 0,8,3,6 -o bottom.png"})},
        {"JoinOfOneTileTwice", {{"scene.json", scene_with("")}}, {},
         "scene.json -q --join top.png --join top.png --join bottom.png", 2,
         {"top.png: the tile overlaps top.png (the same file given twice): both cover pixel 0,0"}, "", false,
         testing::clrender_writes({"scene.json -q --crop 0,8,0,3 -o top.png",
                                   "scene.json -q --crop 0,8,3,6 -o bottom.png"})},
        {"JoinLeavingPixelsUncovered", {{"scene.json", scene_with("")}}, {}, "scene.json -q --join top.png --join bottom.png",
         2, {"--join: 2 tiles leave pixels of the 8x6 frame uncovered: no tile covers pixel 5,3 (column 5, row 3)"}, "",
         false,
         testing::clrender_writes({"scene.json -q --crop 0,8,0,3 -o top.png",
                                   "scene.json -q --crop 0,5,3,6 -o bottom.png"})},
        {"JoinOfATruncatedTile", {{"scene.json", scene_with("")}}, {}, "scene.json -q --join top.png --join bottom.png", 2,
         {"top.png: cannot read the tile: truncated"}, "", false,
         testing::clrender_writes({"scene.json -q --crop 0,8,0,3 -o top.png",
                                   "scene.json -q --crop 0,8,3,6 -o bottom.png"},
                                  [](const std::string& folder) { fs::resize_file(folder + "/top.png", 100); })},
        {"JoinOfOpaqueTilesWithAlpha", {{"scene.json", scene_with("")}}, {},
         "scene.json -q --alpha --join top.png --join bottom.png", 2,
         {"top.png: the tile has no alpha channel, and --alpha writes one"}, "", false,
         testing::clrender_writes({"scene.json -q --crop 0,8,0,3 -o top.png",
                                   "scene.json -q --crop 0,8,3,6 -o bottom.png"})},
        {"JoinOverOneOfItsTiles", {{"scene.json", scene_with("")}}, {},
         "scene.json -q --join top.png --join bottom.png -o top.png", 4,
         {"top.png: the image (-o) would replace the tile (--join) 'top.png'"}, "", false,
         testing::clrender_writes({"scene.json -q --crop 0,8,0,3 -o top.png",
                                   "scene.json -q --crop 0,8,3,6 -o bottom.png"})},
        {"AssembleAFrameOfAnotherRender", {{"path.json", animation_scene()}}, {},
         "path.json -q --frames 0-1 --assemble -o f_%04d.png --video v.mp4", 2,
         {"f_0001.png: frame 1 is of another render: Samples per pixel is 2 in the frame, this render's is 1"}, "", false,
         testing::clrender_writes({"path.json -q --frames 0 -o f_%04d.png",
                                   "path.json -q --frames 1 --spp 2 -o f_%04d.png"})},
        {"ResumeOfAStillOverAFolder", {{"scene.json", scene_with("")}}, {"out.png"}, "scene.json -q --resume -o out.png",
         4, {"out.png: is a folder; clrender writes outputs only to regular files"}},
    };
}

// ---------------------------------------------------------------------------------------

std::set<std::string> entries_of(const std::string& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) names.insert(entry.path().string());
    return names;
}

int count_of(const std::string& text, const std::string& part) {
    int count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++count;
    return count;
}

// Test names and failure messages show a case by its name rather than as raw bytes.
void PrintTo(const BadInput& input, std::ostream* out) { *out << input.name; }

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, FailsWithOneClearErrorAndNoOutput) {
    const BadInput& input = GetParam();
    TempFolder folder;
    for (const std::string& name : input.folders) fs::create_directories(folder.file(name));
    for (const File& file : input.files) folder.write(file.name, file.bytes);
    if (input.prepare) input.prepare(folder.path());
    const std::set<std::string> before = entries_of(folder.path());

    const auto result = run_clrender(input.arguments, folder.path(), input.environment);

    EXPECT_EQ(result.exit_code, input.exit_code) << result.output;
    EXPECT_EQ(count_of(result.output, "clrender: error: "), 1) << result.output;
    EXPECT_EQ(result.output.rfind("clrender: error: ", 0), 0) << "the error comes first:\n" << result.output;
    if (input.parser_error) {
        EXPECT_EQ(count_of(result.output, "Run with --help for more information."), 1) << result.output;
    }
    for (const std::string& fragment : input.fragments)
        EXPECT_NE(result.output.find(fragment), std::string::npos) << "missing '" << fragment << "' in:\n" << result.output;
    // Sanitizer builds run this test too: their reports must not pass as an error message.
    EXPECT_EQ(result.output.find("Sanitizer"), std::string::npos) << result.output;
    EXPECT_EQ(entries_of(folder.path()), before) << "clrender left files behind";
}

std::string case_name(const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInputTest, ::testing::ValuesIn(catalogue()), case_name);

TEST(BadInput, CatalogueCoversAtLeast25Cases) {
    const std::vector<BadInput> cases = catalogue();
    std::cout << "[ catalogue] " << cases.size() << " bad inputs\n";
    ::testing::Test::RecordProperty("bad_inputs", static_cast<int>(cases.size()));
    EXPECT_GE(cases.size(), 25u);
    std::set<std::string> names;
    for (const BadInput& input : cases) EXPECT_TRUE(names.insert(input.name).second) << "two cases named " << input.name;
}

// ---------------------------------------------------------------------------------------
// The JSON Schema (docs/scene.schema.json) against the catalogue: an editor that checks a
// scene with the schema must refuse what clrender refuses, where a schema can say why.

// Catalogue scenes the schema cannot refuse: the text is JSON, but what is wrong is beyond a
// schema (the schema's description lists these rules).
const std::set<std::string> kBeyondTheSchema = {
    // the camera's geometry, also between the keys of a path
    "UpParallelToTheView", "EyeEqualsLookat", "EyeEqualsLookatOnAPath", "EyeMeetsTheLookatPointBetweenKeys",
    "ViewTurnsParallelToUpBetweenKeys",
    // a billboard's area and edges: differences of its corners
    "BillboardCollinearCorners", "BillboardCoincidentCorners", "BillboardEdgeOf1eMinus200",
    // products of values: width x height, fov_angle against the size; one key's count against another's
    "ResolutionOverThePixelLimit", "FovNarrowerThanFloatRaysResolve", "MismatchedEyeAndLookatLocations",
    // a name that must be a key elsewhere in the scene (an impostor's view set)
    "ImpostorNamesAnUnknownViewSet",
    // files the scene names
    "MissingImage", "ImpostorViewImageMissing", "MissingObj",
    // one key's value against another's; a count of array members of one type
    "FarNotBeyondNear", "TooManyPlanes",
    // the size, which --size may give instead of the scene: the schema cannot see the command line
    "MissingWidth", "MissingHeight",
};

// How deeply `text` nests arrays and objects (brackets in strings counted too: an upper bound).
int nesting_depth(const std::string& text) {
    int depth = 0, deepest = 0;
    for (char c : text) {
        if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
        if (c == ']' || c == '}') --depth;
    }
    return deepest;
}

// The catalogue's scene files (bad.json, the file a scene case renders) that are JSON, by case,
// as written (a repeated key included: the validator, like clrender, takes the last value).
std::map<std::string, std::string> catalogue_scenes() {
    std::map<std::string, std::string> scenes;
    for (const BadInput& input : catalogue()) {
        // Cases with files beside the scene are about those files (images), which no schema sees.
        if (input.exit_code != 2 || input.arguments != "bad.json" || input.files.size() != 1 || !input.folders.empty() ||
            input.prepare || !input.environment.empty())
            continue;
        // The validator (Python) recurses once a level, as does writing the JSON out: the cases
        // of 100000 nested arrays are the parser's, not the schema's.
        const std::string& text = input.files.front().bytes;
        if (nesting_depth(text) > 100) continue;
        const nlohmann::json scene = nlohmann::json::parse(text, nullptr, false);
        if (!scene.is_discarded()) scenes[input.name] = text;
    }
    return scenes;
}

// "NAME accepted" or "NAME refused" for each file NAME.json in `folder`, by the schema, as
// python3-jsonschema's Draft 2020-12 validator judges it.
std::map<std::string, std::string> schema_verdicts(const std::string& folder) {
    const std::string script = R"(
import json, pathlib, sys
from jsonschema import Draft202012Validator
schema = json.loads(pathlib.Path(sys.argv[1]).read_text(encoding="utf-8"))
Draft202012Validator.check_schema(schema)
validator = Draft202012Validator(schema)
for path in sorted(pathlib.Path(sys.argv[2]).glob("*.json")):
    scene = json.loads(path.read_text(encoding="utf-8-sig"))
    print(path.stem, "refused" if any(True for _ in validator.iter_errors(scene)) else "accepted")
)";
    const auto result = testing::run_shell("/usr/bin/python3 -c " + testing::shell_quoted(script) + " " +
                                           testing::shell_quoted(std::string(CLRENDER_SOURCE_DIR) + "/docs/scene.schema.json") +
                                           " " + testing::shell_quoted(folder));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    std::map<std::string, std::string> verdicts;
    std::istringstream lines(result.output);
    for (std::string name, verdict; lines >> name >> verdict;) verdicts[name] = verdict;
    return verdicts;
}

bool have_jsonschema() { return testing::run_shell("/usr/bin/python3 -c 'import jsonschema'").exit_code == 0; }

TEST(SceneSchema, RefusesEveryCatalogueSceneWhoseFaultASchemaCanExpress) {
    if (!have_jsonschema()) GTEST_SKIP() << "python3-jsonschema is not installed (scripts/install-deps.sh installs it)";
    TempFolder folder;
    const std::map<std::string, std::string> scenes = catalogue_scenes();
    for (const auto& [name, scene] : scenes) folder.write(name + ".json", scene);
    const std::map<std::string, std::string> verdicts = schema_verdicts(folder.path());
    ASSERT_EQ(verdicts.size(), scenes.size());
    EXPECT_GE(scenes.size(), 40u) << "the catalogue's JSON scenes were not all found";
    for (const auto& [name, verdict] : verdicts) {
        if (kBeyondTheSchema.count(name))
            EXPECT_EQ(verdict, "accepted") << name << ": the schema refuses it now; take it off kBeyondTheSchema";
        else
            EXPECT_EQ(verdict, "refused") << name << ": clrender refuses it, the schema does not";
    }
}

// And accepts the scenes clrender renders: the demo scenes, the course's scenes where the
// course material is present, and the catalogue's base scenes.
TEST(SceneSchema, AcceptsScenesClrenderRenders) {
    if (!have_jsonschema()) GTEST_SKIP() << "python3-jsonschema is not installed (scripts/install-deps.sh installs it)";
    TempFolder folder;
    std::vector<fs::path> good = {fs::path(CLRENDER_SOURCE_DIR) / "scenes/demo/demo.json",
                                  fs::path(CLRENDER_SOURCE_DIR) / "scenes/demo/showcase.json"};
    const fs::path course = fs::path(CLRENDER_SOURCE_DIR) / "../shared";
    if (fs::is_directory(course)) {
        for (const auto& entry : fs::recursive_directory_iterator(course, fs::directory_options::skip_permission_denied))
            if (entry.is_regular_file() && entry.path().extension() == ".json") good.push_back(entry.path());
    }
    int index = 0;
    std::map<std::string, std::string> sources;
    for (const fs::path& path : good) {
        const nlohmann::json scene = nlohmann::json::parse(read_bytes(path), nullptr, false, /*ignore_comments=*/true);
        if (scene.is_discarded() || !scene.is_object() || (!scene.contains("eye") && !scene.contains("eyeLocations")))
            continue;  // not a scene (another JSON file of the course)
        const std::string name = "scene" + std::to_string(index++);
        sources[name] = path.string();
        folder.write(name + ".json", scene.dump());
    }
    folder.write("base.json", scene_with(""));
    folder.write("sphere.json", sphere_scene(R"("radius": 1e-15)"));
    folder.write("far.json", scene_with(R"("SunLocation": [1e15, -1e15, 0])"));
    folder.write("animation.json", animation_scene());
    folder.write("fall2019.json", scene_with(R"("surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
        "ambient": [0.5, 0, 0], "diffuse": [0.5, 0, 0], "specular": [1, 1, 1], "phong_exponent": 20, "mirror": [0.1, 0.1, 0.1]},
        {"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "ambient": [0.1, 0.1, 0.1]}],
        "lights": [{"position": [5, 5, 5], "color": [0.8, 0.8, 0.8]}])"));
    // Meshes of both formats, scaled by one factor or per axis (the schema refused a per-axis
    // scale on a `surfaces` mesh, which clrender reads as the `obj` one).
    folder.write("meshes.json", scene_with(R"("surfaces": [{"type": "mesh", "filename": "m.obj", "ambient": [1, 0, 0],
        "scale": [1, 2, 1]}, {"type": "mesh", "filename": "m.obj", "ambient": [1, 0, 0], "scale": 2}],
        "obj": [{"type": "obj", "filename": "m.obj", "scale": [1, 2, 3], "position": [0, 0, 1]},
        {"filename": "m.obj", "scale": 0.5}])"));
    for (const auto& [name, verdict] : schema_verdicts(folder.path()))
        EXPECT_EQ(verdict, "accepted") << name << " " << sources[name];
}

}  // namespace
}  // namespace clr
