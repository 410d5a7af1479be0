// SURF_REDN: the reduction's mode and direction (a pick then chooses the component, a prompt
// the tolerance or count), the error map of the last reduction and its scale.
#include "acsynt/session/ReductionMenu.h"

#include "acsynt/session/MainMenu.h"
#include "acsynt/session/MenuContext.h"

namespace acsynt {

namespace {

using Phase = SessionCore::Phase;

void returnFromReduction(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    if (c.phase == Phase::SelectReduction) c.phase = Phase::None;
    returnToMain(s);
}

void setMode(MenuContext& s, const std::string& name) {
    SessionCore& c = s.core();
    c.reductionByCount = name == "BY_COUNT";
    s.say(c.reductionByCount ? "REDUCTION BY NUMBER OF KNOTS" : "REDUCTION TO A TOLERANCE");
}

void reduceIn(MenuContext& s, const std::string& name) {
    SessionCore& c = s.core();
    c.reductionDirection = name == "REDUCE_U" ? "U" : name == "REDUCE_W" ? "W" : "U&W";
    c.phase = Phase::SelectReduction;
    s.say("SELECT COMPONENT TO REDUCE");
}

void errorMap(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    const ReductionRecord* shown = c.shownReduction();
    if (!shown) {
        s.fail("NO REDUCTION OF THE CURRENT MODEL TO SHOW");
        return;
    }
    c.style.errorMapComponent = c.style.errorMapComponent < 0 ? shown->componentIndex : -1;
    s.drawErrorMap();
    s.restyle();
    s.say(c.style.errorMapComponent >= 0 ? c.errorMapLine() : "ERROR MAP OFF");
}

}  // namespace

const MenuTable& reductionMenuTable() {
    static const MenuTable table{
        "SURF_REDN",
        "SURF_REDN",
        {
            {"RETURN", "back to MAIN", returnFromReduction},
            {"REDUCE_U", "reduces a picked component across its sections (u)", reduceIn},
            {"REDUCE_W", "reduces a picked component round its sections (w)", reduceIn},
            {"REDUCE_U&W", "reduces a picked component in u and w", reduceIn},
            {"BY_TOLERANCE", "the next reduction keeps within a tolerance", setMode},
            {"BY_COUNT", "the next reduction removes a number of knots", setMode},
            {"ERROR_MAP", "shows or hides the last reduction's error and its legend", errorMap},
            {"ERROR_SCALE", "the error map's scale: a length (fixed) or RELATIVE",
             [](MenuContext& s, const std::string&) {
                 s.prompt("ENTER ERROR MAP SCALE: A LENGTH (RED AT IT, FIXED) OR RELATIVE",
                          SessionCore::Awaiting::ErrorScale);
             }},
        },
        false,
        true};
    return table;
}

}  // namespace acsynt
