// The whole forest as files: forest.json and the pictures it names, in one folder.
#pragma once

#include <filesystem>

#include "scripts/forest/forest_layout.h"

namespace forest {

// Draws the trees' views, the ground and the mountains, lays the forest out and writes the
// scene; the same options give the same bytes. Throws std::runtime_error on failure.
void write_forest(const ForestOptions& options, const std::filesystem::path& folder);

}  // namespace forest
