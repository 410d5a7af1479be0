#pragma once

#include "phigs.h"
#include "phigs/store/Element.h"

namespace phigs::c {

/// The C binding's element type of a stored element: the colour attributes answer their index
/// form (PELEM_LINE_COLR_IND, ...) for an indexed colour and their general form otherwise.
Pelem_type cElementType(const Element& element);

/// Whether `type` is one of the Pelem_type values phigs.h names.
inline bool validElementType(int type) {
    return type >= PELEM_ALL && type <= PELEM_RENDERING_COLR_MODEL;
}

}  // namespace phigs::c
