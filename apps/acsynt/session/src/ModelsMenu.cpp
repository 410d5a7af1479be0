// MODELS: the current model among those loaded, with ACSYNT's messages.
#include "acsynt/session/ModelsMenu.h"

#include "acsynt/session/MainMenu.h"
#include "acsynt/session/MenuContext.h"

namespace acsynt {

namespace {

/// The model list's answer: a changed current model is shown, a refusal is an error.
void report(MenuContext& s, const ModelList::Outcome& outcome) {
    if (outcome.done) {
        s.showModel();
        s.say(outcome.message);
    } else {
        s.fail(outcome.message);
    }
}

void nextModel(MenuContext& s, const std::string&) {
    s.say("CHANGING CURRENT MODEL TO NEXT MODEL");
    report(s, s.core().models.next());
}

void previousModel(MenuContext& s, const std::string&) {
    s.say("CHANGING CURRENT MODEL TO PREVIOUS MODEL");
    report(s, s.core().models.previous());
}

void list(MenuContext& s, const std::string&) {
    const ModelList& models = s.core().models;
    std::string line = "MODELS:";
    for (std::size_t i = 0; i < models.size(); ++i)
        line += " " + models.at(i).name + (i == models.currentIndex() ? "*" : "");
    s.say(models.empty() ? "NO GEOMETRY FILE FOUND!" : line);
}

void deleteModel(MenuContext& s, const std::string&) {
    if (!s.requireModel()) return;
    SessionCore& c = s.core();
    SessionState before = c.state();
    const std::string name = c.models.current().name;
    ModelList::Outcome outcome = c.models.removeCurrent();
    if (outcome.done) {
        std::erase_if(c.mappings, [&](const MappingRecord& m) { return m.model == name; });
        // A model read or renamed to this name later is not this reduction's.
        for (ReductionRecord& r : c.reductions)
            if (r.reducedModel == name) r.modelDeleted = true;
        outcome.message = "MODEL " + name + " DELETED" +
                          (c.models.empty() ? "" : ".  CURRENT MODEL NAME = " + c.models.current().name);
        c.remember(std::move(before), "DELETE MODEL");
    }
    report(s, outcome);
}

}  // namespace

const MenuTable& modelsMenuTable() {
    static const MenuTable table{
        "MODELS",
        "MODELS",
        {
            {"RETURN", "back to MAIN", [](MenuContext& s, const std::string&) { returnToMain(s); }},
            {"NEXT_MODEL", "makes the next model current", nextModel},
            {"PREVIOUS_MODEL", "makes the previous model current", previousModel},
            {"LIST", "names the models, the current one starred", list},
            {"NAME_MODEL", "renames the current model",
             [](MenuContext& s, const std::string&) {
                 if (s.requireModel()) s.prompt("PLEASE ENTER MODEL NAME", SessionCore::Awaiting::ModelName);
             }},
            {"DELETE_MODEL", "removes the current model and its mapped curves", deleteModel},
        }};
    return table;
}

}  // namespace acsynt
