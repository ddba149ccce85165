// Fuzzes what `clrender view` does with a request before anything renders: the guard (Host,
// Origin, token), the camera parameters of the query and their check against a scene
// (view/view_camera.h), the pixel of /explain, and the camera keys of a POST body.
//
// The input is lines: METHOD, PATH, HOST, ORIGIN, COOKIE (unused: the viewer has no cookie), then name=value query parameters
// (decoded, as cpp-httplib hands them over); the whole input is also tried as a POST body.
// The contract under test (docs/command-line.md, Viewer): every request is either
// allowed or refused, every bad parameter is a clr::ParameterError naming a known parameter
// with a one-line message, and an accepted camera is one the scene loader accepts: finite,
// inside the limits, with a view direction and an up vector that fixes the roll. Anything
// else (another exception, a crash, a hang, a sanitizer report) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "scene/limits.h"
#include "scene/scene_loader.h"
#include "view/camera_keys.h"
#include "view/query_tokens.h"
#include "view/request_guard.h"
#include "view/view_camera.h"
#include "view/view_parameters.h"

namespace {

using clr::fuzz::report_bug;

const clr::Scene& path_scene() {
    static const clr::Scene scene = clr::parse_scene(R"({
      "eyeLocations": [[0, 0, 10], [10, 0, 0], [0, 5, -10]], "lookat": [0, 0, 0], "up": [0, 1, 0],
      "fov_angle": 50, "width": 64, "height": 48, "clrender": {"spp": 2, "frames_per_segment": 4},
      "spheres": [{"center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]}]})",
                                                     "view.json");
    return scene;
}

const std::string kToken = "0123456789abcdef0123456789abcdef";

void check_error(const clr::ParameterError& error, const std::set<std::string>& known) {
    if (known.count(error.parameter()) == 0) report_bug("error names an unknown parameter", error.parameter());
    if (std::string(error.what()).empty()) report_bug("empty error message", error.parameter());
    if (!clr::fuzz::is_one_printable_line(error.what())) report_bug("message is not one printable line", error.what());
}

bool finite(const clr::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_camera(const clr::ViewCamera& view) {
    if (!finite(view.key.eye) || !finite(view.key.lookat) || !finite(view.up)) report_bug("accepted a camera that is not finite", "");
    if (view.key.eye == view.key.lookat) report_bug("accepted a camera without a view direction", "");
    if (view.up == clr::Vec3{}) report_bug("accepted a zero up vector", "");
    if (!(view.fov_degrees > 0 && view.fov_degrees < 180)) report_bug("accepted a field of view out of range", "");
    if (view.width < 1 || view.height < 1 || view.width > clr::kMaxImageSide || view.height > clr::kMaxImageSide ||
        static_cast<long long>(view.width) * view.height > clr::kMaxImagePixels)
        report_bug("accepted a size out of range", "");
    if (view.sampling.samples_per_pixel < 1 || view.sampling.samples_per_pixel > clr::kMaxSamplesPerPixel)
        report_bug("accepted samples out of range", "");
    if (view.frame < 0 || view.frame >= 9) report_bug("accepted a frame outside the animation", "");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (std::size_t end; (end = input.find('\n', start)) != std::string::npos; start = end + 1)
        lines.push_back(input.substr(start, end - start));
    lines.push_back(input.substr(start));
    while (lines.size() < 5) lines.emplace_back();

    // The PATH line is also read as a raw target, as every route reads its query
    // (view/query_tokens.h): any bytes must split without a crash, and a pair read from it
    // never holds the '&' that separates pairs unless it was sent as %26.
    for (const clr::QueryPair& pair : clr::query_pairs_as_sent(lines[1]))
        if (lines[1].find("%26") == std::string::npos && (pair.name.find('&') != std::string::npos || pair.value.find('&') != std::string::npos))
            report_bug("read a pair across an '&'", lines[1]);
    clr::query_tokens_as_sent(lines[1]);

    clr::RequestFacts facts;
    facts.method = lines[0];
    facts.path = lines[1];
    if (!lines[2].empty()) facts.host = lines[2];
    if (!lines[3].empty()) facts.origin = lines[3];
    facts.arrived_on = "127.0.0.1";  // the bound address, as every request to this guard
    clr::QueryParameters query;
    for (std::size_t i = 5; i < lines.size(); ++i) {
        const std::size_t equals = lines[i].find('=');
        const std::string name = lines[i].substr(0, equals);
        const std::string value = equals == std::string::npos ? "" : lines[i].substr(equals + 1);
        if (name == "token") facts.query_tokens.push_back(value);
        query.emplace(name, value);
    }
    const clr::RequestGuard guard(kToken, "127.0.0.1", 8123);
    const clr::RequestVerdict verdict = guard.check(facts);
    if (verdict != clr::RequestVerdict::Forbidden) {
        // Allowed only with the token, a Host naming the server, and for a change its own Origin.
        const bool has_token = facts.query_tokens.size() == 1 && facts.query_tokens[0] == kToken;
        if (!has_token) report_bug("allowed without the token in the query", lines[4]);
        if (!facts.host || !guard.host_allowed(*facts.host)) report_bug("allowed with a foreign Host", "");
        if (facts.method != "GET" && facts.method != "HEAD" && (!facts.origin || !guard.origin_allowed(*facts.origin, facts.arrived_on)))
            report_bug("allowed a change from a foreign Origin", "");
    }

    try {
        check_camera(clr::resolve_view_camera(path_scene(), clr::parse_view_query(query)));
    } catch (const clr::ParameterError& error) {
        check_error(error, {"eye", "lookat", "up", "fov", "size", "spp", "frame"});
    }
    try {
        const clr::PixelQuery pixel = clr::parse_pixel_query(query);
        if (pixel.x < 0 || pixel.y < 0) report_bug("accepted a negative pixel", "");
    } catch (const clr::ParameterError& error) {
        check_error(error, {"x", "y"});
    }
    try {
        const clr::CameraKeysRequest keys = clr::parse_camera_keys(input);
        if (keys.keys.empty() || keys.keys.size() > clr::kMostCameraKeys) report_bug("accepted a wrong number of keys", "");
        for (const clr::CameraKey& key : keys.keys)
            if (!finite(key.eye) || !finite(key.lookat)) report_bug("accepted a key that is not finite", "");
        if (!keys.name.empty() && !clr::is_plain_base_name(keys.name)) report_bug("accepted a name that is no plain name", keys.name);
    } catch (const clr::ParameterError& error) {
        check_error(error, {"body", "keys", "name", "up", "fov"});
    }
    return 0;
}
