// Writes a forest scene for clrender: forest.json and its pictures, all drawn by code.
//
//   clrender_make_forest OUT_DIR [--trees N] [--seed S] [--frames F] [--size WxH]
//
// The same options give the same bytes. scripts/forest.sh builds, generates and renders it.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include "scripts/forest/forest_scene.h"

namespace {

// "1280x720" into width and height; false when it is not two positive whole numbers.
bool parse_size(const std::string& text, int& width, int& height) {
    char separator = 0, extra = 0;
    return std::sscanf(text.c_str(), "%d%c%d%c", &width, &separator, &height, &extra) == 3 &&
           (separator == 'x' || separator == 'X') && width > 0 && height > 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"clrender_make_forest: writes a forest scene (forest.json and its pictures) into a folder"};
    forest::ForestOptions options;
    std::string folder, size = "1280x720";
    app.add_option("folder", folder, "Output folder")->required();
    app.add_option("--trees", options.trees, "Number of trees, the lone one included")->check(CLI::Range(1, 200000));
    app.add_option("--seed", options.seed, "Seed of the layout and the tree shapes");
    app.add_option("--frames", options.frames, "Frames of the camera flight")->check(CLI::Range(2, 100000));
    app.add_option("--size", size, "Image size, WxH");
    CLI11_PARSE(app, argc, argv);
    if (!parse_size(size, options.width, options.height)) {
        std::cerr << "clrender_make_forest: --size must be WxH, e.g. 1280x720 (got '" << size << "')\n";
        return 2;
    }
    try {
        forest::write_forest(options, folder);
    } catch (const std::exception& error) {
        std::cerr << "clrender_make_forest: " << error.what() << "\n";
        return 1;
    }
    std::cout << "wrote " << folder << "/forest.json (" << options.trees << " trees, " << options.frames << " frames)\n";
    return 0;
}
