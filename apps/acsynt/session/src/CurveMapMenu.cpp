// CURVE MAP: the curve to map, DEFINE POINT (its picks and pad are input, its ACCEPT / REJECT
// the confirm menu), the curve's flip and rotation, MAP PREVIEW, MAP CURVE, DISPLAY ALL.
#include "acsynt/session/CurveMapMenu.h"

#include "acsynt/session/MainMenu.h"
#include "acsynt/session/MenuContext.h"

namespace acsynt {

namespace {

using Phase = SessionCore::Phase;

void clearHighlights(SessionCore& c) {
    c.style.onlyComponent = c.style.colourfulComponent = c.style.highlightComponent = -1;
}

void returnFromCurveMap(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    if (c.phase != Phase::Placed) {
        // An unfinished DEFINE POINT is abandoned; a placed reference point is kept.
        c.phase = Phase::None;
        c.reference.reset();
        clearHighlights(c);
        if (!c.models.empty()) s.restyle();
        s.drawOverlay();
    }
    returnToMain(s);
}

void definePoint(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    c.phase = Phase::SelectComponent;
    c.reference.reset();
    c.previewLines.clear();
    c.previewClipped.clear();
    c.previewLost.clear();
    clearHighlights(c);
    s.restyle();
    s.drawOverlay();
    s.say("SELECT COMPONENT FOR MAPPING");
}

void flipCurve(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    c.remember(c.state(), "FLIP CURVE");
    c.placement.flipped = !c.placement.flipped;
    c.mappedSincePlaced = false;
    s.drawOverlay();
    s.say(c.placement.flipped ? "CURVE FLIPPED" : "CURVE UNFLIPPED");
}

void rotateCurve(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    c.remember(c.state(), "ROTATE CURVE");
    c.placement.quarterTurns = (c.placement.quarterTurns + 1) % 4;
    c.mappedSincePlaced = false;
    s.drawOverlay();
    s.say("CURVE ROTATED TO " + std::to_string(90 * c.placement.quarterTurns) + " DEGREES");
}

void displayAll(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    clearHighlights(c);
    s.restyle();
    s.drawMapped(true);
    std::size_t n = 0;
    for (const auto& m : c.mappings) n += m.model == c.models.current().name;
    s.say("DISPLAYING " + std::to_string(n) + " MAPPED CURVES");
}

}  // namespace

const MenuTable& curveMapMenuTable() {
    static const MenuTable table{
        "CURVE MAP",
        "CURVE MAP",
        {
            {"RETURN", "back to MAIN (an unfinished DEFINE POINT is abandoned)", returnFromCurveMap},
            {"LOAD_CURVE", "loads a .crv curve, FILE [SCALE]",
             [](MenuContext& s, const std::string&) {
                 s.prompt("ENTER CURVE FILE NAME [SCALE]", SessionCore::Awaiting::CurveFile);
             }},
            {"DEFINE_POINT", "picks a component and patch and places the reference point", definePoint},
            {"FLIP_CURVE", "mirrors the placed curve", flipCurve},
            {"ROTATE_CURVE", "turns the placed curve by 90 degrees", rotateCurve},
            {"MAP_PREVIEW", "draws the projection of every part, clipped and lost ones marked",
             [](MenuContext& s, const std::string&) { s.mapCurve(true); }},
            {"MAP_CURVE", "maps every part of the curve onto the component",
             [](MenuContext& s, const std::string&) { s.mapCurve(false); }},
            {"DISPLAY_ALL", "shows every curve mapped on the current model", displayAll},
        },
        false,
        true};
    return table;
}

}  // namespace acsynt
