// Compares a kernel render with the reference render of the same scene.
#pragma once

#include <string>

#include "core/image.h"

namespace clr::testing {

struct ImageComparison {
    long long pixels = 0;
    long long differing = 0;           // some channel differs by more than 1 (a float rounding)
    long long differing_off_edge = 0;  // ... and no 8-neighbour of it in the reference differs
                                       // from it, i.e. not on a silhouette or texture edge
    int max_channel_difference = 0;
    std::string first_differing;       // "(col, row): kernel r,g,b vs reference r,g,b"
    std::string first_off_edge;        // the same for the first differing off an edge

    double differing_fraction() const { return pixels ? static_cast<double>(differing) / pixels : 0; }
};

ImageComparison compare_images(const Image& kernel, const Image& reference);

}  // namespace clr::testing
