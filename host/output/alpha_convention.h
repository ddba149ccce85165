// --alpha (docs/command-line.md, HDR and alpha outputs): turns a frame's mean colours and
// coverage (Image::linear) into what each format's readers expect of an alpha channel.
//
// A pixel's mean colour m mixes the colours of its samples that hit an object with the
// background colour B of those that did not: with coverage a (the fraction that hit),
// m = hit part + (1 - a) B. Compositors expect that part alone:
//  - EXR, premultiplied (OpenEXR's convention): RGB = m - (1 - a) B, A = a;
//  - PNG, straight (the PNG specification's convention): RGB = (m - (1 - a) B) / a,
//    A = round(a * 255), RGB unchanged where a is 0 (the background) or 1 (no background in it).
#pragma once

#include "core/image.h"
#include "core/vec3.h"
#include "output/image_writer.h"

namespace clr {

// Rewrites `image` (which has linear colours) for `format` as above and marks it
// write_alpha. `samples`: samples per pixel, to which the coverage is snapped (k / samples),
// so that a pixel every sample hit has alpha exactly 1 whatever the device's division.
void apply_alpha_convention(Image& image, ImageFormat format, const Vec3& background, int samples);

}  // namespace clr
