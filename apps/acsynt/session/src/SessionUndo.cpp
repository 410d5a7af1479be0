// UNDO and REDO: whole session states (models, mappings, reductions, the reference point and
// the curve's placement) on a bounded stack; every model change records the state it left.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

namespace acsynt {

using namespace session_detail;

SessionState Session::state() const {
    SessionState s;
    s.models = models_;
    s.mappings = mappings_;
    s.reductions = reductions_;
    s.reference = reference_;
    s.placement = placement_;
    s.placed = phase_ == Phase::Placed;
    return s;
}

void Session::restore(SessionState s) {
    models_ = std::move(s.models);
    mappings_ = std::move(s.mappings);
    reductions_ = std::move(s.reductions);
    placement_ = s.placement;
    viewCentre_.reset();
    showModel();  // clears the reference point and the phase
    if (s.reference && !models_.empty() &&
        std::size_t(s.reference->component) < models_.current().components.size()) {
        reference_ = s.reference;
        phase_ = s.placed ? Phase::Placed : Phase::None;
        mappedSincePlaced_ = false;
    }
    drawOverlay();
    drawMapped(true);
}

void Session::remember(SessionState before, const std::string& what) {
    history_.record(std::move(before), what);
}

void Session::undo() {
    auto back = history_.undo(state());
    if (!back) {
        say("NOTHING TO UNDO");
        return;
    }
    restore(std::move(back->first));
    say("UNDONE: " + back->second);
}

void Session::redo() {
    auto again = history_.redo(state());
    if (!again) {
        say("NOTHING TO REDO");
        return;
    }
    restore(std::move(again->first));
    say("REDONE: " + again->second);
}

}  // namespace acsynt
