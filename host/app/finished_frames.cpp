#include "app/finished_frames.h"

#include <filesystem>

#include "app/description_check.h"
#include "app/frame_description.h"
#include "output/png_reader.h"

namespace clr {
namespace {

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

std::string another_render(const std::string& key, const std::string& in_file, const std::string& in_run) {
    return "made by another render (" + key + ": " + in_file + " in the file, " + in_run + " in this run)";
}

}  // namespace

std::optional<std::string> why_not_finished(const std::string& path, const ExpectedImage& expected) {
    PngHeader header;
    try {
        header = read_png_header(path);
    } catch (const PngReadError& error) {
        return std::string("cannot be read (") + error.what() + ")";
    }
    if (const auto difference = first_difference(header.text, expected.text))
        return another_render(difference->key, difference->in_file.value_or("none"), difference->in_run.value_or("none"));
    if (header.width != expected.width || header.height != expected.height)
        return another_render("image size", size_text(header.width, header.height),
                              size_text(expected.width, expected.height));
    if (!header.clrender_form) return std::string("made by another program (not an 8-bit RGB or RGBA PNG)");
    if (header.alpha != expected.alpha)
        return another_render("alpha channel", header.alpha ? "yes" : "no", expected.alpha ? "yes" : "no");
    return std::nullopt;
}

void find_finished_frames(const Options& options, const Scene& scene, OutputPlan& plan) {
    if (!options.resume || plan.image_target.empty() || plan.assemble) return;
    ExpectedImage expected;
    expected.width = options.crop ? options.crop->width() : scene.width;
    expected.height = options.crop ? options.crop->height() : scene.height;
    expected.alpha = options.alpha;
    for (int frame : plan.frames) {
        const std::string path = plan.image_path(frame);
        std::error_code ignored;
        if (!std::filesystem::is_regular_file(path, ignored)) continue;  // missing, or refused as an output
        if (image_format_for(path) == ImageFormat::Png) {
            expected.text = describe_frame(scene, frame, options);
            if (const std::optional<std::string> reason = why_not_finished(path, expected)) {
                plan.warnings.push_back(path + ": " + *reason + "; rendering it again");
                continue;
            }
        }
        plan.finished_frames.insert(frame);
    }
}

}  // namespace clr
