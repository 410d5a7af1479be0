#pragma once

#include "acsynt/session/MenuTable.h"

namespace acsynt {

/// CURVE MAP: the curve, DEFINE POINT, its flip and rotation, MAP PREVIEW and MAP CURVE.
const MenuTable& curveMapMenuTable();

}  // namespace acsynt
