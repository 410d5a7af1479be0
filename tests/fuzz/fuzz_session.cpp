// libFuzzer target: a whole ACSYNT design session replayed from a script, GPU-free. The input is
// the script; acsynt::Session runs it as `acsynt --script` does (menus, picks on the model
// workstation's draw list, reading models and curves, curve mapping, data reduction, saving and
// archiving), except that snapshots draw nothing (only the program's pictures need Vulkan) and
// vector hardcopies are refused (too slow under the sanitizers).
// Files are read from the shipped data, tests/fuzz/data (a small model, quick to loft) and a
// scratch directory emptied for every input, and written to that directory; a script that names
// a file with a '/' is rejected, so nothing elsewhere is read or written. Bad input must end as
// a message (the session catches it): an exception escaping run() is a finding, and so is a
// recording that does not parse. FUZZ_SESSION_LOG=1 prints each session's log.
#include "FuzzSupport.h"
#include "acsynt/session/Session.h"
#include "phigs/input/ScriptInputSource.h"

#include <cstdio>
#include <cstdlib>

namespace {

/// No string (a file name, or text that might be one) and no directive argument holds a '/'.
bool namesLocalFiles(const std::vector<phigs::InputAction>& actions) {
    for (const phigs::InputAction& a : actions) {
        if (const auto* s = std::get_if<phigs::action::String>(&a.what))
            if (s->text.find('/') != std::string::npos) return false;
        if (const auto* d = std::get_if<phigs::action::Directive>(&a.what))
            for (const std::string& argument : d->arguments)
                if (argument.find('/') != std::string::npos) return false;
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::optional<phigs::ScriptInputSource> script;
    try {
        script.emplace(fuzz::text(data, size), "fuzz.session", acsynt::Session::directives());
    } catch (const phigs::ScriptError&) {
        return 0;
    }
    if (!namesLocalFiles(script->actions())) return -1;  // not added to the corpus

    acsynt::SessionSettings settings;
    settings.outputDirectory = fuzz::scratch();
    settings.searchPath = {ACSYNT_DATA_DIR, FUZZ_DATA_DIR, settings.outputDirectory};
    // A shaded PDF of the demo's transport costs 17 s here, past the time an input may take; the
    // vector writer has its own tests (tests/hardcopy), the fuzzer explores the session's input.
    settings.vectorHardcopies = false;
    acsynt::Session session(settings, *script);
    session.setSnapshot([](const std::filesystem::path&) {});
    session.run();
    static const bool showLog = std::getenv("FUZZ_SESSION_LOG") != nullptr;
    if (showLog)
        for (const std::string& line : session.log()) std::fprintf(stderr, "session: %s\n", line.c_str());
    session.summary();
    phigs::ScriptInputSource(session.recording(), "recording.session", acsynt::Session::directives());
    return 0;
}
