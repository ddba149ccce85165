// The scenes of the run-time-against-error benchmark (docs/error-benchmark.md): the demo
// scenes, a course scene when the course's folder is there, and two numerical stress scenes
// built in code.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace clr::bench {

// One view to measure: the scene at the benchmark's size, the camera key it is seen from, and
// the animation frame index that seeds its sample pattern (with the scene's seed).
struct ErrorScene {
    std::string name;    // as printed, and as given to --scenes
    std::string source;  // the scene file, or what a generated scene shows
    Scene scene;
    CameraKey key;
    int frame = 0;
};

// Every scene, in table order, at width x height. `root` is the repository (scene files are
// read from root/scenes/demo, the course scene from root/../shared/course-scenes, skipped when
// absent). Throws SceneError when a demo scene cannot be read.
std::vector<ErrorScene> error_bench_scenes(const std::string& root, int width, int height);

}  // namespace clr::bench
