#pragma once

#include "phigs/store/Element.h"

namespace phigs {

/// An attribute index ISO 9592 refuses when the element is made, and the error it names.
struct IndexRange {
    int error = 0;  ///< 0: in range
    int value = 0;
};

/// Bundle indices from 1 (error 100), colour indices from 0 (113), view indices from 0 (114),
/// depth cue indices from 0 (119) and colour mapping indices from 0 (121): what INSERT refuses,
/// and so what a retrieved archive may not hold. Other indices (linetype, font, the interior
/// style index, which is also a hatch index, ...) are checked against the workstation when drawn.
IndexRange indexRangeError(const Element& e);

}  // namespace phigs
