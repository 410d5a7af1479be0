#pragma once

#include "acsynt/session/MenuTable.h"

namespace acsynt {

/// SURF_REDN: the reduction's direction and mode, the error map and its scale.
const MenuTable& reductionMenuTable();

}  // namespace acsynt
