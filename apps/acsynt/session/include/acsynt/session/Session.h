#pragma once

#include "acsynt/session/MenuContext.h"
#include "acsynt/session/MenuTable.h"
#include "acsynt/session/ModelPicture.h"
#include "acsynt/session/ScreenLayout.h"
#include "acsynt/session/SessionCore.h"
#include "phigs/Phigs.h"
#include "phigs/input/InputQueue.h"
#include "phigs/input/InputSource.h"
#include "phigs/input/WorkstationInput.h"
#include "phigs/traverse/WorkstationMapping.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace acsynt {

/// The menu-driven ACSYNT design session: a PHIGS workstation showing the model (one or four
/// views), the menu panel, the pointer-valuator pad, sliders and the message line, all as
/// structures; its devices (choice 1 the menu, choice 2 the pad, pick 1, valuators 1-4, string 1)
/// are fed by any input source (a script or a window), and every action is recorded.
class Session : private MenuContext {
public:
    /// `snapshot(file)` writes what the workstation shows to a PNG, for `snapshot NAME`.
    using PictureSink = std::function<void(const std::filesystem::path&)>;

    /// Opens PHIGS and the workstation; throws std::invalid_argument for a screen whose shape is
    /// not the display surface's (a window's follows the screen).
    Session(SessionSettings settings, phigs::InputSource& source);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    /// The directives a session script may use: snapshot NAME, summary NAME, hardcopy
    /// NAME.pdf|svg|eps, and pick_surface COMPONENT PATCH U W VIEW (a recorded pick on a surface,
    /// replayed at the screen position of that surface point in that view now).
    static std::set<std::string> directives();

    /// Handles events until EXIT or until the source is exhausted.
    void run();
    /// Handles at most one event (waiting up to `timeout`); false once the session is over.
    bool step(std::chrono::milliseconds timeout);
    /// Where `snapshot NAME` pictures go (a vk::WorkstationDisplay of workstation(), a window).
    void setSnapshot(PictureSink snapshot) { snapshot_ = std::move(snapshot); }
    /// The screen is now `width` x `height` pixels (a window resized): the display surface of a
    /// window workstation, the layout (views, menu panel, pad, sliders, message line), the echo
    /// areas and the input mapping all follow. Throws std::invalid_argument for an empty screen
    /// (a minimised window: skip it) or, for other types, one not of the display's shape.
    void resize(int width, int height);
    /// How to show the picture now, before a long computation (MAP CURVE's "PLEASE WAIT"): the
    /// program's one present function. Otherwise the program presents after each step().
    void setShowNow(std::function<void()> show) { showNow_ = std::move(show); }
    /// What to do before a vector hardcopy is described (a script gives back its screen's images,
    /// whose room the hardcopy then uses).
    void setBeforeHardcopy(std::function<void()> hook) { beforeHardcopy_ = std::move(hook); }
    bool finished() const { return core_.finished; }
    /// Input lines (script lines, window actions) that failed: each gave one or more `ERROR:`s.
    std::size_t failedLines() const { return core_.failedLines; }

    /// The current picture (regenerated when the structures changed).
    const phigs::DrawList& picture();
    phigs::Workstation& workstation() { return *core_.workstation; }
    /// The session's PHIGS: its structure store holds the model structures (tests inspect them).
    phigs::Phigs& phigs() { return phigs_; }
    const ScreenLayout& layout() const { return layout_; }
    /// Screen pixel of a world point in view `view` (the view table's orientation and mapping).
    glm::dvec2 pixelOf(const glm::dvec3& world, int view);
    /// The workstation transformation on the screen's pixels (render, pick and echo share it).
    const phigs::WorkstationMapping& mapping() const { return *mapping_; }

    /// ERROR_SCALE: the error map's fixed scale (red at this length, model units), 0 when relative.
    double errorScale() const { return core_.errorScale; }
    /// The current value of valuator `device` (1..4: marker u, w, rotation, zoom).
    double valuatorValue(int device) const;
    const std::string& message() const { return core_.message; }
    /// The message line as the session draws it. The text being typed shows in the string
    /// device's echo area on its right, which the toolkit draws (Workstation::echoState).
    std::string messageLine() const;
    const std::vector<std::string>& log() const { return core_.log; }
    const std::string& menuTitle() const { return menu_->title; }
    const std::vector<std::string>& menuItems() const { return menuItems_; }
    const ModelList& models() const { return core_.models; }
    const std::optional<ReferencePoint>& reference() const { return core_.reference; }
    const std::optional<PickedPatch>& lastPick() const { return core_.lastPick; }
    const std::optional<phigs::SurfacePickDetail>& lastPickDetail() const { return core_.lastPickDetail; }
    const std::vector<MappingRecord>& mappings() const { return core_.mappings; }
    const std::vector<ReductionRecord>& reductions() const { return core_.reductions; }
    const std::vector<std::filesystem::path>& pictures() const { return pictures_; }
    /// The vector hardcopies written (FILE > HARDCOPY, `hardcopy NAME`).
    const std::vector<std::filesystem::path>& hardcopies() const { return hardcopies_; }
    /// The other files written (SAVE_MODEL, EXPORT, ARCHIVE, `summary NAME`), each once, as first written.
    const std::vector<std::filesystem::path>& savedFiles() const { return savedFiles_; }
    bool fourViews() const { return core_.fourViews; }
    const DisplayStyle& style() const { return core_.style; }

