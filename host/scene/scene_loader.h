// Turns a scene file (the course's "balls and billboards" JSON) into a validated Scene.
// Every failure is a SceneError naming the file, the JSON location and what is wrong.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/limits.h"
#include "scene/scene.h"
#include "scene/scene_overrides.h"

namespace clr {

// Largest scene file read. The biggest generated scenes (scripts/forest) are a few MiB; a
// parsed document takes several times its text in memory.
constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t(64) << 20;

// Set ("1") by `clrender view` for the render of its video: load_scene() reads the scene's text
// from standard input, where the viewer hands over the text it wrote and checked, and the path
// only names the scene (in messages). Read by its name, the file was whatever another program
// writing into --output-dir had put there meanwhile.
inline constexpr const char* kSceneOnStdinVariable = "CLRENDER_SCENE_ON_STDIN";

struct LoadOptions {
    // Render a placeholder image (see make_placeholder_image) for a billboard image that is
    // missing or unreadable, with a warning, instead of failing.
    bool placeholder_images = false;
    // Resolution given on the command line; replaces the scene's width and height, which
    // may then be absent.
    std::optional<int> width_override;
    std::optional<int> height_override;
    // Samples per pixel given on the command line (--spp); replaces the scene's.
    std::optional<int> samples_override;
    // The sample pattern's seed given on the command line (--seed); replaces clrender.seed.
    std::optional<unsigned> seed_override;
    // Scene values given on the command line (-D), set in order before the scene is read;
    // --size, --spp and --seed replace what they set.
    std::vector<SceneOverride> overrides;
    // false (--check): images are checked from their headers only, not decoded; the scene's
    // image pointers stay null (placeholders aside) and Scene::image_files describes them.
    bool decode_images = true;
    // true (--frame-count): only what the number of frames depends on matters; the image
    // size is neither required nor checked, and the images are not read at all.
    bool count_frames_only = false;
    // false (the viewer's export check): the meshes' placements are checked as JSON, but their
    // OBJ files are not read again; scene.meshes stays empty.
    bool read_meshes = true;
    // Most bytes all the scene's images may take while they are decoded (scene/image_budget.h);
    // unset: CLRENDER_IMAGE_MEMORY_MIB, else kDefaultImageMemoryBytes.
    std::optional<std::uint64_t> image_memory_limit;
    // Most bytes the scene's meshes may take to read and render (scene/mesh_loader.h); unset:
    // default_memory_budget(), half of the machine's memory.
    std::optional<std::uint64_t> mesh_memory_budget;
};

// Reads and validates the scene file at `path` (its text from standard input under
// kSceneOnStdinVariable). Relative image paths are resolved against the scene file's folder.
// Throws SceneError.
Scene load_scene(const std::string& path, const LoadOptions& options = {});

// The same for scene text already in memory; `path` names it in messages and anchors
// relative image paths.
Scene parse_scene(const std::string& text, const std::string& path, const LoadOptions& options = {});

}  // namespace clr
