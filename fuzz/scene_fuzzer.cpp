// Fuzzes the scene loader: clr::parse_scene on the input as the text of a scene file.
//
// The contract under test (docs/scene-format.md): any text either becomes a valid Scene or is
// rejected with a clr::SceneError naming the file. Anything else is a bug: another exception
// type, a crash, a hang, a sanitizer report, a message that is not one printable line
// (clrender prints each error and warning as one line), or a Scene that breaks a rule the loader
// promises to enforce (checked below, so that validation gaps count as findings too).
//
// The scene "file" is <work folder>/scene.json. parse_scene reads images relative to it, so
// the folder holds a few small images under the names the seed scenes use (scene_images());
// a mutated name that misses them is an error, which is fine. An absolute or "../" name can
// reach other files, which are only ever read, never written, so that stays harmless.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <typeinfo>

#include "core/errors.h"
#include "fuzz_support.h"
#include "scene/scene_loader.h"
#include "seed_images.h"

namespace {

using clr::fuzz::report_bug;

const std::string& scene_path() {
    static const std::string path = clr::fuzz::work_folder() + "/scene.json";
    return path;
}

bool finite(const clr::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The promises of docs/scene-format.md (Validation) that a loaded Scene must keep.
void check_scene(const clr::Scene& scene) {
    if (scene.camera_path.empty()) report_bug("scene loaded without a camera", "");
    for (const clr::CameraKey& key : scene.camera_path) {
        if (!finite(key.eye) || !finite(key.lookat)) report_bug("camera key is not finite", "");
        if (key.eye == key.lookat) report_bug("camera key has eye == lookat", "");
    }
    if (!finite(scene.up) || scene.up == clr::Vec3{}) report_bug("up is zero or not finite", "");
    if (!(scene.fov_degrees > 0 && scene.fov_degrees < 180)) report_bug("fov_angle outside (0, 180)", "");
    if (scene.width < 1 || scene.height < 1 || scene.width > clr::kMaxImageSide || scene.height > clr::kMaxImageSide ||
        static_cast<long long>(scene.width) * scene.height > clr::kMaxImagePixels)
        report_bug("image size outside the limits", std::to_string(scene.width) + "x" + std::to_string(scene.height));
    if (scene.max_depth < 0 || scene.max_depth > 64) report_bug("MaxDepth outside 0..64", "");
    if (!finite(scene.background) || (scene.has_sun && !finite(scene.sun_location)))
        report_bug("background or sun not finite", "");
    for (const clr::Sphere& sphere : scene.spheres) {
        if (!finite(sphere.center) || !finite(sphere.ambient)) report_bug("sphere not finite", "");
        if (!(sphere.radius > 0) || !std::isfinite(sphere.radius)) report_bug("sphere radius not > 0", "");
    }
    for (const clr::Billboard& billboard : scene.billboards) {
        if (!finite(billboard.upper_left) || !finite(billboard.lower_left) || !finite(billboard.upper_right))
            report_bug("billboard corner not finite", "");
        if (!billboard.is_mirror && !billboard.image && !billboard.has_ambient)
            report_bug("billboard with neither image nor colour", "");
        if (billboard.image) {
            const clr::Image& image = *billboard.image;
            if (image.width < 1 || image.height < 1 ||
                image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
                report_bug("billboard image has inconsistent size", image.path);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    for (const clr::fuzz::NamedFile& image : clr::fuzz::scene_images())
        clr::fuzz::write_file(clr::fuzz::work_folder() + "/" + image.name, image.bytes.data(), image.bytes.size());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const clr::Scene scene = clr::parse_scene(text, scene_path());
        check_scene(scene);
        for (const std::string& warning : scene.warnings)
            if (!clr::fuzz::is_one_printable_line(warning)) report_bug("warning is not one printable line", warning);
    } catch (const clr::SceneError& error) {
        // The expected way to refuse a scene; it must name the scene file, say something,
        // and fit on the one line clrender prints.
        if (error.file() != scene_path()) report_bug("SceneError names another file", error.what());
        if (error.detail().empty()) report_bug("SceneError without a detail", error.what());
        if (!clr::fuzz::is_one_printable_line(error.what())) report_bug("SceneError is not one printable line", error.what());
    } catch (const std::exception& error) {
        report_bug(std::string("parse_scene threw ") + typeid(error).name() + " instead of clr::SceneError",
                   error.what());
    }
    return 0;
}
