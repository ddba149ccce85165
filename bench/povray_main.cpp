// clrender_to_povray: writes one frame of a clrender scene as a POV-Ray 3.7 scene (OUT.pov)
// and its render settings (OUT.ini beside it), for the comparison of docs/benchmarks.md,
// Against POV-Ray. The scene is read by clrender's own loader, so --size, --spp and -D mean
// what they mean to clrender and a scene clrender refuses is refused here too.
//
//   clrender_to_povray SCENE OUT.pov [--size WxH] [--spp N] [-D key=value]... [--frame N]
//   cd OUT's folder && povray OUT.ini +OIMAGE.png
#include <CLI/CLI.hpp>

#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "bench/povray_scene.h"
#include "bench/povray_settings.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "output/atomic_file.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"

namespace clr::bench {
namespace {

struct Options {
    std::string scene_path;
    std::string pov_path;
    std::string size;
    std::optional<int> samples;
    std::vector<std::string> overrides;
    int frame = 0;
};

std::optional<Options> parse_options(int argc, char** argv, int& exit_code) {
    Options options;
    CLI::App app{"Writes one frame of a clrender scene as a POV-Ray 3.7 scene (OUT.pov) and its render "
                 "settings (OUT.ini); render it with: povray OUT.ini +OIMAGE.png"};
    app.add_option("scene", options.scene_path, "clrender scene file (JSON)")->required();
    app.add_option("output", options.pov_path, "POV-Ray scene file to write; the settings go beside it as .ini")
        ->required();
    app.add_option("--size", options.size, "image size WIDTHxHEIGHT, replacing the scene's (as clrender --size)");
    app.add_option("--spp", options.samples, "samples per pixel (as clrender --spp)")->check(CLI::Range(1, 4096));
    app.add_option("-D,--define", options.overrides, "scene value key=value (as clrender -D); repeatable");
    app.add_option("--frame", options.frame, "frame of an animation, 0-based")->capture_default_str()->check(
        CLI::NonNegativeNumber);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) {  // --help: CLI11 prints it
            exit_code = app.exit(error);
            return std::nullopt;
        }
        throw UsageError(error.what());  // clrender's exit code for a bad command line, not CLI11's
    }
    return options;
}

LoadOptions load_options(const Options& options) {
    LoadOptions load;
    if (!options.size.empty()) {
        static const std::regex pattern(R"((\d{1,6})[xX](\d{1,6}))");
        std::smatch match;
        if (!std::regex_match(options.size, match, pattern) || std::stoi(match[1]) < 1 || std::stoi(match[2]) < 1)
            throw UsageError("--size: expected WIDTHxHEIGHT with positive integers, got '" + options.size + "'");
        load.width_override = std::stoi(match[1]);
        load.height_override = std::stoi(match[2]);
    }
    load.samples_override = options.samples;
    for (const std::string& argument : options.overrides) load.overrides.push_back(parse_scene_override(argument));
    return load;
}

// OUT.pov -> OUT.ini; a name without the .pov extension gets .ini added.
std::string ini_path_for(const std::string& pov_path) {
    std::filesystem::path path(pov_path);
    if (path.extension() == ".pov") return path.replace_extension(".ini").string();
    return pov_path + ".ini";
}

void write_text(AtomicFile& file, const std::string& text) { file.write(text.data(), text.size()); }

int run(const Options& options) {
    const Scene scene = load_scene(options.scene_path, load_options(options));
    for (const std::string& warning : scene.warnings) std::cerr << "clrender_to_povray: warning: " << printable(warning) << "\n";
    const std::string scene_text = povray_scene_text(scene, options.frame);
    const std::string pov_absolute = std::filesystem::absolute(options.pov_path).lexically_normal().string();
    const std::string ini_text = povray_ini_text(scene, pov_absolute);

    // Both files or neither: each is complete before either takes its final name.
    AtomicFile pov(options.pov_path);
    AtomicFile ini(ini_path_for(options.pov_path));
    write_text(pov, scene_text);
    write_text(ini, ini_text);
    pov.complete();
    ini.complete();
    pov.commit();
    ini.commit();
    return kExitOk;
}

int report(int code, const std::string& message) {
    std::cerr << "clrender_to_povray: error: " << printable(message) << "\n";
    return code;
}

}  // namespace
}  // namespace clr::bench

int main(int argc, char** argv) {
    using namespace clr;
    try {
        int exit_code = 0;
        std::optional<bench::Options> options = bench::parse_options(argc, argv, exit_code);
        return options ? bench::run(*options) : exit_code;
    } catch (const Error& error) {
        return bench::report(error.code(), error.what());
    } catch (const std::bad_alloc&) {
        return bench::report(kExitOutOfMemory, "out of memory");
    } catch (const std::exception& error) {
        return bench::report(kExitInternal, std::string("internal error: ") + error.what());
    }
}
