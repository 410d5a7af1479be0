#pragma once

#include "acsynt/session/MenuTable.h"

namespace acsynt {

/// MODELS: the loaded models (next, previous, list, name, delete).
const MenuTable& modelsMenuTable();

}  // namespace acsynt
