// Fills the program store that clrender finds beside its executable (device/program_store.h):
//   clrender_build_program_store FOLDER [--all]
// with the binaries of render_packets on the default device (a plain run's: the first CPU
// device) for every feature set of render/feature_combinations.h (each scene feature set of
// spheres and billboards, and the general programs) in float precision with byte output, what a command line
// without --precision double, --alpha or an EXR output asks for; --all adds those (four times
// as many programs). Run at build time (cmake/build_program_store.cmake). Never fails for want
// of a device or a compiler: the store is then empty (or short) and a message says so, and
// first runs build their programs from source as without a store.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "device/device_selection.h"
#include "render/feature_combinations.h"
#include "render/program_store_builder.h"

int main(int argc, char** argv) {
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    const bool all = arguments.size() == 2 && arguments[1] == "--all";
    if (arguments.empty() || arguments.size() > 2 || (arguments.size() == 2 && !all) || arguments[0].empty()) {
        std::cerr << "usage: clrender_build_program_store FOLDER [--all]\n";
        return 1;
    }
    const std::string& folder = arguments[0];
    std::error_code error;
    std::filesystem::create_directories(folder, error);  // an empty store is still one to install
    std::vector<clr::FeatureSet> sets = clr::store_feature_sets(false, false);
    if (all) {
        for (auto [double_precision, float_output] : {std::pair{false, true}, {true, false}, {true, true}}) {
            const std::vector<clr::FeatureSet> more = clr::store_feature_sets(double_precision, float_output);
            sets.insert(sets.end(), more.begin(), more.end());
        }
    }
    clr::DeviceEntry device;
    try {
        device = clr::select_device(clr::list_devices(), "");
    } catch (const std::exception& error) {
        const int removed = clr::empty_program_store(folder);
        std::cout << "clrender_build_program_store: no OpenCL device (" << error.what() << "): the program store "
                  << folder << " is empty" << (removed ? " (older entries removed)" : "")
                  << "; first runs build their programs from source\n";
        return 0;
    }
    const auto start = std::chrono::steady_clock::now();
    try {
        const clr::ProgramStoreBuild build = clr::build_program_store(folder, device, sets, std::cerr);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cout << "clrender_build_program_store: " << folder << ": " << build.built + build.kept << " of "
                  << sets.size() << " programs for '" << device.device_name << "' (" << build.built << " built, "
                  << build.kept << " kept, " << build.removed << " removed) in " << seconds << " s\n";
        if (build.failed)
            std::cout << "clrender_build_program_store: " << build.failed
                      << " could not be built: first runs that need them build from source\n";
    } catch (const std::exception& error) {
        std::cout << "clrender_build_program_store: " << error.what() << ": the program store " << folder
                  << " is incomplete; first runs build their programs from source\n";
    }
    return 0;
}
