// Writes the fuzzers' seed corpus: valid (and a few nearly valid) inputs for each target, made
// by the project itself rather than downloaded.
//
//   clrender_fuzz_seeds SOURCE_DIR OUT_DIR
//
// writes OUT_DIR/view (viewer requests), OUT_DIR/scene (scene files: the demo scenes from SOURCE_DIR/scenes/demo and one
// scene for each key, variant and image kind of docs/scene-format.md), OUT_DIR/png,
// OUT_DIR/jpeg, OUT_DIR/ppm_p3 and OUT_DIR/ppm_p6 (images in every variant the decoders read,
// and the demo's textures). The output is the same on every run and machine.
#include <stb_image_write.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "seed_images.h"

namespace {

namespace fs = std::filesystem;
using clr::fuzz::JpegSpec;
using clr::fuzz::PngColor;
using clr::fuzz::PngSpec;
using clr::fuzz::PpmSpec;

void write(const fs::path& folder, const std::string& name, const std::string& bytes) {
    fs::create_directories(folder);
    std::ofstream out(folder / name, std::ios::binary);
    out << bytes;
    if (!out) throw std::runtime_error("cannot write " + (folder / name).string());
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// ---------------------------------------------------------------------------------------
// Scenes. Image names are those the scene fuzzer puts beside its scene (scene_images()).

const char* kCamera = R"("eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 8, "height": 6)";

struct NamedScene {
    const char* name;
    std::string text;
};

std::vector<NamedScene> scenes() {
    const std::string camera = kCamera;
    return {
        {"minimal.json", "{" + camera + "}"},
        {"course_still.json", R"({
  "eye": [0, 0, 5.5], "lookat": [0, 0, 3], "up": [0, 1, 0], "fov_angle": 99,
  "width": 16, "height": 12, "DefaultColor": [0, 0, 0], "SunLocation": [-900, 900, 0], "MaxDepth": 6,
  "OnlyAmbient": 0,
  "spheres": [
    {"type": "sphere", "center": [4, 0, 3], "radius": 1.5, "ambient": [0.09, 0.99, 0.09]},
    {"type": "sphere", "center": [0.3, -2, 3], "radius": 1.5, "ambient": [0.5, 0.5, 0.5], "IsMirror": 1}
  ],
  "billboards": [
    {"type": "billboard", "UpperLeft": [-8, 8, -1], "LowerLeft": [-8, -8, -1], "UpperRight": [8, 8, -1],
     "filename": "tex.png"},
    {"type": "billboard", "UpperLeft": [-2, 2, 0], "LowerLeft": [-2, -2, 0], "UpperRight": [2, 2, 0],
     "ambient": [1, 0, 0], "IsMirror": 0}
  ]
})"},
        {"course_variants.json", R"({
  "eye": [1, 2, 9], "lookat": [0, 0, 0], "up": [0, 0.5, 0.1], "fov_angle": 45.5, "width": 12.0, "height": 7,
  "DefaulColor": [0.2, 0.3, 0.4], "OnlyAmbient": true,
  "spheres": [{"center": [0, 0, 0], "radius": 2, "ambient": [1, 1, 1], "IsMirror": false}],
  "billboards": [{"type": "billboards", "UpperLeft": [-1, 1, -3], "LowerLeft": [-1, -1, -3],
                  "UpperRight": [1, 1, -3], "IsMirror": true}]
})"},
        {"every_image_kind.json", "{" + camera + R"(,
  "billboards": [
    {"UpperLeft": [-4, 3, -2], "LowerLeft": [-4, 1, -2], "UpperRight": [-2, 3, -2], "filename": "tex.png"},
    {"UpperLeft": [-1, 3, -2], "LowerLeft": [-1, 1, -2], "UpperRight": [1, 3, -2], "filename": "tex16.png"},
    {"UpperLeft": [2, 3, -2], "LowerLeft": [2, 1, -2], "UpperRight": [4, 3, -2], "filename": "photo.jpg"},
    {"UpperLeft": [-4, 0, -2], "LowerLeft": [-4, -2, -2], "UpperRight": [-2, 0, -2], "filename": "ascii.ppm"},
    {"UpperLeft": [-1, 0, -2], "LowerLeft": [-1, -2, -2], "UpperRight": [1, 0, -2], "filename": "binary.ppm"},
    {"UpperLeft": [2, 0, -2], "LowerLeft": [2, -2, -2], "UpperRight": [4, 0, -2], "filename": "./tex.png",
     "ambient": [0, 1, 0]}
  ]
})"},
        {"path_fixed_lookat.json", R"({"eyeLocations": [[0, 0, 5], [5, 0, 0], [0, 5, 1]], "lookat": [0, 0, 0],
  "up": [0, 1, 0], "fov_angle": 60, "width": 8, "height": 8,
  "spheres": [{"center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]}]})"},
        {"path_lookat_list.json", R"({"eyeLocations": [[0, 0, 5], [1, 0, 5]], "lookatLocations": [[0, 0, 0], [1, 0, 0]],
  "up": [0, 1, 0], "fov_angle": 30, "width": 4, "height": 4,
  "clrender": {"fps": 24, "frames": 30, "interpolation": "catmull-rom"}})"},
        {"path_duration.json", R"({"eyeLocations": [[0, 0, 5], [1, 1, 5], [2, 0, 5]], "lookat": [0, 0, 0],
  "up": [0, 1, 0], "fov_angle": 60, "width": 4, "height": 4,
  "clrender": {"duration": 2.5, "fps": 12, "interpolation": "linear"}})"},
        {"path_per_segment.json", R"({"eyeLocations": [[0, 0, 5]], "lookatLocations": [[0, 0, 0]], "up": [0, 1, 0],
  "fov_angle": 60, "width": 4, "height": 4, "clrender": {"frames_per_segment": 3}})"},
        {"webgl_2025.json", R"({"eyeLocations": [[0, 0, 5], [0, 1, 5]], "lookatLocations": [[0, 0, 0], [0, 0, 0]],
  "up": [0, 1, 0], "fov_angle": 60, "near": 0.1, "far": 100, "obj": "teapot.obj", "width": 4, "height": 4,
  "billboard": {"UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0], "UpperRight": [1, 1, 0], "filename": "checker.png"},
  "mirror": {"UpperLeft": [-3, 1, -1], "LowerLeft": [-3, -1, -1], "UpperRight": [3, 1, -1], "IsMirror": 1}})"},
        {"older_format.json", "{" + camera + R"(, "surfaces": [{"type": "sphere"}], "lights": [{"pos": [0, 1, 0]}]})"},
        {"fall2019.json", "{" + camera + R"(, "near": 0.5, "far": 50, "surfaces": [
  {"type": "sphere", "center": [0, 1, 0], "radius": 1, "ambient": [0.2, 0, 0], "diffuse": [0.7, 0.1, 0.1],
   "specular": [1, 1, 1], "phong_exponent": 20, "mirror": [0.1, 0.1, 0.1]},
  {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "ambient": [0.1, 0.1, 0.1], "diffuse": [0.5, 0.5, 0.5]},
  {"type": "triangle", "vertices": [[0, 0, -2], [1, 0, -2], [0, 1, -2]], "ambient": [0, 0, 1]}],
  "lights": [{"position": [5, 5, 5], "color": [0.8, 0.8, 0.8]}, {"position": [-5, 3, 1], "color": [0.2, 0.2, 0.6]}]})"},
        {"warnings.json", "{" + camera + R"(, "width": 9, "radious": 1, "spheres": [{"center": [0, 0, 0],
  "radius": 1, "ambient": [1, 0, 0], "colour": [0, 1, 0], "a/b~c": 1}], "clrender": {"fsp": 10}})"},
        {"comments_bom_crlf.json", "\xEF\xBB\xBF// a scene\r\n{\r\n  /* the camera */\r\n  " + camera +
                                       ",\r\n  \"MaxDepth\": 0 // no mirrors\r\n}\r\n"},
        {"strings_and_numbers.json", R"({"eye": [0e0, -0, 5E+0], "lookat": [1e-300, 0.0, -0.0],
  "up": [0, 1e2, 0], "fov_angle": 179.999, "width": 16384, "height": 1, "MaxDepth": 64.0,
  "billboards": [{"UpperLeft": [0, 1, 0], "LowerLeft": [0, 0, 0], "UpperRight": [1, 1, 0],
                  "filename": ".\/t\u0065x.png", "ambient": [2, -1, 0.5], "caf\u00e9 \"x\"\\": 1}]})"},
        {"no_size.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60})"},
        {"trailing_comma.json", "{" + camera + R"(, "spheres": [],})"},
        {"overflow.json", R"({"eye": [0, 0, 1e999], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60})"},
        {"degenerate.json", "{" + camera + R"(, "billboards": [{"UpperLeft": [0, 0, 0], "LowerLeft": [1, 1, 1],
  "UpperRight": [2, 2, 2], "ambient": [1, 1, 1]}], "spheres": [{"center": [0, 0, 0], "radius": 0, "ambient": [0, 0, 0]}]})"},
    };
}

