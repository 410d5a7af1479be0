#pragma once

#include "acsynt/session/MenuTable.h"

namespace acsynt {

/// VIEW: one or four views, shading, hulls, the views' centre and reset.
const MenuTable& viewMenuTable();

}  // namespace acsynt