    /// FILE > IMPORT of an IGES or STEP file, as the command line's --import does it before a
    /// session's input: false (with the message) when it is refused and nothing changed.
    bool importCadFile(const std::filesystem::path& path);

    // ---- navigation (a window's mouse and keys, see ViewNavigation; scripts: `view`)
    /// Turns the 3D view by `azimuth` degrees about the vertical and tilts it by `elevation`
    /// degrees (kept within +-89).
    void rotateView(double azimuth, double elevation);
    /// Multiplies the zoom of every view by `factor` (kept within the ZOOM slider's 0.25..8).
    void zoomView(double factor);
    /// Moves the views' centre so that the model follows a pointer moved by `pixels` in the 3D view.
    void panView(glm::dvec2 pixels);
    double azimuth() const { return core_.azimuth; }
    double elevation() const { return core_.elevation; }
    double zoom() const { return core_.zoom; }
    /// Shows or hides the key and mouse help over the views (structure 29).
    void toggleHelp();
    bool helpShown() const { return help_; }
    /// Ctrl+Z (true) or Ctrl+Y: UNDO or REDO from any menu.
    void undoRedoKey(bool undo);
    /// A prompt is open or text is being typed (so H is text, not the help key).
    bool typing() const;

    /// Changes UNDO can take back, and undone changes REDO can make again.
    std::size_t undoCount() const { return core_.history.undoCount(); }
    std::size_t redoCount() const { return core_.history.redoCount(); }

    /// The text summary (patch picked, marker (u, w), mapped loops, control points before and after).
    std::string summary() const;
    /// The session so far as a script that replays it, whatever the screen's size then: menu
    /// rows and pad buttons as `choice NAME`, picks on surfaces as `pick_surface COMPONENT PATCH
    /// U W VIEW`, each with a comment saying what it did; directives (snapshots) as they came.
    std::string recording() const;

private:
    using Phase = SessionCore::Phase;
    using Awaiting = SessionCore::Awaiting;

    void setupWorkstation();
    void fitWorkstation();  ///< the workstation's display, window, viewport and mapping for the layout
    void setupDevices();
    void initialiseSliders();
    /// Valuator `device`'s range: U and W (1, 2) span the reference patch in the component's
    /// own parameters ([0, 1] without one), ROTATE and ZOOM (3, 4) are fixed.
    glm::dvec2 sliderRange(int device) const;
    void initialiseString();  ///< string 1, echoed on the right of the message line
    void followStringEcho();
    /// The input is exhausted: the session ends (a script's open prompt fails its line).
    void endOfInput();
    void handle(const phigs::EventReport& report);
    /// Runs a command; bad input it throws (a model file's, geometry's, PHIGS's) fails its line.
    void reportingFailures(const std::function<void()>& command);
    /// A script directive (snapshot, view, pick_surface, ...): applyDirective, and the end of a
    /// run that stops at its first failing line when this one failed.
    void directive(const phigs::action::Directive& d, const phigs::InputAction& a);
    void applyDirective(const phigs::action::Directive& d, const phigs::InputAction& a);
    void writeDirective(const phigs::action::Directive& d);
    /// pick_surface: a pick at the screen position of a component's surface point in a view,
    /// which must find that component and patch; the pick reports the recorded (u, w).
    void pickSurface(const std::vector<std::string>& arguments);
    /// The recording writes the input action being handled as `line` (and `comment`).
    void recordAs(std::string line, std::string comment = {});
    /// A pick on a surface recorded as pick_surface (its view: the click's, or pickView_).
    void recordPick(const PickedPatch& picked, const phigs::PickMeasure& measure);
    /// A menu row chosen (CHOICE 1): the current menu's table runs it.
    void choose(const std::string& item);
    void padButton(int button);
    /// Why the pad or a valuator cannot move the marker yet: the next step of DEFINE POINT.
    std::string noMarkerYet() const;
    void pick(const phigs::PickMeasure& measure);
    /// A pick that hit nothing: refused off the screen, else recorded as pick_nothing.
    void missedPick();
    void valuator(int device, double value);
    void text(const std::string& input);