// ---------------------------------------------------------------------------------------
// Images

struct NamedPng {
    const char* name;
    PngSpec spec;
};

std::vector<NamedPng> pngs() {
    auto spec = [](PngColor color, int depth) {
        PngSpec s;
        s.color = color;
        s.bit_depth = depth;
        return s;
    };
    std::vector<NamedPng> list = {
        {"rgba8.png", spec(PngColor::Rgba, 8)},         {"rgb8.png", spec(PngColor::Rgb, 8)},
        {"grey8.png", spec(PngColor::Grey, 8)},         {"grey_alpha8.png", spec(PngColor::GreyAlpha, 8)},
        {"grey1.png", spec(PngColor::Grey, 1)},         {"grey2.png", spec(PngColor::Grey, 2)},
        {"grey4.png", spec(PngColor::Grey, 4)},         {"palette1.png", spec(PngColor::Palette, 1)},
        {"palette2.png", spec(PngColor::Palette, 2)},   {"palette4.png", spec(PngColor::Palette, 4)},
        {"palette8.png", spec(PngColor::Palette, 8)},   {"rgb16.png", spec(PngColor::Rgb, 16)},
        {"rgba16.png", spec(PngColor::Rgba, 16)},       {"grey16.png", spec(PngColor::Grey, 16)},
        {"grey_alpha16.png", spec(PngColor::GreyAlpha, 16)},
    };
    // Variants of structure rather than pixel format.
    PngSpec s = spec(PngColor::Rgb, 8);
    s.vary_filters = true;
    s.width = 9;
    s.height = 6;
    list.push_back({"rgb8_all_filters.png", s});
    s = spec(PngColor::Rgba, 16);
    s.vary_filters = true;
    list.push_back({"rgba16_all_filters.png", s});
    s = spec(PngColor::Rgb, 8);
    s.interlaced = true;
    s.width = 11;
    s.height = 10;
    list.push_back({"rgb8_interlaced.png", s});
    s = spec(PngColor::Palette, 2);
    s.interlaced = true;
    s.vary_filters = true;
    s.transparency = true;
    s.width = 3;  // leaves some of Adam7's seven passes empty
    s.height = 2;
    list.push_back({"palette2_interlaced_trns.png", s});
    s = spec(PngColor::GreyAlpha, 16);
    s.interlaced = true;
    s.width = 9;
    s.height = 9;
    list.push_back({"grey_alpha16_interlaced.png", s});
    s = spec(PngColor::Palette, 8);
    s.transparency = true;
    list.push_back({"palette8_trns.png", s});
    s = spec(PngColor::Rgb, 8);
    s.transparency = true;
    list.push_back({"rgb8_colour_key.png", s});
    s = spec(PngColor::Grey, 4);
    s.transparency = true;
    list.push_back({"grey4_colour_key.png", s});
    s = spec(PngColor::Rgb, 16);
    s.transparency = true;
    list.push_back({"rgb16_colour_key.png", s});
    s = spec(PngColor::Rgba, 8);
    s.zlib_level = 0;
    list.push_back({"rgba8_stored_blocks.png", s});
    s = spec(PngColor::Rgba, 8);
    s.fixed_huffman = true;
    s.idat_chunks = 3;
    s.text_chunk = true;
    list.push_back({"rgba8_fixed_huffman_split_idat.png", s});
    s = spec(PngColor::Rgba, 8);
    s.width = 1;
    s.height = 1;
    list.push_back({"rgba8_1x1.png", s});
    s = spec(PngColor::Rgb, 8);
    s.width = 64;
    s.height = 40;
    s.zlib_level = 9;
    list.push_back({"rgb8_64x40.png", s});
    return list;
}

