#include "support/scene_json.h"

#include "core/errors.h"

namespace clr::testing::scene_json {

// The smallest valid scene; tests add or change keys.
Json minimal_scene() {
    return Json::parse(R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0],
                           "fov_angle": 60, "width": 4, "height": 3})");
}

Json sphere(const Json& radius) {
    return Json{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", radius}, {"ambient", {1, 0, 0}}};
}

Json flat_billboard() {
    return Json::parse(R"({"type": "billboard", "UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0],
                           "UpperRight": [1, 1, 0], "ambient": [0, 1, 0]})");
}

Scene parse(const Json& scene, const LoadOptions& options) {
    return parse_scene(scene.dump(), "test.json", options);
}

// Passes when parsing `text` throws a SceneError at `location` whose detail contains
// `fragment`; otherwise says what happened instead.
::testing::AssertionResult TextFailsAt(const std::string& text, const std::string& location,
                                       const std::string& fragment, const LoadOptions& options,
                                       const std::string& path) {
    try {
        parse_scene(text, path, options);
    } catch (const SceneError& error) {
        if (error.file() != path) return ::testing::AssertionFailure() << "file is '" << error.file() << "'";
        if (error.location() == location && error.detail().find(fragment) != std::string::npos)
            return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "got location '" << error.location() << "', detail '"
                                             << error.detail() << "'";
    }
    return ::testing::AssertionFailure() << "no SceneError for " << text;
}

::testing::AssertionResult FailsAt(const Json& scene, const std::string& location, const std::string& fragment,
                                   const LoadOptions& options) {
    return TextFailsAt(scene.dump(), location, fragment, options);
}

bool has_warning(const Scene& scene, const std::string& text) {
    for (const std::string& warning : scene.warnings)
        if (warning.find(text) != std::string::npos) return true;
    return false;
}

std::string all_warnings(const Scene& scene) {
    std::string text;
    for (const std::string& warning : scene.warnings) text += warning + "\n";
    return text;
}

// Writes a binary PPM (P6) of `width` x `height` texels, all of one colour, into `folder`;
// returns its path.
std::string write_ppm(const TempFolder& folder, const std::string& name, int width, int height) {
    std::string content = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    for (int i = 0; i < width * height; ++i) content += "\x10\x20\x30";
    return folder.write(name, content);
}

}  // namespace clr::testing::scene_json
