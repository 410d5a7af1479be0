// UNDO and REDO: whole session states (models, mappings, reductions, the reference point and
// the curve's placement) on a bounded stack; every model change records the state it left.
#include "acsynt/session/Session.h"

#include "SessionShared.h"
#include "acsynt/session/MainMenu.h"

namespace acsynt {

using namespace session_detail;

void Session::restore(SessionState s) {
    // What was pending (a prompt, a pick for a reduction) belonged to the state left behind, and
    // a menu that works on a model has nothing to work on when none is left.
    core_.awaiting = Awaiting::Nothing;
    core_.prompt.clear();
    if (s.models.empty() && menu_->needsModel) returnToMain(*this);
    core_.models = std::move(s.models);
    core_.mappings = std::move(s.mappings);
    core_.reductions = std::move(s.reductions);
    core_.placement = s.placement;
    core_.viewCentre.reset();
    showModel();  // clears the reference point and the phase
    if (s.reference && !core_.models.empty() &&
        std::size_t(s.reference->component) < core_.models.current().components.size()) {
        core_.reference = s.reference;
        // A point not yet placed was being moved (DONE places it): the pad moves it again.
        core_.phase = s.placed ? Phase::Placed : Phase::MoveMarker;
        core_.mappedSincePlaced = false;
    }
    drawOverlay();
    drawMapped(true);
}

void Session::undo() {
    auto back = core_.history.undo(core_.state());
    if (!back) {
        say("NOTHING TO UNDO");
        return;
    }
    restore(std::move(back->first));
    say("UNDONE: " + back->second);
}

void Session::redo() {
    auto again = core_.history.redo(core_.state());
    if (!again) {
        say("NOTHING TO REDO");
        return;
    }
    restore(std::move(again->first));
    say("REDONE: " + again->second);
}

}  // namespace acsynt