    // MenuContext: what the menus' commands act on (the menus are MainMenu.cpp, FileMenu.cpp, ...).
    SessionCore& core() override { return core_; }
    void say(const std::string& text) override;
    void fail(const std::string& text) override;
    void prompt(const std::string& text, Awaiting what) override;
    bool requireModel() override;
    void openMenu(const MenuTable& menu) override;
    void restyle() override;
    void showModel() override;
    void updateViews() override;
    void drawOverlay() override;
    void drawMapped(bool all) override;
    void drawErrorMap() override;
    void mapCurve(bool previewOnly) override;
    void undo() override;  ///< SessionUndo.cpp
    void redo() override;

    void restore(SessionState state);  ///< UNDO and REDO: the state and the screen showing it
    void readModel(const std::string& name);
    void readCurve(const std::string& input);
    void saveModel(const std::string& name);
    void exportModel(const std::string& name);  ///< FILE > EXPORT: IGES or STEP by the name's extension
    void importModel(const std::string& name);  ///< FILE > IMPORT
    /// FILE > HARDCOPY and `hardcopy NAME`: the views as PDF, SVG or EPS by the name's extension.
    void writeHardcopy(const std::string& name);
    void archive(const std::string& name, bool retrieve);
    void retrieveArchive(const std::filesystem::path& path);
    void renameModel(const std::string& name);  ///< NAME_MODEL's answer
    /// The tolerance or knot count a reduction was asked for (`count`: BY COUNT's prompt).
    void reductionAnswer(const std::string& input, bool count);
    void reduce(int component, double tolerance, std::size_t count);
    /// MAP PREVIEW: every part's projection lines, or its placed outline when it maps nothing.
    void previewMapping(const ComponentMapping& mapped);
    void drawScreen();   ///< menu, pad, sliders, message
    void drawPad();      ///< the pointer-valuator pad, live while the marker moves
    void drawMessage();  ///< title, menu name, current model and the message line
    glm::dvec3 npc(glm::dvec2 pixel, double z = 0.5) const { return mapping_->pixelsToNpc(pixel, z); }
    std::vector<glm::dvec3> outline(const PixelBox& box) const;
    void drawLegend();  ///< the error map's colour bar in model units, or nothing when it is off
    void drawHelp();
    void navigated();  ///< after a navigation: views, sliders, and the recording's `view` line
    void setView(const std::vector<std::string>& arguments);  ///< the `view` directive
    glm::dvec3 obliqueDirection() const;  ///< from the model's centre towards the 3D view's eye
    std::pair<glm::dvec3, glm::dvec3> modelBounds() const;  ///< the current model's control points' box
    void setErrorScale(const std::string& input);           ///< ERROR_SCALE: a length (fixed) or RELATIVE
    void moveMarker(double u, double w);
    std::filesystem::path findInput(const std::string& name) const;
    /// `name` inside the output directory; std::invalid_argument for an absolute name, one with
    /// "..", a directory, or the session's own summary or log (which the end of the run writes
    /// over), save that the summary directive (`summary`) may write the summary.
    std::filesystem::path outputPath(const std::string& name, bool summary = false) const;

    SessionCore core_;
    ScreenLayout layout_;
    phigs::InputSource& source_;
    PictureSink snapshot_;
    std::function<void()> showNow_;
    std::function<void()> beforeHardcopy_;

    phigs::Phigs phigs_;
    std::optional<phigs::WorkstationMapping> mapping_;
    phigs::InputQueue queue_;
    ModelPicture modelPicture_;

    bool help_ = false;
    const MenuTable* menu_ = nullptr;     ///< the menu on the panel (CHOICE 1)
    std::vector<std::string> menuItems_;  ///< its commands' names
    std::uint64_t echoEdits_ = 0;
    glm::dvec2 sliderRanges_[4];  ///< the ranges the valuators were last initialised with

    std::vector<std::filesystem::path> pictures_;
    std::vector<std::filesystem::path> hardcopies_;
    std::vector<std::filesystem::path> savedFiles_;
    void noteSaved(const std::filesystem::path& file);
    /// By index in the devices' action history: how the recording writes that action.
    std::map<std::size_t, std::pair<std::string, std::string>> recordedAs_;
    int pickView_ = 0;  ///< the view of the pick_surface being replayed
    /// Lines the recording writes that are no device's action (navigation as `view`, Ctrl+Z as
    /// `undo`), each before the action history entry of its index.
    std::vector<std::pair<std::size_t, std::string>> extraLines_;
};

}  // namespace acsynt
