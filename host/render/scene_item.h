// How screen tiles and BVH leaves name an object to the kernels: a scene item, the object's
// kind (CLR_HIT_*) above its index among the objects of that kind (CLR_ITEM_KIND_BITS,
// kernels/shared/clr_types.h; the kernels read it with kernels/common/scene_items.cl).
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "shared/clr_types.h"

namespace clr {

// The item of object `index` of kind `kind`. An index that does not fit the item's index bits
// would name another object: a scene file cannot describe that many, so it is a bug.
inline std::uint32_t scene_item(int kind, std::size_t index) {
    if (index > CLR_ITEM_INDEX_MASK || kind <= CLR_HIT_NONE || kind >= (1 << CLR_ITEM_KIND_BITS))
        throw std::length_error("scene item of kind " + std::to_string(kind) + " and index " + std::to_string(index) +
                                " does not fit in 32 bits");
    return static_cast<std::uint32_t>(kind) << CLR_ITEM_INDEX_BITS | static_cast<std::uint32_t>(index);
}

inline int scene_item_kind(std::uint32_t item) { return static_cast<int>(item >> CLR_ITEM_INDEX_BITS); }
inline std::uint32_t scene_item_index(std::uint32_t item) { return item & CLR_ITEM_INDEX_MASK; }

}  // namespace clr
