// The camera parameters of a viewer request (/frame.png, /frame.rgba, /explain), read from its
// query: eye=x,y,z, lookat=x,y,z, up=x,y,z, fov=DEGREES, size=WxH, spp=N, frame=N, and for
// /explain x=X, y=Y. Each is optional. This file checks only their form (numbers, finite,
// whole where whole); what values a scene allows is checked as the scene loader checks a
// scene's (view/view_camera.h), so that the viewer's limits are the command line's.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace clr {

// A parameter the viewer cannot use: answered with 400 and {"error": what(), "parameter": ...}.
class ParameterError : public std::runtime_error {
public:
    ParameterError(std::string parameter, const std::string& message)
        : std::runtime_error(message), parameter_(std::move(parameter)) {}
    const std::string& parameter() const { return parameter_; }

private:
    std::string parameter_;
};

// A query's name=value pairs, decoded (query_parameters() gives each name once).
using QueryParameters = std::multimap<std::string, std::string>;

// The parameters of the query of `target` (a request's target as sent, "/frame.png?eye=..."),
// token= aside (the guard checks it): each named in `known`, given once, with no '=' in its
// value as sent. Throws ParameterError naming the first that is not: cpp-httplib's own parse
// (Request::params) ignored a name it did not know (a typo, sise=4x4, rendered the scene's
// size), took a pair given twice alike as one, and kept what followed a value's last '='.
QueryParameters query_parameters(const std::string& target, const std::vector<std::string>& known);

struct ViewQuery {
    std::optional<Vec3> eye, lookat, up;
    std::optional<double> fov_degrees;
    std::optional<int> width, height;
    std::optional<int> samples_per_pixel;
    std::optional<int> frame;
};

struct PixelQuery {
    int x = 0, y = 0;  // column and row from the top-left
};

// Reads the camera parameters; names it does not know are left alone (query_parameters()
// refuses them). Throws ParameterError naming the parameter.
ViewQuery parse_view_query(const QueryParameters& query);

// Reads x= and y= (both required, whole numbers from 0). Throws ParameterError.
PixelQuery parse_pixel_query(const QueryParameters& query);

// One finite number in plain decimal notation ("-1.5", "2e3"): no hex, no inf, no nan, no
// surrounding spaces; a value beyond double's range is not finite. nullopt otherwise.
std::optional<double> parse_plain_number(const std::string& text);

}  // namespace clr
