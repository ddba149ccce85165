// Whether an image file was made by the same render as this run's: its PNG description (the
// text chunks of docs/command-line.md, PNG metadata) against the one this run writes. --resume,
// --assemble and --join trust a file only when they agree.
#pragma once

#include <optional>
#include <string>

#include "output/image_writer.h"

namespace clr {

struct DescriptionDifference {
    std::string key;
    std::optional<std::string> in_file;  // nullopt: the file has no such key
    std::optional<std::string> in_run;   // nullopt: this run writes no such key
};

// The first key whose text differs: this run's keys in order, then any the file has besides.
// `this_run` is compared as a PNG holds it (png_text_as_written). nullopt when they agree.
std::optional<DescriptionDifference> first_difference(const ImageText& in_file, const ImageText& this_run);

// "Samples per pixel is 16 in the tile, this render's is 64", with `file_word` ("tile", "frame").
std::string difference_sentence(const DescriptionDifference& difference, const std::string& file_word);

// --assemble: throws SceneError (exit 2) naming `path` unless the PNG there is frame `frame`
// of this render (`this_run`: the description this run writes for it). PPM frames carry no
// description and pass.
void check_frame_description(const std::string& path, int frame, const ImageText& this_run);

// `text` without the pairs of `key`.
ImageText without_key(const ImageText& text, const std::string& key);

// The text of `key`, or nullopt when `text` has none.
std::optional<std::string> text_of(const ImageText& text, const std::string& key);

}  // namespace clr
