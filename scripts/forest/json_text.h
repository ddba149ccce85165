// Scene JSON laid out for people: nested objects open up, but each element of a list of
// objects (a tree, a boulder, a view) stays on one line, so 3000 trees are 3000 lines.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace forest {

std::string scene_text(const nlohmann::ordered_json& scene);

}  // namespace forest
