#pragma once

#include "acsynt/session/MenuTable.h"

namespace acsynt {

/// FILE: the prompts for the files a session reads and writes, and EXIT.
const MenuTable& fileMenuTable();

}  // namespace acsynt
