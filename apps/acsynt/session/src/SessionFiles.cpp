// The files the session reads and writes: models, curves, saved models, IGES and STEP, archives.
#include "acsynt/session/Session.h"

#include "acsynt/session/ModelStateFile.h"

#include "SessionShared.h"

#include "acsynt/ModelFile.h"
#include "acsynt/session/ModelExchange.h"
#include "geom/BoundingBox.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "phigs/core/Error.h"
#include "phigs/core/FileTarget.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/ws/EchoStructures.h"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

namespace acsynt {

using namespace phigs;
using namespace session_detail;

namespace {

/// Refuses a path with a part longer than a file system's name (255 bytes): the file system's
/// own refusal came through as "filesystem error: status: File name too long".
void requireNameLengths(const std::filesystem::path& path, const std::string& what) {
    constexpr std::size_t kMaxName = 255;
    for (const std::filesystem::path& part : path) {
        const std::string text = part.string();
        if (text.size() > kMaxName)
            throw std::invalid_argument(
                what + " NAME '" + text.substr(0, 24) + "...' IS " + std::to_string(text.size()) +
                " CHARACTERS LONG: A FILE NAME HOLDS AT MOST " + std::to_string(kMaxName));
    }
}

/// The structures an archive holds, read into a store of their own.
std::unique_ptr<Phigs> readArchive(const std::filesystem::path& path) {
    auto archived = std::make_unique<Phigs>();
    archived->open();
    archived->openArchiveFile(1, path);
    try {
        archived->retrieveAllStructures(1);
    } catch (...) {
        archived->closeArchiveFile(1);
        throw;
    }
    archived->closeArchiveFile(1);
    return archived;
}

/// Why `archived` is not a picture of `model` (empty when it is): every structure must be one
/// of the model's picture (the root, the overlays, a component's, a hull's or a patch's of a
/// component the model has), and a patch's must be the one the model draws, element for element.
std::string notAPictureOf(const StructureStore& archived, const StructureStore& expected,
                          const Model& model) {
    const int components = static_cast<int>(model.components.size());
    for (const int id : archived.structureIds()) {
        const bool overlay = id == structures::modelRoot || id == structures::mapped ||
                             id == structures::overlay || id == structures::errorMap;
        const bool styled = (id >= structures::component(0) && id < structures::component(components)) ||
                            (id >= structures::hull(0) && id < structures::hull(components));
        if (overlay || styled) continue;
        const std::string name = "STRUCTURE " + std::to_string(id);
        if (!expected.exists(id) || id < structures::patch(0, 0)) return name + " IS NOT IN ITS PICTURE";
        const int count = archived.elementCount(id);
        bool same = count == expected.elementCount(id);
        for (int k = 1; same && k <= count; ++k)
            same = archived.elementAt(id, k) == expected.elementAt(id, k);
        const Component& component = model.components[std::size_t(id / structures::patch(0, 0) - 1)];
        if (!same)
            return name + " IS NOT " + component.name + " PATCH " +
                   std::to_string(id % structures::patch(0, 0));
    }
    return {};
}

}  // namespace

std::filesystem::path Session::findInput(const std::string& name) const {
    const std::filesystem::path path(name);
    requireNameLengths(path, "INPUT FILE");
    if (path.is_absolute() || std::filesystem::exists(path)) return path;
    for (const auto& dir : core_.settings.searchPath)
        if (std::filesystem::exists(dir / path)) return dir / path;
    // Files are read from the working directory and the data folders, written to the output
    // directory: a file the session wrote is named by its path there.
    const std::filesystem::path written = core_.settings.outputDirectory / path;
    if (std::filesystem::exists(written))
        throw std::invalid_argument("FILE " + name +
                                    " IS NOT IN THE WORKING DIRECTORY OR THE DATA FOLDERS; THE OUTPUT "
                                    "DIRECTORY HAS IT: NAME IT " +
                                    written.string());
    return path;
}

namespace {

/// Writes `path` through `write(temporary)`, the temporary a file of the same name in a folder of
/// this process's own beside it (a writer that records the file's name, as IGES does, records
/// the final one), renamed over `path` only when the write succeeded: a failed save or export
/// leaves the previous file as it was and no partial one. An error names `path`.
template <class Write>
void replaceWhole(const std::filesystem::path& path, Write&& write) {
    const std::filesystem::path folder =
        path.parent_path() / ("." + path.filename().string() + ".writing-" + std::to_string(::getpid()));
    const std::filesystem::path temporary = folder / path.filename();
    std::error_code ignored;
    try {
        std::filesystem::create_directory(folder);  // throws where something else has the name
        write(temporary);
        std::filesystem::rename(temporary, path);
        std::filesystem::remove(folder, ignored);
    } catch (const std::exception& e) {
        if (std::filesystem::is_directory(folder, ignored)) std::filesystem::remove_all(folder, ignored);
        // The message names the file asked for, not the temporary.
        std::string message = e.what();
        for (std::size_t at = message.find(temporary.string()); at != std::string::npos;
             at = message.find(temporary.string(), at + path.string().size()))
            message.replace(at, temporary.string().size(), path.string());
        if (message.find(path.string()) == std::string::npos) message = path.string() + ": " + message;
        throw std::runtime_error(message);
    }
}

}  // namespace

std::filesystem::path Session::outputPath(const std::string& name, bool summary) const {
    // Files a session writes stay inside the output directory: a script cannot reach further.
    const std::filesystem::path path(name);
    const bool climbs = std::any_of(path.begin(), path.end(), [](const auto& part) { return part == ".."; });
    if (name.empty() || path.is_absolute() || climbs || !path.has_filename())
        throw std::invalid_argument(
            "OUTPUT FILE '" + name +
            "' MUST BE A FILE NAME INSIDE THE OUTPUT DIRECTORY (NOT ABSOLUTE, NO '..')");
    requireNameLengths(path, "OUTPUT FILE");
    // `summary .` made '..txt' and `snapshot .png` '.png.png': hidden files, not what was meant.
    if (path.filename().string().front() == '.')
        throw std::invalid_argument("OUTPUT FILE '" + name + "' HAS NO NAME BEFORE ITS EXTENSION");
    // The session writes these itself at its end, over whatever a command put there.
    const std::filesystem::path plain = path.lexically_normal();
    if ((plain == "summary.txt" && !summary) || plain == "acsynt.log")
        throw std::invalid_argument("OUTPUT FILE '" + name + "' IS THE SESSION'S OWN " +
                                    (plain == "summary.txt" ? "SUMMARY" : "LOG") + ": CHOOSE ANOTHER NAME");
    const std::filesystem::path full = core_.settings.outputDirectory / path;
    // A symbolic link inside the directory (to a folder or as the file) must not lead out of it.
    auto inside = std::filesystem::weakly_canonical(core_.settings.outputDirectory);
    if (!inside.has_filename()) inside = inside.parent_path();  // written with a trailing '/'
    const auto target = std::filesystem::weakly_canonical(replacedFile(full));
    const auto [end, rest] = std::mismatch(inside.begin(), inside.end(), target.begin(), target.end());
    if (end != inside.end())
        throw std::invalid_argument("OUTPUT FILE '" + name + "' LEADS OUT OF THE OUTPUT DIRECTORY (TO " +
                                    target.string() + ") THROUGH A SYMBOLIC LINK");
    std::filesystem::create_directories(full.parent_path());
    if (std::filesystem::is_directory(full))
        throw std::invalid_argument("OUTPUT FILE " + full.string() + " IS A DIRECTORY");
    return full;
}

void Session::readModel(const std::string& name) {
    // All or nothing: both readers throw before anything changes.
    const std::filesystem::path path = findInput(name);
    SessionState before = core_.state();
    ModelState state;
    if (isModelStateFile(path))
        state = readModelState(path);
    else
        state.model = loadModel(path);
    core_.viewCentre.reset();
    // A name already loaded: the model read is renamed NAME_2, NAME_3, ... and the line says so.
    const std::string fileName = state.model.name;
    std::string modelName = fileName;
    const auto loaded = [this](const std::string& n) {
        for (std::size_t i = 0; i < core_.models.size(); ++i)
            if (core_.models.at(i).name == n) return true;
        return false;
    };
    for (int k = 2; loaded(modelName) && k < 1000; ++k) {
        const std::string suffix = "_" + std::to_string(k);
        modelName = fileName.substr(0, std::min(fileName.size(), std::size_t(20) - suffix.size())) + suffix;
    }
    if (loaded(modelName)) {
        fail("A MODEL NAMED " + fileName + " IS ALREADY LOADED");
        return;
    }
    state.model.name = modelName;
    for (MappingRecord& m : state.mappings) m.model = modelName;
    const std::size_t patches = state.model.patchCount(), components = state.model.components.size();
    const std::size_t mapped = state.mappings.size();
    core_.models.add(std::move(state.model));
    for (MappingRecord& m : state.mappings) core_.mappings.push_back(std::move(m));
    core_.remember(std::move(before), "READ MODEL " + modelName);
    showModel();
    if (mapped > 0) drawMapped(true);
    std::string line = "MODEL " + fileName + " READ";
    if (modelName != fileName) line += " AS " + modelName + " (" + fileName + " IS LOADED)";
    line += ": " + std::to_string(components) + " COMPONENTS, " + std::to_string(patches) + " PATCHES";
    if (mapped > 0) line += ", " + std::to_string(mapped) + " MAPPED CURVES";
    say(line);
}

void Session::readCurve(const std::string& input) {
    // FILE [SCALE]: the scale, when given, must be a whole positive number and the last word.
    std::istringstream in(input);
    std::string name, scaleText, extra;
    in >> name >> scaleText >> extra;
    double scale = 1.0;
    if (!scaleText.empty()) {
        const auto [end, ec] = std::from_chars(scaleText.data(), scaleText.data() + scaleText.size(), scale);
        if (ec != std::errc() || end != scaleText.data() + scaleText.size()) scale = -1.0;
    }
    if (name.empty() || !extra.empty() || !(scale > 0) || !std::isfinite(scale)) {
        fail("BAD INPUT IN CURVE MAP: '" + input + "': expected FILE [SCALE], SCALE a positive number");
        return;
    }
    const std::filesystem::path path = findInput(name);
    geom::CurveModel model = geom::readCurveFile(path);
    std::vector<geom::Curve> curves;
    for (const geom::CurvePart& part : model.parts) {
        try {
            curves.push_back(geom::interpolatePart(part));
        } catch (const geom::CurveFileError&) {
            throw;
        } catch (const geom::GeometryError& e) {
            // Points the reader took that no curve passes through (two the same, 1e300): the
            // file and the part's line named, as for its other faults.
            throw geom::CurveFileError(path.string(), part.line, e.what());
        }
    }
    // The placed curve must stay a drawable, mappable size in model units, as the model's own
    // places and sizes are (kModelMaxLength), and not shrink below a micro-unit.
    constexpr double kSmallest = 1e-6;
    geom::BoundingBox box;
    for (auto& c : curves)
        for (auto& p : c.points) box.add(p *= scale);
    const glm::dvec3 far = glm::max(glm::abs(box.lo), glm::abs(box.hi));
    const double reach = std::max({far.x, far.y, far.z});
    if (!(reach <= kModelMaxLength)) {
        fail("CURVE SCALE " + scaleText + " IS TOO LARGE: THE CURVE REACHES " + number(reach) +
             " MODEL UNITS, PAST 1E6");
        return;
    }
    if (!(box.diagonal() >= kSmallest)) {
        fail("CURVE SCALE " + scaleText + " IS TOO SMALL: THE CURVE SPANS " + number(box.diagonal()) +
             " MODEL UNITS, BELOW 1E-6");
        return;
    }
    core_.curveModel = std::move(model);
    core_.curves = std::move(curves);
    core_.curveFile = std::filesystem::path(name).filename().string();
    core_.curveScale = scale;
    drawOverlay();
    say("CURVE MODEL " + core_.curveFile + " LOADED: " + std::to_string(core_.curves.size()) + " PARTS");
}

void Session::noteSaved(const std::filesystem::path& file) {
    if (std::find(savedFiles_.begin(), savedFiles_.end(), file) == savedFiles_.end())
        savedFiles_.push_back(file);
}

void Session::saveModel(const std::string& name) {
    // The current model as it is (reduced surfaces, imported or not) and its mapped curves.
    const auto path = outputPath(name);
    const Model& model = core_.models.current();
    std::ostringstream text;
    writeModelState(text, model, core_.mappings);
    try {
        replaceWhole(path, [&](const std::filesystem::path& temporary) {
            std::ofstream out(temporary);
            if (!(out << text.str()) || !out.flush())
                throw std::runtime_error("CANNOT WRITE " + path.string());
        });
    } catch (const std::exception&) {
        fail("CANNOT WRITE " + path.string());
        return;
    }
    noteSaved(path);
    std::size_t mapped = 0;
    for (const MappingRecord& m : core_.mappings) mapped += m.model == model.name;
    say("MODEL " + model.name + " SAVED TO " + path.string() + ": " +
        std::to_string(model.components.size()) + " COMPONENTS, " + std::to_string(mapped) +
        " MAPPED CURVES");
}

void Session::exportModel(const std::string& name) {
    const auto path = outputPath(name);
    const Model& model = core_.models.current();
    // ExchangeError (a runtime_error) names the file and cause.
    std::size_t curves = 0;
    replaceWhole(path, [&](const std::filesystem::path& temporary) {
        curves = exchangeCalls().exportModel(model, core_.mappings, temporary);
    });
    noteSaved(path);
    say("MODEL " + model.name + " EXPORTED TO " + path.string() + ": " +
        std::to_string(model.components.size()) + " COMPONENTS, " + std::to_string(model.patchCount()) +
        " PATCHES, " + std::to_string(curves) + " MAPPED CURVES");
}

namespace {

/// What of an imported model lies beyond the coordinates SAVE MODEL writes and READ MODEL takes
/// back (a point of a component or of a mapped loop), or empty: such a model is refused whole.
std::string beyondSavedCoordinates(const ImportedModel& imported) {
    const auto far = [](const glm::dvec3& p) {
        return !isSavableCoordinate(p.x) || !isSavableCoordinate(p.y) || !isSavableCoordinate(p.z);
    };
    for (const Component& c : imported.model.components)
        if (std::any_of(c.surface.points.begin(), c.surface.points.end(), far))
            return "a control point of " + c.name;
    for (const MappingRecord& m : imported.mappings)
        for (const auto& loop : m.polylines)
            if (std::any_of(loop.begin(), loop.end(), far)) return "a point of a curve on " + m.component;
    return {};
}

}  // namespace

void Session::importModel(const std::string& name) {
    ImportedModel imported =
        exchangeCalls().importModel(findInput(name));  // all or nothing: throws before anything changes
    for (std::size_t i = 0; i < core_.models.size(); ++i)
        if (core_.models.at(i).name == imported.model.name) {
            fail("A MODEL NAMED " + imported.model.name + " IS ALREADY LOADED");
            return;
        }
    if (const std::string far = beyondSavedCoordinates(imported); !far.empty()) {
        fail(findInput(name).string() + ": " + far + " is beyond " +
             std::to_string(int(kModelStateMaxCoordinate)) +
             " m, the largest coordinate a saved model holds");
        return;
    }
    core_.viewCentre.reset();
    for (const auto& w : imported.warnings) core_.log.push_back("import: " + w);
    const std::string modelName = imported.model.name;
    const std::size_t patches = imported.model.patchCount(), components = imported.model.components.size();
    const std::size_t curves = imported.mappings.size();
    SessionState before = core_.state();
    core_.models.add(std::move(imported.model));
    for (auto& m : imported.mappings) core_.mappings.push_back(std::move(m));
    core_.remember(std::move(before), "IMPORT " + modelName);
    showModel();
    say("MODEL " + modelName + " IMPORTED: " + std::to_string(components) + " COMPONENTS, " +
        std::to_string(patches) + " PATCHES, " + std::to_string(curves) + " MAPPED CURVES" +
        (imported.warnings.empty()
             ? ""
             : ", " + std::to_string(imported.warnings.size()) + " WARNINGS IN THE LOG"));
}

bool Session::importCadFile(const std::filesystem::path& path) {
    const std::size_t before = core_.failedLines;
    try {
        importModel(path.string());
    } catch (const std::runtime_error& e) {
        fail(e.what());
    } catch (const std::invalid_argument& e) {
        fail(e.what());
    }
    if (core_.failedLines != before) return false;
    // Recorded as the FILE menu's IMPORT of the same file (absolute: the recording may replay from
    // elsewhere), so that a recording of a session started with an import replays.
    const std::size_t at = core_.input ? core_.input->history().size() : 0;
    const std::string file = std::filesystem::absolute(path).lexically_normal().string();
    InputAction typed;
    typed.what = action::String{file, 1};
    // A name no script line holds (a control character, a blank at an end, too long) is noted in
    // a comment instead (with the name where the comment can hold it), and the replay needs the
    // import made another way.
    constexpr std::size_t limit = ScriptInputSource::kMaxScriptLineLength;
    const bool plain = std::none_of(file.begin(), file.end(), [](char c) { return (unsigned char)c < 0x20; });
    if (!ScriptInputSource::readsBack(typed)) {
        const std::string note = "# began with --import of a file a script line cannot name";
        extraLines_.emplace_back(at,
                                 plain && note.size() + 2 + file.size() <= limit ? note + ": " + file : note);
        return true;
    }
    for (const std::string& l : {std::string("choice FILE"), std::string("choice IMPORT"),
                                 ScriptInputSource::format(typed), std::string("choice RETURN")})
        extraLines_.emplace_back(at, l);
    return true;
}

void Session::retrieveArchive(const std::filesystem::path& path) {
    // The screen, picks and mappings must keep showing the session's model: an archive is taken
    // back only when it is a picture of that model (putting back structures it drew), and the
    // session's own style and overlays are drawn over it again.
    if (core_.models.empty()) {
        fail("RETRIEVE NEEDS THE MODEL THE ARCHIVE WAS WRITTEN FROM: READ_MODEL IT FIRST");
        return;
    }
    const std::unique_ptr<Phigs> archived = readArchive(path);
    Phigs expected;
    expected.open();
    ModelPicture(expected.store()).build(core_.models.current(), core_.style);
    const Model& model = core_.models.current();
    if (const std::string why = notAPictureOf(archived->store(), expected.store(), model); !why.empty()) {
        fail("ARCHIVE " + path.string() + " IS NOT A PICTURE OF MODEL " + model.name + ": " + why);
        return;
    }
    phigs_.openArchiveFile(1, path);
    try {
        phigs_.setConflictResolution(ConflictResolution::Update, ConflictResolution::Update);
        phigs_.retrieveAllStructures(1);
    } catch (...) {
        phigs_.closeArchiveFile(1);
        throw;
    }
    phigs_.closeArchiveFile(1);
    restyle();
    drawMapped(false);
    drawErrorMap();
    drawOverlay();
    say("RETRIEVED " + std::to_string(archived->store().structureIds().size()) + " STRUCTURES FROM " +
        path.string());
}

void Session::archive(const std::string& name, bool retrieve) {
    const auto path = retrieve ? findInput(name) : outputPath(name);
    if (retrieve && !std::filesystem::exists(path)) {
        fail("ARCHIVE FILE " + path.string() + " NOT FOUND");
        return;
    }
    if (retrieve && std::filesystem::is_directory(path)) {
        fail("ARCHIVE FILE " + path.string() + " IS A DIRECTORY");
        return;
    }
    if (retrieve) {
        retrieveArchive(path);
        return;
    }
    // A new archive of the model's network alone, replacing the file whole (an existing archive
    // is not merged into: it may hold another model's picture).
    std::size_t count = 0;
    replaceWhole(path, [&](const std::filesystem::path& temporary) {
        phigs_.openArchiveFile(1, temporary);
        try {
            phigs_.archiveStructureNetworks(1, {structures::modelRoot});
            count = phigs_.archiveContents(1).size();
            phigs_.closeArchiveFile(1);
        } catch (...) {
            phigs_.closeArchiveFile(1);
            throw;
        }
    });
    noteSaved(path);
    say("ARCHIVED " + std::to_string(count) + " STRUCTURES TO " + path.string());
}

}  // namespace acsynt
