#include "app/description_check.h"

#include <algorithm>
#include <iterator>

#include "core/errors.h"
#include "output/png_reader.h"

namespace clr {

std::optional<std::string> text_of(const ImageText& text, const std::string& key) {
    for (const auto& [keyword, value] : text)
        if (keyword == key) return value;
    return std::nullopt;
}

std::optional<DescriptionDifference> first_difference(const ImageText& in_file, const ImageText& this_run) {
    const ImageText expected = png_text_as_written(this_run);
    for (const auto& [key, value] : expected) {
        const std::optional<std::string> found = text_of(in_file, key);
        if (found != value) return DescriptionDifference{key, found, value};
    }
    for (const auto& [key, value] : in_file)
        if (!text_of(expected, key)) return DescriptionDifference{key, value, std::nullopt};
    return std::nullopt;
}

std::string difference_sentence(const DescriptionDifference& difference, const std::string& file_word) {
    if (!difference.in_file)
        return "the " + file_word + " has no " + difference.key + ", this render's is " + *difference.in_run;
    if (!difference.in_run)
        return difference.key + " is " + *difference.in_file + " in the " + file_word + ", this render writes none";
    return difference.key + " is " + *difference.in_file + " in the " + file_word + ", this render's is " +
           *difference.in_run;
}

void check_frame_description(const std::string& path, int frame, const ImageText& this_run) {
    if (image_format_for(path) != ImageFormat::Png) return;
    const std::string name = "frame " + std::to_string(frame);
    PngHeader header;
    try {
        header = read_png_header(path);
    } catch (const PngReadError& error) {
        throw SceneError(path, "", "cannot read " + name + ": " + error.what());
    }
    if (const auto difference = first_difference(header.text, this_run))
        throw SceneError(path, "", name + " is of another render: " + difference_sentence(*difference, "frame") +
                                       "; render it again (--resume does so) or assemble with the options it was made with");
}

ImageText without_key(const ImageText& text, const std::string& key) {
    ImageText kept;
    std::copy_if(text.begin(), text.end(), std::back_inserter(kept), [&key](const auto& pair) { return pair.first != key; });
    return kept;
}

}  // namespace clr
