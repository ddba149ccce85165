// The body of POST /export and POST /render-video: the camera keys the page recorded,
// {"keys": [{"eye": [x, y, z], "lookat": [x, y, z]}, ...], "name": "optional base name"},
// optionally with the "up" vector and "fov" the page used.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace clr {

// Most keys one export may have: far more than anyone records by hand.
constexpr std::size_t kMostCameraKeys = 10000;

// Most JSON values and object members a body may hold: kMostCameraKeys keys take 11 each, and a
// key may carry a few members more (the page's own `up` or `fov` of a later version).
constexpr std::size_t kMostBodyValues = 16 * kMostCameraKeys + 64;

struct CameraKeysRequest {
    std::vector<CameraKey> keys;  // at least one
    std::string name;             // base name of the files written; "" when not given
    std::optional<Vec3> up;
    std::optional<double> fov_degrees;
};

// Throws ParameterError naming "body", "keys", "name", "up" or "fov". Positions are checked
// for their form here (three finite numbers) and for their range by the scene loader, once
// they are in the exported scene.
CameraKeysRequest parse_camera_keys(const std::string& body);

// Whether `name` may name an exported file in --output-dir: letters, digits, '.', '_' and '-',
// 1 to 100 of them, starting with a letter or digit (no folders, no hidden files).
bool is_plain_base_name(const std::string& name);

}  // namespace clr
