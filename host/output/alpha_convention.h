// --alpha (docs/command-line.md, HDR and alpha outputs): turns a frame's mean colours and
// coverage (Image::linear) into the colour of what was hit and its coverage.
//
// A pixel's mean colour m mixes the colours of its samples that hit an object with the
// background colour B of those that did not: with coverage a (the fraction that hit),
// m = hit part + (1 - a) B. Compositors expect that part alone. In display values, as the
// renderer computes, the hit samples' own colour is S = (m - (1 - a) B) / a:
//  - PNG, straight (the PNG specification's convention): RGB = the bytes of S,
//    A = round(a * 255), RGB unchanged where a is 0 (the background) or 1 (no background in it);
//  - EXR, premultiplied in linear light (OpenEXR's convention): RGB = a * linear(S), A = a, which
//    the EXR writer computes (output/exr_values.h) from the S and the bytes left here.
#pragma once

#include "core/image.h"
#include "core/vec3.h"

namespace clr {

// Rewrites `image` (which has float colours) as above: image.rgba holds the PNG's straight
// bytes and alpha, image.linear S and a (S = m where a is 0 or 1), and marks it write_alpha.
// `samples`: samples per pixel, to which the coverage is snapped (k / samples), so that a pixel
// every sample hit has alpha exactly 1 whatever the device's division.
void apply_alpha_convention(Image& image, const Vec3& background, int samples);

}  // namespace clr
