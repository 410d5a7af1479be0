// DEFINE POINT's confirmation: ACCEPT places the marker on the picked patch, REJECT asks for
// another patch. It leaves an open prompt open, as it always did.
#include "acsynt/session/ConfirmMenu.h"

#include "acsynt/session/CurveMapMenu.h"
#include "acsynt/session/MenuContext.h"

namespace acsynt {

namespace {

using Phase = SessionCore::Phase;

/// The panel can still show ACCEPT / REJECT after the patch choice was undone: then the
/// choice only withdraws the prompt, as any other menu's does.
bool confirming(SessionCore& c) {
    if (c.phase == Phase::AcceptReject) return true;
    c.awaiting = SessionCore::Awaiting::Nothing;
    return false;
}

void accept(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    if (!confirming(c)) return;
    const Component& comp = c.models.current().components[std::size_t(c.pickedComponent)];
    const Patch& p = comp.patches.patches[std::size_t(c.lastPick->patch - 1)];
    c.reference = ReferencePoint{c.pickedComponent, p.number, p.u0, p.w0};
    c.phase = Phase::MoveMarker;
    s.openMenu(curveMapMenuTable());
    s.drawOverlay();
    s.say("MOVE THE MARKER WITH THE POINTER VALUATOR, THEN DONE");
}

void reject(MenuContext& s, const std::string&) {
    SessionCore& c = s.core();
    if (!confirming(c)) return;
    c.style.colourfulComponent = c.pickedComponent;
    c.style.highlightComponent = -1;
    s.restyle();
    c.phase = Phase::SelectPatch;
    s.openMenu(curveMapMenuTable());
    s.say("SELECT REFERENCE PATCH TO MAP");
}

}  // namespace

const MenuTable& confirmMenuTable() {
    static const MenuTable table{"CONFIRM",
                                 "CURVE MAP",
                                 {
                                     {"ACCEPT", "takes the picked patch: the marker goes on it", accept},
                                     {"REJECT", "back to picking a patch of the component", reject},
                                 },
                                 true,
                                 true};
    return table;
}

}  // namespace acsynt
