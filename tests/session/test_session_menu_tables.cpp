// The menus as tables of commands: each table against COMMANDS.md, the dispatcher on a stub
// session, and every command of every table run once in a headless session (no picture: the
// workstation draws nothing, picks use its draw list).
#include "SessionTestSupport.h"

#include "acsynt/session/ConfirmMenu.h"
#include "acsynt/session/FileMenu.h"
#include "acsynt/session/MainMenu.h"
#include "acsynt/session/MenuContext.h"
#include "acsynt/session/MenuTable.h"
#include "acsynt/session/ViewMenu.h"
#include "geom/Evaluate.h"

#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace test_session_menu_tables {

namespace {

std::string trimmed(const std::string& s) {
    const auto first = s.find_first_not_of(' ');
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(' ') - first + 1);
}

/// Text before " (": a cell's name or list without its remark.
std::string withoutRemark(const std::string& s) {
    return trimmed(s.substr(0, s.find(" (")));
}

/// COMMANDS.md's menu table: each menu's name and its items in order.
std::map<std::string, std::vector<std::string>> documentedMenus() {
    const auto path = std::filesystem::path(PHIGS_TEST_DATA_DIR).parent_path().parent_path() / "apps" /
                      "acsynt" / "COMMANDS.md";
    std::ifstream in(path);
    REQUIRE(in);
    std::map<std::string, std::vector<std::string>> menus;
    std::string line;
    while (std::getline(in, line) && line.rfind("| Menu | Items |", 0) != 0) {
    }
    std::getline(in, line);  // |---|---|
    while (std::getline(in, line) && line.rfind("|", 0) == 0) {
        std::vector<std::string> cells;
        std::istringstream row(line.substr(1));
        for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
        REQUIRE(cells.size() >= 2);
        std::vector<std::string> items;
        std::istringstream list(withoutRemark(cells[1]));
        for (std::string item; std::getline(list, item, ',');) items.push_back(trimmed(item));
        menus[withoutRemark(cells[0])] = items;
    }
    return menus;
}

/// A session stand-in that keeps the core and notes the screen operations asked for.
class StubSession : public acsynt::MenuContext {
public:
    acsynt::SessionCore& core() override { return state; }
    void say(const std::string& text) override { state.say(text); }
    void fail(const std::string& text) override { state.fail(text); }
    void prompt(const std::string& text, acsynt::SessionCore::Awaiting what) override {
        state.awaiting = what;
        say(text);
    }
    bool requireModel() override { return !state.models.empty(); }
    void openMenu(const acsynt::MenuTable& menu) override { calls.push_back("open " + menu.name); }
    void restyle() override { calls.push_back("restyle"); }
    void showModel() override { calls.push_back("showModel"); }
    void updateViews() override { calls.push_back("updateViews"); }
    void drawOverlay() override { calls.push_back("drawOverlay"); }
    void drawMapped(bool) override { calls.push_back("drawMapped"); }
    void drawErrorMap() override { calls.push_back("drawErrorMap"); }
    void mapCurve(bool) override { calls.push_back("mapCurve"); }
    void undo() override { calls.push_back("undo"); }
    void redo() override { calls.push_back("redo"); }

    acsynt::SessionCore state;
    std::vector<std::string> calls;
};

/// A session with no picture on the small screen, the fuzz targets' small model loaded.
struct Headless {
    Headless() : session(settings(), source) {
        run({"choice FILE", "choice READ_MODEL", "string small.acm", "choice RETURN"});
        REQUIRE(session.models().size() == 1);
    }
    static acsynt::SessionSettings settings() {
        acsynt::SessionSettings s;
        s.width = session_test::width;
        s.height = session_test::height;
        s.outputDirectory = session_test::outputDirectory("menu_tables");
        s.searchPath.push_back(std::filesystem::path(PHIGS_TEST_DATA_DIR).parent_path() / "fuzz" / "data");
        return s;
    }
    void run(std::initializer_list<std::string> lines) {
        for (const std::string& line : lines) {
            source.push(line);
            while (!source.empty() && session.step(std::chrono::milliseconds(0))) {
            }
        }
    }
    /// DEFINE POINT's two picks, on the first patch of the model that shows in the view.
    void pickPatch() {
        for (const acsynt::Component& c : session.models().current().components)
            for (const acsynt::Patch& p : c.patches.patches) {
                const glm::dvec3 at = geom::evaluate(c.surface, (p.u0 + p.u1) / 2, (p.w0 + p.w1) / 2);
                const glm::dvec2 pixel = session.pixelOf(at, 1);
                const std::string line = "pick " + std::to_string(pixel.x) + " " + std::to_string(pixel.y);
                run({line});
                if (session.message() != "SELECT REFERENCE PATCH TO MAP") continue;
                run({line});
                REQUIRE(session.message() == "ACCEPT OR REJECT PATCH");
                return;
            }
        FAIL("no patch of the model could be picked");
    }
    /// From any menu back to MAIN.
    void toMain() {
        for (int i = 0; i < 4 && !session.finished() && session.menuTitle() != "MAIN"; ++i) {
            const auto& items = session.menuItems();
            const bool hasReturn = std::find(items.begin(), items.end(), "RETURN") != items.end();
            run({hasReturn ? "choice RETURN" : "choice REJECT"});
        }
        REQUIRE((session.finished() || session.menuTitle() == "MAIN"));
    }
    /// From MAIN to the menu `table`.
    void open(const acsynt::MenuTable& table) {
        if (table.name == "CONFIRM") {
            run({"choice CURVE_MAP", "choice DEFINE_POINT"});
            pickPatch();
        } else if (table.name != "MAIN") {
            run({"choice " + std::string(table.name == "CURVE MAP" ? "CURVE_MAP" : table.name)});
        }
        REQUIRE(session.menuTitle() == table.title);
        REQUIRE(session.menuItems() == table.names());
    }

