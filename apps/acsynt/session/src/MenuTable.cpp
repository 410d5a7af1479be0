// Menu tables: look-up and dispatch of a chosen command, and the list of every menu.
#include "acsynt/session/MenuTable.h"

#include "acsynt/session/ConfirmMenu.h"
#include "acsynt/session/CurveMapMenu.h"
#include "acsynt/session/FileMenu.h"
#include "acsynt/session/MainMenu.h"
#include "acsynt/session/MenuContext.h"
#include "acsynt/session/ModelsMenu.h"
#include "acsynt/session/ReductionMenu.h"
#include "acsynt/session/ViewMenu.h"

namespace acsynt {

const MenuCommand* MenuTable::find(const std::string& command) const {
    for (const MenuCommand& c : commands)
        if (c.name == command) return &c;
    return nullptr;
}

std::vector<std::string> MenuTable::names() const {
    std::vector<std::string> out;
    for (const MenuCommand& c : commands) out.push_back(c.name);
    return out;
}

void MenuTable::dispatch(const std::string& command, MenuContext& session) const {
    if (!keepsPrompt) session.core().awaiting = SessionCore::Awaiting::Nothing;
    const MenuCommand* c = find(command);
    if (!c || !c->run) {
        session.fail("MENU " + name + " HAS NO COMMAND '" + command + "'");
        return;
    }
    c->run(session, c->name);
}

const std::vector<const MenuTable*>& menuTables() {
    static const std::vector<const MenuTable*> all{
        &mainMenuTable(),    &fileMenuTable(),      &viewMenuTable(),  &curveMapMenuTable(),
        &confirmMenuTable(), &reductionMenuTable(), &modelsMenuTable()};
    return all;
}

}  // namespace acsynt
