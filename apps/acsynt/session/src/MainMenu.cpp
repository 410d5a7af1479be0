// MAIN: opens the submenus, UNDO and REDO, EXIT.
#include "acsynt/session/MainMenu.h"

#include "acsynt/session/CurveMapMenu.h"
#include "acsynt/session/FileMenu.h"
#include "acsynt/session/MenuContext.h"
#include "acsynt/session/ModelsMenu.h"
#include "acsynt/session/ReductionMenu.h"
#include "acsynt/session/ViewMenu.h"

namespace acsynt {

namespace {

void open(MenuContext& s, const MenuTable& menu) {
    s.openMenu(menu);
    s.say("SELECT MENU ITEM");
}

/// CURVE_MAP and SURF_REDN work on the current model.
void openWithModel(MenuContext& s, const MenuTable& menu) {
    if (s.requireModel()) open(s, menu);
}

}  // namespace

void returnToMain(MenuContext& s) {
    open(s, mainMenuTable());
}

const MenuTable& mainMenuTable() {
    static const MenuTable table{
        "MAIN",
        "MAIN",
        {
            {"FILE", "reading and writing models, curves, archives and hardcopies",
             [](MenuContext& s, const std::string&) { open(s, fileMenuTable()); }},
            {"VIEW", "one or four views, shading, hulls, centre and reset",
             [](MenuContext& s, const std::string&) { open(s, viewMenuTable()); }},
            {"CURVE_MAP", "maps a plane curve onto a component (needs a model)",
             [](MenuContext& s, const std::string&) { openWithModel(s, curveMapMenuTable()); }},
            {"SURF_REDN", "data reduction of a component's surface (needs a model)",
             [](MenuContext& s, const std::string&) { openWithModel(s, reductionMenuTable()); }},
            {"MODELS", "the loaded models: next, previous, list, name, delete",
             [](MenuContext& s, const std::string&) { open(s, modelsMenuTable()); }},
            {"UNDO", "takes back the last model change",
             [](MenuContext& s, const std::string&) { s.undo(); }},
            {"REDO", "makes an undone change again", [](MenuContext& s, const std::string&) { s.redo(); }},
            {"EXIT", "ends the session",
             [](MenuContext& s, const std::string&) {
                 s.say("EXIT");
                 s.core().finished = true;
             }},
        }};
    return table;
}

}  // namespace acsynt