    session_test::LineSource source;
    acsynt::Session session;
};

}  // namespace

TEST_CASE("menu tables: each command named once, with help, and listed in COMMANDS.md") {
    const auto documented = documentedMenus();
    std::set<std::string> tableNames;
    for (const acsynt::MenuTable* table : acsynt::menuTables()) {
        INFO("menu " << table->name);
        CHECK(tableNames.insert(table->name).second);
        CHECK(!table->title.empty());
        std::set<std::string> names;
        for (const acsynt::MenuCommand& c : table->commands) {
            INFO("command " << c.name);
            CHECK(!c.name.empty());
            CHECK(c.name.find(' ') == std::string::npos);  // `choice NAME` takes one word
            CHECK(names.insert(c.name).second);
            CHECK(!trimmed(c.help).empty());
            CHECK(c.help.find('\n') == std::string::npos);
            CHECK(c.run != nullptr);
        }
        // The panel's rows in COMMANDS.md's order (`choice N` counts them).
        const auto it = documented.find(table->name);
        REQUIRE(it != documented.end());
        CHECK(it->second == table->names());
    }
    for (const auto& [name, items] : documented) {
        INFO("COMMANDS.md lists menu " << name);
        CHECK(tableNames.count(name) == 1);
    }
}

TEST_CASE("menu tables: the dispatcher runs a command and refuses one the menu lacks") {
    StubSession s;
    acsynt::fileMenuTable().dispatch("READ_MODEL", s);
    CHECK(s.state.awaiting == acsynt::SessionCore::Awaiting::ModelFile);
    CHECK(s.state.message == "ENTER MODEL FILE NAME");
    // Another menu's choice withdraws the prompt; ACCEPT / REJECT leave it while confirming.
    s.state.phase = acsynt::SessionCore::Phase::AcceptReject;
    s.state.pickedComponent = 0;
    acsynt::confirmMenuTable().dispatch("REJECT", s);
    CHECK(s.state.awaiting == acsynt::SessionCore::Awaiting::ModelFile);
    CHECK(s.state.phase == acsynt::SessionCore::Phase::SelectPatch);
    CHECK(s.calls == std::vector<std::string>{"restyle", "open CURVE MAP"});
    acsynt::viewMenuTable().dispatch("HULL_ON", s);
    CHECK(s.state.awaiting == acsynt::SessionCore::Awaiting::Nothing);
    CHECK(s.state.style.hull);
    CHECK(s.state.message == "HULL ON DONE");
    CHECK(s.state.failedLines == 0);

    acsynt::mainMenuTable().dispatch("READ_MODEL", s);
    CHECK(s.state.message == "MENU MAIN HAS NO COMMAND 'READ_MODEL'");
    CHECK(s.state.log.back() == "ERROR: MENU MAIN HAS NO COMMAND 'READ_MODEL'");
    CHECK(s.state.failedLines == 1);
}

TEST_CASE("menu tables: every command of every menu answers when chosen from the panel") {
    std::size_t commands = 0;
    for (const acsynt::MenuTable* table : acsynt::menuTables()) {
        auto h = std::make_unique<Headless>();
        for (const acsynt::MenuCommand& c : table->commands) {
            INFO("menu " << table->name << ", command " << c.name);
            if (h->session.finished()) h = std::make_unique<Headless>();  // after an EXIT
            h->toMain();
            h->open(*table);
            const std::size_t before = h->session.log().size();
            h->run({"choice " + c.name});
            // The choice is logged, and the command answers: a message, a prompt or an error.
            REQUIRE(h->session.log().size() >= before + 2);
            CHECK(h->session.log()[before] == "choice " + c.name);
            CHECK(!h->session.log()[before + 1].empty());
            ++commands;
        }
    }
    CHECK(commands == 51);
}

}  // namespace test_session_menu_tables
