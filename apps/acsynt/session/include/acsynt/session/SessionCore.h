#pragma once

#include "acsynt/ModelList.h"
#include "acsynt/session/History.h"
#include "acsynt/session/MappingRecord.h"
#include "acsynt/session/ModelPicture.h"
#include "acsynt/session/SessionSettings.h"
#include "geom/CurveFile.h"
#include "geom/Deviation.h"
#include "geom/curvemap/CurveMapper.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace phigs {
class Workstation;
class WorkstationInput;
}  // namespace phigs

namespace acsynt {

/// One data reduction of a component (SURF_REDN).
struct ReductionRecord {
    std::string model, reducedModel, component, direction, mode;
    double tolerance = 0;
    std::size_t count = 0;
    std::size_t countUBefore = 0, countWBefore = 0, countUAfter = 0, countWAfter = 0;
    std::size_t removedU = 0, removedW = 0;
    double maxError = 0;
    geom::SurfaceDeviation deviation;
    int componentIndex = -1;
    bool modelDeleted = false;  ///< reducedModel was deleted since (the summary still lists it)
};

/// What UNDO and REDO bring back: the models, the mappings and reductions made on them, the
/// reference point and the curve's placement.
struct SessionState {
    ModelList models;
    std::vector<MappingRecord> mappings;
    std::vector<ReductionRecord> reductions;
    std::optional<ReferencePoint> reference;
    geom::curvemap::Placement placement;
    bool placed = false;  ///< DEFINE POINT finished (DONE)
};

/// The session's state that its menus act on: settings, models, view, curve and reduction
/// state, the undo stack, the message line and the log, and the workstation's handles.
class SessionCore {
public:
    /// Where DEFINE POINT and SURF_REDN's component choice are.
    enum class Phase {
        None,
        SelectComponent,
        SelectPatch,
        AcceptReject,
        MoveMarker,
        Placed,
        SelectReduction
    };
    /// What the open prompt's answer (STRING 1) is for.
    enum class Awaiting {
        Nothing,
        ModelFile,
        CurveFile,
        SaveFile,
        ExportFile,
        ImportFile,
        HardcopyFile,
        ArchiveFile,
        RetrieveFile,
        Tolerance,
        Count,
        ModelName,
        ErrorScale
    };

    SessionCore() = default;
    explicit SessionCore(SessionSettings s) : settings(std::move(s)) {}

    /// The state UNDO would bring back now.
    SessionState state() const;
    /// A change named `what` was made from `before` (REDO's stack is cleared).
    void remember(SessionState before, const std::string& what) { history.record(std::move(before), what); }
    /// The message line and the log (the screen is redrawn by the session).
    void say(const std::string& text);
    /// An error on the message line and in the log, counted once per input action.
    void fail(const std::string& text);
    /// The reduction the error map shows: the last one that made the current model, or null.
    const ReductionRecord* shownReduction() const;
    /// The length the error map shows red at: the fixed scale, or the reduction's largest error.
    double errorMapTop() const;
    /// ERROR_MAP's message: the scale and the largest error of the shown reduction.
    std::string errorMapLine() const;

    SessionSettings settings;
    phigs::Workstation* workstation = nullptr;
    phigs::WorkstationInput* input = nullptr;

    ModelList models;
    DisplayStyle style;
    bool fourViews = false;
    double azimuth = -135, elevation = 25, zoom = 1;
    std::optional<glm::dvec3> viewCentre;  ///< CENTRE ON MARKER; else the model's middle

    std::string message;
    std::vector<std::string> log;
    Phase phase = Phase::None;
    Awaiting awaiting = Awaiting::Nothing;
    std::string prompt;  ///< the open prompt's text
    bool finished = false;
    std::size_t failedLines = 0;
    std::size_t lastFailedAction = 0;

    // CURVE MAP
    std::optional<geom::CurveModel> curveModel;
    std::vector<geom::Curve> curves;  ///< interpolated parts, scaled
    std::string curveFile;
    double curveScale = 1.0;
    geom::curvemap::Placement placement;
    int pickedComponent = -1;
    std::optional<ReferencePoint> reference;
    std::optional<PickedPatch> lastPick;
    std::optional<phigs::SurfacePickDetail> lastPickDetail;
    std::vector<MappingRecord> mappings;
    bool mappedSincePlaced = false;
    std::vector<std::vector<glm::dvec3>> previewLines;    ///< MAP PREVIEW: parts that map
    std::vector<std::vector<glm::dvec3>> previewClipped;  ///< parts clipped at an edge
    std::vector<std::vector<glm::dvec3>> previewLost;     ///< placed outlines of parts that map nothing

    // SURF_REDN
    std::string reductionDirection = "U";
    bool reductionByCount = false;
    int reductionComponent = -1;
    /// ERROR_SCALE: the error map is red at this length (model units) on a fixed scale; 0: at
    /// the reduction's largest error (relative).
    double errorScale = 0.01;
    std::vector<ReductionRecord> reductions;

    History<SessionState> history;
};

}  // namespace acsynt
