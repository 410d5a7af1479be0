#pragma once

#include <string>
#include <vector>

namespace acsynt {

class MenuContext;

/// One command of a menu: its name as `choice NAME` takes it, a line of help, what it does.
struct MenuCommand {
    /// Runs the command (`name` is its own, for handlers several commands share).
    using Handler = void (*)(MenuContext& session, const std::string& name);
    std::string name;
    std::string help;
    Handler run = nullptr;
};

/// A menu as a table of commands in panel order, and the dispatcher that runs one of them.
struct MenuTable {
    std::string name;   ///< as COMMANDS.md lists it (unique)
    std::string title;  ///< as the screen's heading shows it
    std::vector<MenuCommand> commands;
    /// Choosing here leaves an open prompt open (ACCEPT / REJECT); other menus withdraw it.
    bool keepsPrompt = false;
    /// The menu works on the current model: an UNDO or REDO that leaves none goes back to MAIN.
    bool needsModel = false;

    /// The command named `command`, or null.
    const MenuCommand* find(const std::string& command) const;
    /// The commands' names, the panel's rows.
    std::vector<std::string> names() const;
    /// Runs `command`; one this menu has not fails with a message naming it and the menu.
    void dispatch(const std::string& command, MenuContext& session) const;
};

/// Every menu's table, MAIN first.
const std::vector<const MenuTable*>& menuTables();

}  // namespace acsynt
