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

// Counts a body's JSON values (and object members) as it is read, building none, and stops past
// `most`: a tree of the body is about 24 times its bytes where they are empty arrays ("[],"),
// and the server reads 32 bodies at once, so that 32 bodies of 2 MiB sent together took the
// viewer 1.5 GB further (and it kept 1.1 GB of it once they were answered).
class ValueCounter : public nlohmann::json_sax<json> {
public:
    explicit ValueCounter(std::size_t most) : most_(most) {}
    bool too_many() const { return count_ > most_; }

    bool null() override { return one_more(); }
    bool boolean(bool) override { return one_more(); }
    bool number_integer(number_integer_t) override { return one_more(); }
    bool number_unsigned(number_unsigned_t) override { return one_more(); }
    bool number_float(number_float_t, const string_t&) override { return one_more(); }
    bool string(string_t&) override { return one_more(); }
    bool binary(binary_t&) override { return one_more(); }
    bool start_object(std::size_t) override { return one_more(); }
    bool key(string_t&) override { return one_more(); }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return one_more(); }
    bool end_array() override { return true; }
    // The parse that follows says what is wrong, as it always has.
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

private:
    bool one_more() { return ++count_ <= most_; }
    std::size_t most_;
    std::size_t count_ = 0;
};

}  // namespace

bool is_plain_base_name(const std::string& name) {
    static const std::regex plain(R"([A-Za-z0-9][A-Za-z0-9._-]{0,99})");
    return std::regex_match(name, plain);
}

CameraKeysRequest parse_camera_keys(const std::string& body) {
    const std::string shape = "a JSON object {\"keys\": [{\"eye\": [x, y, z], \"lookat\": [x, y, z]}, ...]}";
    // Refused before a tree is built: a body of kMostCameraKeys keys has fewer values and members
    // (11 a key: its object, two members, two arrays and six numbers), and a few more of its own.
    ValueCounter counter(kMostBodyValues);
    json::sax_parse(body, &counter);
    if (counter.too_many())
        throw ParameterError("body", "the body holds more than " + std::to_string(kMostBodyValues) +
                                         " JSON values; " + std::to_string(kMostCameraKeys) +
                                         " keys, the most an export takes, need fewer; it must be " + shape);
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
