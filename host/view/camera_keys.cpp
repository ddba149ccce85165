#include "view/camera_keys.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>

#include "view/view_parameters.h"

namespace clr {
namespace {

using nlohmann::json;

Vec3 read_point(const json& value, const std::string& parameter, const std::string& what) {
    if (!value.is_array() || value.size() != 3)
        throw ParameterError(parameter, what + " must be [x, y, z], three finite numbers");
    double coordinates[3];
    for (int i = 0; i < 3; ++i) {
        if (!value[i].is_number() || !std::isfinite(value[i].get<double>()))
            throw ParameterError(parameter, what + " must be [x, y, z], three finite numbers");
        coordinates[i] = value[i].get<double>();
    }
    return {coordinates[0], coordinates[1], coordinates[2]};
}

}  // namespace

bool is_plain_base_name(const std::string& name) {
    static const std::regex plain(R"([A-Za-z0-9][A-Za-z0-9._-]{0,99})");
    return std::regex_match(name, plain);
}

CameraKeysRequest parse_camera_keys(const std::string& body) {
    const std::string shape = "a JSON object {\"keys\": [{\"eye\": [x, y, z], \"lookat\": [x, y, z]}, ...]}";
    json document;
    try {  // each way a body fails says so: a number past a double's range is JSON that no double holds
        document = json::parse(body);
    } catch (const json::parse_error& error) {
        throw ParameterError("body", "the body is not JSON (byte " + std::to_string(error.byte) + "); it must be " + shape);
    } catch (const json::out_of_range&) {  // its message would echo the whole number
        throw ParameterError("body", "the body holds a number too large for a double; it must be " + shape);
    }
    if (!document.is_object()) throw ParameterError("body", "the body must be " + shape);
    CameraKeysRequest request;
    const auto keys = document.find("keys");
    if (keys == document.end() || !keys->is_array() || keys->empty())
        throw ParameterError("keys", "keys must be a non-empty array of {\"eye\": [x, y, z], \"lookat\": [x, y, z]}");
    if (keys->size() > kMostCameraKeys)
        throw ParameterError("keys", "at most " + std::to_string(kMostCameraKeys) + " keys, got " + std::to_string(keys->size()));
    for (std::size_t i = 0; i < keys->size(); ++i) {
        const json& key = (*keys)[i];
        const std::string where = "keys[" + std::to_string(i) + "]";
        if (!key.is_object() || !key.contains("eye") || !key.contains("lookat"))
            throw ParameterError("keys", where + " must be {\"eye\": [x, y, z], \"lookat\": [x, y, z]}");
        request.keys.push_back({read_point(key["eye"], "keys", where + ".eye"), read_point(key["lookat"], "keys", where + ".lookat")});
    }
    if (const auto name = document.find("name"); name != document.end() && !name->is_null()) {
        if (!name->is_string()) throw ParameterError("name", "name must be a string");
        std::string text = name->get<std::string>();
        if (text.size() > 5 && text.compare(text.size() - 5, 5, ".json") == 0) text.resize(text.size() - 5);
        if (!is_plain_base_name(text))
            throw ParameterError("name", "name must be a plain file name without extension: letters, digits, '.', '_' "
                                         "and '-', starting with a letter or digit, at most 100");
        request.name = text;
    }
    if (const auto up = document.find("up"); up != document.end() && !up->is_null())
        request.up = read_point(*up, "up", "up");
    if (const auto fov = document.find("fov"); fov != document.end() && !fov->is_null()) {
        if (!fov->is_number() || !std::isfinite(fov->get<double>()))
            throw ParameterError("fov", "fov must be a finite number of degrees");
        request.fov_degrees = fov->get<double>();
    }
    return request;
}

}  // namespace clr
