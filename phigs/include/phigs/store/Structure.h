#pragma once

#include "phigs/store/Element.h"

#include <cstdint>
#include <vector>

namespace phigs {

/// An element as the store keeps it: the value and a serial number unique in the store's
/// lifetime, which changes whenever the element is inserted or replaced (caches key on it).
struct StoredElement {
    Element value;
    std::uint64_t serial = 0;
};

/// One structure of the central structure store: its elements (element n is elements[n - 1])
/// and a version that changes on every edit of the structure.
struct Structure {
    int id = 0;
    std::vector<StoredElement> elements;
    std::uint64_t version = 0;
};

}  // namespace phigs
