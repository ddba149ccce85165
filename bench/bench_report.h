// The benchmark's results: one row of measurements per scene, printed as a Markdown table
// (it reads in a terminal and pastes into docs/benchmarks.md) and written as JSON.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "bench/bench_scenes.h"
#include "device/device_selection.h"

namespace clr::bench {

struct RunSettings {
    int width = 1920, height = 1080;
    int repeat = 5;  // timed frames per side and scene
    bool with_embree = false;
};

// One scene's measurements from both sides.
struct SceneRow {
    BenchSceneSpec spec;
    double clr_setup_ms = 0;                         // program build and scene upload
    std::vector<double> clr_kernel_ms, clr_wall_ms;  // per timed frame
    double embree_build_ms = 0;                      // device, geometry and BVH build
    std::vector<double> embree_wall_ms;              // per timed frame
    double covered = 0;    // fraction of pixels where clrender sees an object
    // Fraction of pixels where the two sides see different objects; in a lit scene, where
    // their colours differ by more than kLitTolerance display steps in a channel.
    double differing = 0;
    std::size_t triangles = 0;      // mesh triangles in the scene
    double bytes_per_triangle = 0;  // device memory (bench/triangle_memory.h); 0 without triangles
};


// CPU, OpenCL device and peer, as a few lines.
void print_machine(std::ostream& out, const DeviceEntry& device);

void print_table(std::ostream& out, const std::vector<SceneRow>& rows, const RunSettings& settings);

// Throws OutputError when the file cannot be written.
void write_json(const std::string& path, const std::vector<SceneRow>& rows, const DeviceEntry& device,
                const RunSettings& settings);

}  // namespace clr::bench
