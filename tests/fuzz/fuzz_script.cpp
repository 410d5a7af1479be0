// libFuzzer target: a session script as the acsynt program reads it (ScriptInputSource with the
// session's directives). A script that parses must format, action by action, to lines that parse
// back to the same action (the recorder writes sessions that way).
#include "FuzzSupport.h"
#include "acsynt/session/Session.h"
#include "phigs/input/ScriptInputSource.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::set<std::string> directives = acsynt::Session::directives();
    std::vector<phigs::InputAction> actions;
    try {
        actions = phigs::ScriptInputSource(fuzz::text(data, size), "fuzz.session", directives).actions();
    } catch (const phigs::ScriptError&) {
        return 0;
    }
    for (const phigs::InputAction& action : actions) {
        const std::string line = phigs::ScriptInputSource::format(action);
        const phigs::ScriptInputSource again(line, "formatted.session", directives);
        fuzz::check(again.actions().size() == 1, "a formatted action is one script line");
        fuzz::check(phigs::ScriptInputSource::format(again.actions().front()) == line,
                    "a formatted action parses back to itself");
    }
    return 0;
}
