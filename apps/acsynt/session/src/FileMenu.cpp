// FILE: each command prompts for a file name; the answer is read or written by the session.
#include "acsynt/session/FileMenu.h"

#include "acsynt/session/MainMenu.h"
#include "acsynt/session/MenuContext.h"

namespace acsynt {

namespace {

using Awaiting = SessionCore::Awaiting;

/// A prompt for a file, when the session has the model it needs (`needsModel`).
void ask(MenuContext& s, bool needsModel, const std::string& text, Awaiting what) {
    if (!needsModel || s.requireModel()) s.prompt(text, what);
}

}  // namespace

const MenuTable& fileMenuTable() {
    static const MenuTable table{
        "FILE",
        "FILE",
        {
            {"RETURN", "back to MAIN", [](MenuContext& s, const std::string&) { returnToMain(s); }},
            {"READ_MODEL", "reads an aircraft description or a saved model as a new model",
             [](MenuContext& s, const std::string&) {
                 ask(s, false, "ENTER MODEL FILE NAME", Awaiting::ModelFile);
             }},
            {"READ_CURVE_FILE", "loads a .crv curve, FILE [SCALE]",
             [](MenuContext& s, const std::string&) {
                 ask(s, false, "ENTER CURVE FILE NAME [SCALE]", Awaiting::CurveFile);
             }},
            {"SAVE_MODEL", "writes the current model and its mapped curves",
             [](MenuContext& s, const std::string&) {
                 ask(s, true, "ENTER FILE NAME TO SAVE THE MODEL", Awaiting::SaveFile);
             }},
            {"ARCHIVE", "writes the model's structures to a PHIGS archive",
             [](MenuContext& s, const std::string&) {
                 ask(s, true, "ENTER ARCHIVE FILE NAME", Awaiting::ArchiveFile);
             }},
            {"RETRIEVE", "reads every structure of a PHIGS archive back",
             [](MenuContext& s, const std::string&) {
                 ask(s, false, "ENTER ARCHIVE FILE NAME TO RETRIEVE", Awaiting::RetrieveFile);
             }},
            {"EXPORT", "writes the current model as IGES or STEP",
             [](MenuContext& s, const std::string&) {
                 ask(s, true, "ENTER IGES OR STEP FILE NAME TO EXPORT (.igs, .iges, .stp, .step)",
                     Awaiting::ExportFile);
             }},
            {"IMPORT", "reads an IGES or STEP file as a new model",
             [](MenuContext& s, const std::string&) {
                 ask(s, false, "ENTER IGES OR STEP FILE NAME TO IMPORT", Awaiting::ImportFile);
             }},
            {"HARDCOPY", "writes the views as PDF, SVG or EPS",
             [](MenuContext& s, const std::string&) {
                 ask(s, true, "ENTER HARDCOPY FILE NAME (.pdf, .svg, .eps)", Awaiting::HardcopyFile);
             }},
            {"EXIT", "ends the session",
             [](MenuContext& s, const std::string&) {
                 s.say("EXIT");
                 s.core().finished = true;
             }},
        }};
    return table;
}

}  // namespace acsynt
