#pragma once

#include "StoreBuffer.h"
#include "phigs/store/Element.h"

namespace phigs::c {

/// Implementation error: the element (a PHIGS PLUS surface, mesh or lighting attribute) has no
/// Pelem_data form in this part of the binding; its type and size are still answered.
inline constexpr int kNoContentForm = -205;

/// Writes `element`'s contents into `store` (replacing what it held); 0 or kNoContentForm.
int fillContent(const Element& element, Phigs_store& store);

}  // namespace phigs::c
