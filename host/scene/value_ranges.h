// The ranges of scene numbers that clrender renders right, and their checks. The kernels
// trace in float32 with positions relative to each frame's eye, and square lengths
// (radius^2, |centre - eye|^2, billboard dual vectors, sun distance): those squares must stay
// finite and normal in float, or a sphere silently vanishes. docs/scene-format.md
// ("Numeric ranges") gives the derivation.
#pragma once

#include <string>

#include "core/vec3.h"
#include "scene/json_reader.h"

namespace clr {

// Every coordinate of every position (eye, lookat, centres, corners, the sun) lies in
// [-kMaxCoordinate, kMaxCoordinate]. Points are then at most 2 sqrt(3) 1e15 ~ 3.5e15 apart.
constexpr double kMaxCoordinate = 1e15;
// Every length (radius, billboard edge, impostor width and height) lies in
// [kMinLength, kMaxLength]. The upper bound is above any distance between valid positions,
// so that a billboard spanning the whole coordinate range still passes.
constexpr double kMinLength = 1e-15;
constexpr double kMaxLength = 1e16;

// Neighbouring pixels' rays must differ in direction by at least this much (2 tan(fov/2)
// divided by the image's larger side): the kernels keep ray directions in float32, whose
// components resolve about 6e-8, so at a narrower spacing neighbouring pixels get the same
// ray (a blocky or blank image). 1e-6 leaves a margin of about 16.
constexpr double kMinPixelSpan = 1e-6;

// The text of the ranges, for messages.
std::string position_range_text();
std::string length_range_text();

// A number as JSON writes it (shortest round trip: 1e-200, 2.5).
std::string number_text(double value);

// node.vec3(), each coordinate checked against the position range; a coordinate out of
// range is reported at its own location ("/spheres/0/center/2").
Vec3 read_position(const Node& node);

// The same check for a position already read, with the location of its [x, y, z] array.
void check_position(const Vec3& position, const std::string& location, const std::string& label,
                    const Diagnostics& diagnostics);

// A length in the length range; "must be > 0" for zero or negative values, as before.
double read_length(const Node& node);

}  // namespace clr