struct NamedJpeg {
    const char* name;
    JpegSpec spec;
};

std::vector<NamedJpeg> jpegs() {
    std::vector<NamedJpeg> list;
    JpegSpec s;
    list.push_back({"rgb_420.jpg", s});
    s.h_sampling = 2;
    s.v_sampling = 1;
    list.push_back({"rgb_422.jpg", s});
    s.h_sampling = 1;
    s.v_sampling = 1;
    s.quality = 100;
    list.push_back({"rgb_444_q100.jpg", s});
    s = JpegSpec{};
    s.components = 1;
    s.width = 13;
    s.height = 9;
    list.push_back({"grey_13x9.jpg", s});
    s = JpegSpec{};
    s.progressive = true;
    s.width = 24;
    s.height = 17;
    list.push_back({"rgb_progressive.jpg", s});
    s.components = 1;
    list.push_back({"grey_progressive.jpg", s});
    s = JpegSpec{};
    s.restart_rows = 1;
    s.width = 40;
    s.height = 33;
    list.push_back({"rgb_restart_markers.jpg", s});
    s = JpegSpec{};
    s.optimize_huffman = true;
    s.quality = 30;
    list.push_back({"rgb_optimized_q30.jpg", s});
    s = JpegSpec{};
    s.components = 4;
    list.push_back({"cmyk_adobe.jpg", s});
    s = JpegSpec{};
    s.width = 1;
    s.height = 1;
    list.push_back({"rgb_1x1.jpg", s});
    return list;
}

