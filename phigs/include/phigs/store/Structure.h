#pragma once

#include "phigs/store/ElementArena.h"

#include <cstdint>

namespace phigs {

/// One structure of the central structure store: its elements (element n is elements' n - 1:
/// compact, each with a serial unique in the store's lifetime that changes whenever the element
/// is inserted or replaced, which caches key on) and a version that changes on every edit.
struct Structure {
    int id = 0;
    ElementArena elements;
    std::uint64_t version = 0;
};

}  // namespace phigs
