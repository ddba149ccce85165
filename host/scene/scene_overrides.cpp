#include "scene/scene_overrides.h"

#include <cstdlib>

#include "core/errors.h"
#include "core/printable_text.h"

namespace clr {
namespace {

[[noreturn]] void refuse(const std::string& argument, const std::string& problem) {
    throw UsageError(printable("-D " + shortened(argument, kLongestDetail) + ": " + problem));
}

// RFC 6901: "~1" is '/', "~0" is '~'.
std::string unescape_pointer_token(const std::string& token, const std::string& argument) {
    std::string key;
    for (std::size_t i = 0; i < token.size(); ++i) {
        if (token[i] != '~') {
            key += token[i];
        } else if (i + 1 < token.size() && (token[i + 1] == '0' || token[i + 1] == '1')) {
            key += token[++i] == '0' ? '~' : '/';
        } else {
            refuse(argument, "'~' in a JSON pointer must be followed by 0 or 1 (~0 is '~', ~1 is '/')");
        }
    }
    return key;
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t at; (at = text.find(separator, start)) != std::string::npos; start = at + 1)
        parts.push_back(text.substr(start, at - start));
    parts.push_back(text.substr(start));
    return parts;
}

std::vector<std::string> parse_key(const std::string& key, const std::string& argument) {
    if (key.empty() || key == "/") refuse(argument, "the key is empty; write -D key=value, e.g. -D MaxDepth=2");
    if (key.front() != '/') {
        std::vector<std::string> path = split(key, '.');
        for (const std::string& part : path)
            if (part.empty()) refuse(argument, "a dotted key has an empty part; e.g. -D spheres.0.radius=2");
        return path;
    }
    std::vector<std::string> path;
    for (const std::string& token : split(key.substr(1), '/')) path.push_back(unescape_pointer_token(token, argument));
    return path;
}

std::string pointer_of(const std::vector<std::string>& path, std::size_t length) {
    std::string pointer;
    for (std::size_t i = 0; i < length; ++i) pointer += "/" + json_pointer_token(path[i]);
    return pointer;
}

// An array index as RFC 6901 writes it: digits, no leading zero.
bool is_array_index(const std::string& token) {
    if (token.empty() || token.size() > 9 || (token.size() > 1 && token[0] == '0')) return false;
    for (char c : token)
        if (c < '0' || c > '9') return false;
    return true;
}

std::string type_name(const Json& value) {
    switch (value.type()) {
        case Json::value_t::null: return "null";
        case Json::value_t::boolean: return "a boolean";
        case Json::value_t::string: return "a string";
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float: return "a number";
        default: return "not a container";
    }
}

// The element `token` names in `container` (an array), with "-" appending one when it is the
// last step.
Json& array_element(Json& container, const std::string& token, bool last, const SceneOverride& set, std::size_t depth) {
    if (last && token == "-") {
        container.push_back(nullptr);
        return container.back();
    }
    if (!is_array_index(token))
        refuse(set.argument, pointer_of(set.path, depth) + " is an array; '" + token + "' is not an index into it");
    const std::size_t index = std::strtoul(token.c_str(), nullptr, 10);
    if (index >= container.size()) {
        refuse(set.argument, pointer_of(set.path, depth) + " has " + std::to_string(container.size()) +
                                 (container.size() == 1 ? " element" : " elements") + ", so there is no element " +
                                 token + (last ? " (\"-\" adds one at the end)" : ""));
    }
    return container[index];
}

bool starts_as_array_or_object(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    return first != std::string::npos && (text[first] == '[' || text[first] == '{');
}

void apply(Json& document, const SceneOverride& set) {
    Json* value = &document;
    for (std::size_t depth = 0; depth < set.path.size(); ++depth) {
        const std::string& token = set.path[depth];
        const bool last = depth + 1 == set.path.size();
        if (value->is_object()) {
            Json& member = (*value)[token];
            if (member.is_null() && !last) {
                // An object is made on the way; an array is not: its elements do not exist.
                const std::string& next = set.path[depth + 1];
                if (is_array_index(next) || next == "-")
                    refuse(set.argument, pointer_of(set.path, depth + 1) + " does not exist, so it has no element " + next);
                member = Json::object();
            }
            value = &member;
        } else if (value->is_array()) {
            value = &array_element(*value, token, last, set, depth);
        } else {
            refuse(set.argument, pointer_of(set.path, depth) + " is " + type_name(*value) +
                                     ", not an object or array, so it has no '" + token + "'");
        }
    }
    *value = set.value;
}

}  // namespace

SceneOverride parse_scene_override(const std::string& argument) {
    const std::size_t equals = argument.find('=');
    if (equals == std::string::npos)
        refuse(argument, "expected key=value, e.g. -D MaxDepth=2 or -D /spheres/0/radius=2");
    SceneOverride set;
    set.argument = argument;
    set.path = parse_key(argument.substr(0, equals), argument);
    const std::string text = argument.substr(equals + 1);
    const std::string pointer = pointer_of(set.path, set.path.size());
    // Warnings about the value name its place in the scene and this argument, as the loader's do.
    Diagnostics diagnostics{"", &set.warnings};
    diagnostics.overridden = {{pointer, argument}};
    JsonArgument parsed = parse_json_argument(text, pointer, diagnostics);
    if (parsed.value) {
        set.value = std::move(*parsed.value);
    } else if (parsed.out_of_range) {
        refuse(argument, parsed.problem_location + ": " + parsed.problem);
    } else if (starts_as_array_or_object(text)) {
        // Meant as JSON: a string of "[0, 0" would only fail later as the wrong type.
        refuse(argument, parsed.problem_location + ": the value is not valid JSON (" + parsed.problem +
                             "); quote text that starts with '[' or '{' as a JSON string, e.g. -D 'key=\"[a].png\"'");
    } else {
        set.value = text;  // not JSON: the text as a string
    }
    return set;
}

std::vector<std::pair<std::string, std::string>> apply_scene_overrides(Json& document,
                                                                      const std::vector<SceneOverride>& overrides) {
    std::vector<std::pair<std::string, std::string>> applied;
    for (const SceneOverride& set : overrides) {
        apply(document, set);
        applied.emplace_back(pointer_of(set.path, set.path.size()), set.argument);
    }
    return applied;
}

}  // namespace clr
