// VIEW: each command changes the views or the model's style, then redraws and says so.
#include "acsynt/session/ViewMenu.h"

#include "SessionShared.h"

#include "acsynt/session/MainMenu.h"
#include "acsynt/session/MenuContext.h"
#include "geom/Evaluate.h"

namespace acsynt {

namespace {

using session_detail::shown;

/// Every VIEW command's end: the model restyled, the views updated, NAME DONE.
void changed(MenuContext& s, const std::string& name) {
    if (!s.core().models.empty()) s.restyle();
    s.updateViews();
    s.say(shown(name) + " DONE");
}

void setViews(MenuContext& s, const std::string& name) {
    s.core().fourViews = name == "FOUR_VIEWS";
    changed(s, name);
}

void setShaded(MenuContext& s, const std::string& name) {
    s.core().style.shaded = name == "SHADE";
    changed(s, name);
}

void setHull(MenuContext& s, const std::string& name) {
    s.core().style.hull = name == "HULL_ON";
    changed(s, name);
}

void centreOnMarker(MenuContext& s, const std::string& name) {
    SessionCore& c = s.core();
    if (!c.reference) {
        s.fail("NO REFERENCE POINT: USE DEFINE POINT FIRST");
        return;
    }
    const Component& comp = c.models.current().components[std::size_t(c.reference->component)];
    c.viewCentre = geom::evaluate(comp.surface, c.reference->u, c.reference->w);
    changed(s, name);
}

void resetView(MenuContext& s, const std::string& name) {
    SessionCore& c = s.core();
    c.azimuth = -135;
    c.elevation = 25;
    c.zoom = 1;
    c.viewCentre.reset();
    changed(s, name);
}

}  // namespace

const MenuTable& viewMenuTable() {
    static const MenuTable table{
        "VIEW",
        "VIEW",
        {
            {"RETURN", "back to MAIN", [](MenuContext& s, const std::string&) { returnToMain(s); }},
            {"ONE_VIEW", "one oblique 3D view", setViews},
            {"FOUR_VIEWS", "plan, front, side and the 3D view", setViews},
            {"SHADE", "shaded surfaces", setShaded},
            {"WIREFRAME", "iso-lines and patch boundaries", setShaded},
            {"HULL_ON", "shows the control hulls", setHull},
            {"HULL_OFF", "hides the control hulls", setHull},
            {"CENTRE_ON_MARKER", "centres the views on the reference point", centreOnMarker},
            {"RESET_VIEW", "the first direction, zoom and centre again", resetView},
        }};
    return table;
}

}  // namespace acsynt
