// The session's state: the undo snapshot, the message line and log, the error map's scale.
#include "acsynt/session/SessionCore.h"

#include "SessionShared.h"

#include "phigs/input/WorkstationInput.h"

namespace acsynt {

using namespace session_detail;

SessionState SessionCore::state() const {
    SessionState s;
    s.models = models;
    s.mappings = mappings;
    s.reductions = reductions;
    s.reference = reference;
    s.placement = placement;
    s.placed = phase == Phase::Placed;
    return s;
}

void SessionCore::say(const std::string& text) {
    message = text;
    log.push_back(text);
}

void SessionCore::fail(const std::string& text) {
    // One count per input action (a script line), however many errors it causes: actions are
    // told apart by how many the devices had consumed when the error came.
    const std::size_t action = input ? input->history().size() : 0;
    if (failedLines == 0 || action != lastFailedAction) ++failedLines;
    lastFailedAction = action;
    message = text;
    // The log names the script line of every error (the input's own errors name it already).
    const std::string where = input ? input->position() : "";
    const bool scriptLine = where.find(" line ") != std::string::npos;
    log.push_back("ERROR: " + text +
                  (scriptLine && text.find(where) == std::string::npos ? " (" + where + ")" : ""));
}

const ReductionRecord* SessionCore::shownReduction() const {
    if (models.empty()) return nullptr;
    // Any reduction made the model shown, not only the session's last one (which may have made
    // another model since).
    const Model& current = models.current();
    for (auto r = reductions.rbegin(); r != reductions.rend(); ++r)
        if (!r->modelDeleted && r->reducedModel == current.name)
            return std::size_t(r->componentIndex) < current.components.size() ? &*r : nullptr;
    return nullptr;
}

double SessionCore::errorMapTop() const {
    if (errorScale > 0) return errorScale;
    const ReductionRecord* r = shownReduction();
    return r ? std::max(r->maxError, 1e-12) : 1e-12;
}

std::string SessionCore::errorMapLine() const {
    const ReductionRecord* r = shownReduction();
    if (!r) return "ERROR MAP OFF";
    return "ERROR MAP: BLUE 0 TO RED " + lengthText(errorMapTop()) +
           (errorScale > 0 ? " (FIXED SCALE)" : " (RELATIVE SCALE)") + ", MAX ERROR " +
           lengthText(r->maxError);
}

}  // namespace acsynt
