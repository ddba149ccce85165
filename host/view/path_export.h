// POST /export: the scene with the page's camera keys as the course's camera path
// (eyeLocations / lookatLocations, docs/animation.md), written as NAME.json into --output-dir.
// The exported scene is the scene the viewer shows: the file with the command line's -D values
// applied, --size, --spp and --seed written in, and image paths rewritten to be found from
// --output-dir. It is checked by the scene loader before it is written, written atomically, and
// never over any file: a name that is taken is skipped for the next free one (NAME-2, ...).
#pragma once

#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "app/options.h"
#include "scene/scene.h"
#include "view/camera_keys.h"

namespace clr {

struct ExportedScene {
    std::string text;  // the scene file's text
    std::string path;  // where it was written: OUTPUT_DIR/NAME.json
    std::string name;  // NAME: the request's name, or the next free one of its series
};

class PathExporter {
public:
    // `scene_text` is the scene file as read when the viewer started (the scene was loaded
    // from it), `options` the command line's. The scene's folder is resolved here, once: later
    // exports need neither the current folder nor the name it was reached by.
    PathExporter(const Scene& scene, std::string scene_text, const Options& options, std::string output_dir);

    // Makes, checks and writes the exported scene (one export at a time), under the first name
    // of the request's name's series (view/unused_name_file.h) whose NAME.json, and NAME + each
    // of `also_unused` (".mp4" for a video), do not exist and are no input of the scene.
    // Throws ParameterError (the keys make no valid scene: "keys", naming the problem as the
    // loader does) and OutputError (the file cannot be written). `before_write`, given, sees the
    // checked text before anything is written: what it throws refuses the export, writing nothing.
    ExportedScene export_keys(const CameraKeysRequest& request, const std::vector<std::string>& also_unused = {},
                              const std::function<void(const std::string& text)>& before_write = {}) const;

    // The exported scene's text without writing it (for the checks and tests).
    std::string scene_text_for(const CameraKeysRequest& request) const;

    // Checks that `path` may be written by this run: not the scene, an image it shows, or
    // (through a link) either. Throws OutputError.
    void check_output(const std::string& role, const std::string& path) const;

    const std::string& output_dir() const { return output_dir_; }
    std::string default_name() const { return scene_.name + "_path"; }

private:
    const Scene& scene_;
    std::string scene_text_;
    const Options& options_;
    std::string output_dir_;
    std::filesystem::path scene_folder_;  // absolute, physical: relative image names are found from it
    // Each export holds the scene's JSON twice as a tree (made, then checked by the loader),
    // about 18 times the file each (docs/robustness.md, Memory): several at once (a script, a
    // page's clicks) held several, 8 at once of a 21 MB scene 2.2 GB. One runs at a time.
    mutable std::mutex one_at_a_time_;
};

}  // namespace clr