struct NamedPpm {
    const char* name;
    PpmSpec spec;
};

std::vector<NamedPpm> ppms(bool ascii) {
    auto spec = [ascii](int width, int height, int maxval, bool comments) {
        PpmSpec s;
        s.width = width;
        s.height = height;
        s.maxval = maxval;
        s.ascii = ascii;
        s.comments = comments;
        return s;
    };
    return {
        {"maxval255.ppm", spec(5, 3, 255, false)},  {"maxval255_comments.ppm", spec(4, 4, 255, true)},
        {"maxval1.ppm", spec(3, 2, 1, false)},      {"maxval15.ppm", spec(6, 1, 15, true)},
        {"maxval1000.ppm", spec(2, 3, 1000, false)}, {"maxval65535.ppm", spec(3, 3, 65535, true)},
        {"1x1.ppm", spec(1, 1, 255, false)},
    };
}

// A texture as the renderer's own PNG writer (stb_image_write) produces it, and a JPEG from
// stb_image_write too: files the way most of clrender's users' tools write them.
std::string stb_encoded(bool jpeg) {
    constexpr int kWidth = 10, kHeight = 7;
    std::vector<unsigned char> rgba;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 4; ++c) rgba.push_back(static_cast<unsigned char>(clr::fuzz::pattern_sample(x, y, c, 255)));
    std::string out;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    if (jpeg)
        stbi_write_jpg_to_func(append, &out, kWidth, kHeight, 4, rgba.data(), 90);
    else
        stbi_write_png_to_func(append, &out, kWidth, kHeight, 4, rgba.data(), kWidth * 4);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: clrender_fuzz_seeds SOURCE_DIR OUT_DIR\n";
        return 1;
    }
    const fs::path source = argv[1];
    const fs::path out = argv[2];
    try {
        const fs::path demo = source / "scenes" / "demo";
        for (const NamedScene& scene : scenes()) write(out / "scene", scene.name, scene.text);
        for (const char* name : {"demo.json", "showcase.json"}) write(out / "scene", name, read(demo / name));

        for (const NamedPng& png : pngs()) write(out / "png", png.name, clr::fuzz::encode_png(png.spec));
        write(out / "png", "stb_image_write.png", stb_encoded(false));
        for (const char* name : {"backdrop.png", "checker.png", "cutout.png"}) write(out / "png", name, read(demo / name));

        for (const NamedJpeg& jpeg : jpegs()) write(out / "jpeg", jpeg.name, clr::fuzz::encode_jpeg(jpeg.spec));
        write(out / "jpeg", "stb_image_write.jpg", stb_encoded(true));

        for (const NamedPpm& ppm : ppms(true)) write(out / "ppm_p3", ppm.name, clr::fuzz::encode_ppm(ppm.spec));
        write(out / "ppm_p3", "demo_sign.ppm", read(demo / "sign.ppm"));
        for (const NamedPpm& ppm : ppms(false)) write(out / "ppm_p6", ppm.name, clr::fuzz::encode_ppm(ppm.spec));

        // OBJ meshes (obj_fuzzer.cpp, which puts materials.mtl beside them): every corner form,
        // relative indices, polygons, groups, materials, CRLF and CR line ends.
        const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
        write(out / "obj", "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        write(out / "obj", "quad_forms.obj",
              "mtllib materials.mtl\no square\ng front\ns 1\n" + square +
                  "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nusemtl red\nf 1/1/1 2/2/1 3/3/1 4/3/1\n"
                  "usemtl grey\nf 1//1 3//1 4//1\nf 1/1 2/2 3/3\ns off\nf -4 -3 -2 -1\n");
        write(out / "obj", "pentagon_crlf.obj", "v 0 0 0\r\nv 2 0 0\r\nv 2 2 0\r\nv 1 3 0\r\nv 0 2 0\r\nf 1 2 3 4 5\r\n");
        write(out / "obj", "cr_only.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
        write(out / "obj", "exponents.obj", "v 0e5 1.5E-3 -2e+2\nv 1e-300 .5 -0.\nv 7 +1 0\nvn 0 0 1e0\nf 1//1 2//1 3//1\n");
        write(out / "obj", "cube.obj",
              "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
              "vn 0 0 -1\nvn 0 0 1\nvn -1 0 0\nvn 1 0 0\nvn 0 -1 0\nvn 0 1 0\n"
              "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 5//3 8//3 4//3\n"
              "f 2//4 3//4 7//4 6//4\nf 1//5 2//5 6//5 5//5\nf 4//6 8//6 7//6 3//6\n");

        // Viewer requests (view_request_fuzzer.cpp): METHOD, PATH, HOST, ORIGIN, COOKIE lines, then
        // query parameters; a POST body of camera keys.
        const std::string token = "token=0123456789abcdef0123456789abcdef";
        write(out / "view", "frame", "GET\n/frame.png\n127.0.0.1:8123\n\n\n" + token +
                                         "\neye=1,2,3\nlookat=0,0,0\nup=0,1,0\nfov=45\nsize=64x48\nspp=4\n");
        write(out / "view", "path_frame", "GET\n/frame.rgba\nlocalhost:8123\n\n\n" + token + "\nframe=5\neye=0,5,5\n");
        write(out / "view", "explain", "GET\n/explain\n[::1]:8123\n\n\n" + token + "\nx=3\ny=7\nfov=1e-5\n");
        write(out / "view", "cookie", "GET\n/scene.json\n127.0.0.1:8123\n\nclrender_token=0123456789abcdef0123456789abcdef\n");
        write(out / "view", "export",
              "{\"keys\": [{\"eye\": [0, 1, 5], \"lookat\": [0, 0, 0]}, {\"eye\": [1, 1, 5], \"lookat\": [0, 0, 0]}], "
              "\"name\": \"tour\", \"up\": [0, 1, 0], \"fov\": 40}");
        write(out / "view", "post", "POST\n/export\n127.0.0.1:8123\nhttp://127.0.0.1:8123\n\n" + token + "\n");
    } catch (const std::exception& error) {
        std::cerr << "clrender_fuzz_seeds: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
