// Reading JSON with every value's location at hand, so that each scene error and warning
// names the JSON pointer (e.g. "/spheres/3/radius") a user has to fix. The scene loader
// uses it; it knows nothing of scenes itself.
#pragma once

#include <cstddef>
#include <map>
#include <utility>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/vec3.h"

namespace clr {

using Json = nlohmann::json;

// Where problems go: errors become SceneErrors naming `file`, warnings are appended to
// `warnings` as "LOCATION: message". Past kMostWarnings, warnings are only counted (a file
// of a million unknown keys would otherwise print a million lines and hold them all in
// memory first); summarise_warnings() then adds one line that counts them.
struct Diagnostics {
    static constexpr std::size_t kMostWarnings = 100;

    std::string file;
    std::vector<std::string>* warnings = nullptr;
    mutable std::size_t unshown_warnings = 0;
    // Values set on the command line (-D): the JSON pointer of each and the argument that
    // set it. An error or warning about a value at or under one says so.
    std::vector<std::pair<std::string, std::string>> overridden = {};

    [[noreturn]] void fail(const std::string& location, const std::string& detail) const;
    void warn(const std::string& location, const std::string& message) const;
    void summarise_warnings() const;
    // " (set on the command line: -D ARG)" when a -D set the value at `location`, else "".
    std::string origin_of(const std::string& location) const;
};

// Parses UTF-8 JSON text (a leading BOM, CRLF line endings and // or /* */ comments are
// accepted; UTF-16 and UTF-32 text is refused with a message that names the encoding). A syntax error, or a number too large for a double, becomes a SceneError whose
// detail starts with "line L, column C:". A key repeated within one object is a warning
// (the last value is used, as in most JSON readers); past the first ten, one warning counts them.
Json parse_json_text(const std::string& text, const Diagnostics& diagnostics);

// One JSON value given on the command line (-D KEY=VALUE), for the value at `base` (a JSON
// pointer) in the scene. A key repeated within an object is a warning at its location, as in a
// file; comments are not JSON here (a '/' starts a file name more often than a comment).
struct JsonArgument {
    std::optional<Json> value;     // nullopt when the text is not JSON; then:
    std::string problem_location;  // the JSON pointer of the value that was being read
    std::string problem;           // "column C: why", for a message
    bool out_of_range = false;     // JSON but for a number too large for a double (1e400)
};
JsonArgument parse_json_argument(const std::string& text, const std::string& base, const Diagnostics& diagnostics);

// One JSON value with its location and a short label for messages ("radius", "eye[1]").
// The typed readers throw a SceneError at the value's location when the value does not fit.
class Node {
public:
    Node(const Json& value, std::string location, std::string label, const Diagnostics& diagnostics);

    const Json& json() const { return *value_; }
    const std::string& location() const { return location_; }
    const std::string& label() const { return label_; }
    const Diagnostics& diagnostics() const { return *diagnostics_; }

    [[noreturn]] void fail(const std::string& detail) const { diagnostics_->fail(location_, detail); }
    void warn(const std::string& message) const { diagnostics_->warn(location_, message); }

    Node member(const std::string& key) const;  // the value must be an object holding `key`
    std::vector<Node> elements() const;         // the value must be an array

    double number() const;  // any finite number
    // A number with an integral value (600 and 600.0 both do) in [min, max].
    long long integer(long long min, long long max) const;
    bool flag() const;  // 0, 1, false or true
    std::string string() const;
    // Exactly three finite numbers; `shape` names them in messages, e.g. "[x, y, z]".
    Vec3 vec3(const char* shape = "[x, y, z]") const;
    Vec3 color() const { return vec3("[r, g, b]"); }

    // A value for messages: numbers and short strings as written, others by their type.
    std::string shown() const;

private:
    [[noreturn]] void fail_type(const std::string& expected) const;

    const Json* value_;
    std::string location_;
    std::string label_;
    const Diagnostics* diagnostics_;
};

// Reads one JSON object member by member, and warns about the members nobody asked for:
// a misspelt key must not pass silently. Call warn_about_unknown_keys() once, last.
class ObjectReader {
public:
    // `what` names the object in messages ("sphere", "scene"). Fails unless `node` is an object.
    ObjectReader(const Node& node, std::string what);

    const Node& node() const { return node_; }
    bool has(const std::string& key);  // also marks `key` as known
    std::optional<Node> optional(const std::string& key);
    // Fails at the object's location when `key` is missing; `hint` is added to the message.
    Node required(const std::string& key, const std::string& hint = "");
    // A key this reader recognises but does not use: if present, warns with `message`.
    void note_ignored(const std::string& key, const std::string& message);
    // One warning for each member not asked for, suggesting a known key of similar spelling,
    // or the hint given for it.
    void warn_about_unknown_keys() const;
    // For keys people write by mistake where the right key is spelt too differently for a
    // suggestion ("fov" for "fov_angle"), or belongs elsewhere ("spp" under "clrender"): an
    // unknown key among `likely_mistakes` (ignoring case) is warned about with `hint`, and
    // an error that `right_key` is missing names it. Give hints before reading keys.
    void hint(const std::vector<std::string>& likely_mistakes, const std::string& right_key, const std::string& hint);
    // " (it has 'fov': did you mean 'fov_angle'?)" when the object holds a likely mistake for
    // `right_key`, else "": for errors about a missing key.
    std::string mistake_note(const std::string& right_key) const;

private:
    struct Hint {
        std::string right_key;
        std::string text;
    };

    std::string suggestion_for(const std::string& unknown_key) const;

    Node node_;
    std::string what_;
    std::set<std::string> known_keys_;
    std::map<std::string, Hint> hints_;  // by the mistaken key in lower case
};

// `text` with ASCII letters in lower case.
std::string lowercase_ascii(std::string text);

// A key as a JSON pointer reference token ("~" -> "~0", "/" -> "~1", RFC 6901).
std::string json_pointer_token(const std::string& key);

}  // namespace clr
