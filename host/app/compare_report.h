// What `clrender compare` prints on standard output (docs/command-line.md, Comparing with an
// image): the share of pixels that differ and the pixels that differ most, as text or as one
// JSON object (--json).
#pragma once

#include <string>

#include "app/image_difference.h"

namespace clr {

struct CompareFacts {
    std::string scene_path;
    int frame = 0;
    std::string image_path;
    std::string heat_map_path;  // empty: none written
};

std::string compare_report_text(const CompareFacts& facts, const ImageDifference& difference);
std::string compare_report_json(const CompareFacts& facts, const ImageDifference& difference);

}  // namespace clr
