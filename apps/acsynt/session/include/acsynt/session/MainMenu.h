#pragma once

#include "acsynt/session/MenuTable.h"

namespace acsynt {

/// MAIN: the top menu (FILE, VIEW, CURVE_MAP, SURF_REDN, MODELS, UNDO, REDO, EXIT).
const MenuTable& mainMenuTable();

/// RETURN of a submenu: back to MAIN, SELECT MENU ITEM.
void returnToMain(MenuContext& session);

}  // namespace acsynt
