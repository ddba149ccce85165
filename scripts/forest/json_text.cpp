#include "scripts/forest/json_text.h"

namespace forest {

namespace {

bool is_list_of_objects(const nlohmann::ordered_json& value) {
    return value.is_array() && !value.empty() && value.front().is_object();
}

void write(std::string& out, const nlohmann::ordered_json& value, int depth) {
    const std::string indent(4 * (depth + 1), ' '), closing_indent(4 * depth, ' ');
    if (value.is_object() && !value.empty()) {
        out += "{\n";
        bool first = true;
        for (const auto& [key, item] : value.items()) {
            out += (first ? "" : ",\n") + indent + nlohmann::json(key).dump() + ": ";
            write(out, item, depth + 1);
            first = false;
        }
        out += "\n" + closing_indent + "}";
    } else if (is_list_of_objects(value)) {
        out += "[\n";
        for (std::size_t i = 0; i < value.size(); ++i) out += (i ? ",\n" : "") + indent + value[i].dump();
        out += "\n" + closing_indent + "]";
    } else {
        out += value.dump();
    }
}

}  // namespace

std::string scene_text(const nlohmann::ordered_json& scene) {
    std::string out;
    write(out, scene, 0);
    return out + "\n";
}

}  // namespace forest
