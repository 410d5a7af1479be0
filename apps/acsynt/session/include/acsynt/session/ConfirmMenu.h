#pragma once

#include "acsynt/session/MenuTable.h"

namespace acsynt {

/// DEFINE POINT's ACCEPT or REJECT of the picked reference patch (titled CURVE MAP).
const MenuTable& confirmMenuTable();

}  // namespace acsynt
