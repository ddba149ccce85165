// How much memory clrender lets the data that grows with a scene take before it refuses the run
// with exit 6 and the figures, rather than meet the system's out-of-memory killer part-way
// through: the screen tiles of a frame (render/tile_lists.h) and a scene's meshes
// (scene/mesh_loader.h) each may take half of the machine's physical memory
// (docs/robustness.md, Memory).
#pragma once

#include <cstdint>
#include <string>

namespace clr {

// Half of this machine's physical memory; no limit where the system does not say.
std::uint64_t default_memory_budget();

// `bytes` in GiB with one decimal, for messages ("10.4 GiB").
std::string gib_text(std::uint64_t bytes);

}  // namespace clr
