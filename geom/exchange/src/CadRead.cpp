// readCadFile: an IGES or STEP file's faces back to named B-spline surfaces and curve sets.
#include "CadDocument.h"
#include "FailureText.h"
#include "FileEntities.h"
#include "IgesParameters.h"
#include "ImportCodec.h"
#include "Isolated.h"
#include "MessageCollector.h"
#include "OcctSession.h"
#include "ShapeRead.h"
#include "StepReals.h"
#include "Units.h"

#include "geom/exchange/CadFile.h"
#include "geom/exchange/ExchangeError.h"
#include "geom/exchange/PatchGrid.h"

#include <IGESCAFControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESGeom_TrimmedSurface.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepShape_Face.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>

namespace geom::exchange {

namespace {

/// Refuses, before OpenCASCADE sees it, a path that is not a readable, non-empty file within the limit.
void checkFile(const std::filesystem::path& path, const CadReadOptions& options) {
    const std::string file = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw ExchangeError(file, "no such file");
    if (std::filesystem::is_directory(path, ec)) throw ExchangeError(file, "is a directory");
    if (!std::filesystem::is_regular_file(path, ec)) throw ExchangeError(file, "is not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || !std::ifstream(path)) throw ExchangeError(file, "cannot be read");
    if (size == 0) throw ExchangeError(file, "is empty");
    if (size > options.maxFileBytes)
        throw ExchangeError(file, std::to_string(size) + " bytes: larger than the limit of " +
                                      std::to_string(options.maxFileBytes));
    std::ifstream in(path, std::ios::binary);
    const std::optional<std::string> bad =
        cadFormatOf(path) == CadFormat::Step ? firstOutOfRangeStepReal(in) : firstBadIgesParameter(in);
    if (bad) throw ExchangeError(file, *bad);
}

/// Refuses a file whose loading failed (truncated, corrupt): the first failure OpenCASCADE noted.
void checkLoad(const opencascade::handle<XSControl_WorkSession>& session, const std::string& file,
               const char* format) {
    const Interface_CheckIterator checks = session->ModelCheckList();
    for (checks.Start(); checks.More(); checks.Next()) {
        const opencascade::handle<Interface_Check>& check = checks.Value();
        if (!check->HasFailed()) continue;
        std::string text = check->NbFails() > 0 ? check->CFail(1) : "a load failure";
        // Some of OpenCASCADE's messages keep their printf templates ("parameter %d").
        for (std::size_t at; (at = text.find(" %d")) != std::string::npos;) text.erase(at, 3);
        if (const std::size_t at = text.find(" Process continues."); at != std::string::npos) text.erase(at);
        const int entity = checks.Number();
        if (entity > 0) text = "entity " + std::to_string(entity) + ": " + text;
        throw ExchangeError(file, std::string("not a valid ") + format + " file (" + text + ")");
    }
}

/// What OpenCASCADE's shape healing left out while transferring (a wire it took for one of null
/// area, a small edge, wire or face), a warning each by entity: a mapped curve's hole can go so,
/// and the caller must hear of it.
void addHealingWarnings(const opencascade::handle<XSControl_WorkSession>& session, CadImport& result) {
    const opencascade::handle<Transfer_TransientProcess> process =
        session->TransferReader()->TransientProcess();
    if (process.IsNull()) return;
    const Interface_CheckIterator checks = process->CheckList(false);
    for (checks.Start(); checks.More(); checks.Next()) {
        const opencascade::handle<Interface_Check>& check = checks.Value();
        for (int i = 1; i <= check->NbWarnings(); ++i) {
            const std::string text = check->CWarning(i);
            if (text.find("removed") == std::string::npos && text.find("skipped") == std::string::npos)
                continue;
            result.warnings.push_back(entityLabel(session->Model(), check->Entity()) +
                                      ": OpenCASCADE's healing left something out: " + text);
        }
    }
}

/// The loops the file gives a trimmed face (an IGES 144's outer and inner contours, a STEP face's
/// bounds), or 0 for any other entity (an IGES face on its natural bounds counts 0 too).
int boundsInFile(const opencascade::handle<Standard_Transient>& entity) {
    if (const auto trimmed = opencascade::handle<IGESGeom_TrimmedSurface>::DownCast(entity))
        return (trimmed->HasOuterContour() ? 1 : 0) + trimmed->NbInnerContours();
    if (const auto face = opencascade::handle<StepShape_Face>::DownCast(entity)) return face->NbBounds();
    return 0;
}

/// A warning for every trimmed face of the file that came back with fewer loops than the file
/// gives it: OpenCASCADE's healing skips some holes (and with them at times the outer loop), not
/// always with a message (addHealingWarnings).
void addLostBoundWarnings(const opencascade::handle<XSControl_WorkSession>& session, CadImport& result) {
    const opencascade::handle<Interface_InterfaceModel> model = session->Model();
    const opencascade::handle<XSControl_TransferReader> transfer = session->TransferReader();
    if (model.IsNull() || transfer.IsNull()) return;
    const opencascade::handle<Transfer_TransientProcess> process = transfer->TransientProcess();
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const opencascade::handle<Standard_Transient> entity = model->Value(i);
        const int expected = boundsInFile(entity);
        if (expected <= 0) continue;
        TopoDS_Shape shape = transfer->ShapeResult(entity);
        if (shape.IsNull() && !process.IsNull()) shape = TransferBRep::ShapeResult(process->Find(entity));
        if (shape.IsNull()) continue;  // a face not transferred at all is warned of where it is read
        int wires = 0;
        for (TopExp_Explorer w(shape, TopAbs_WIRE); w.More(); w.Next()) ++wires;
        if (wires < expected)
            result.warnings.push_back(entityLabel(model, entity) + ": a face with " +
                                      std::to_string(expected) +
                                      " loops in the file came back from OpenCASCADE with " +
                                      std::to_string(wires) + ": " + std::to_string(expected - wires) +
                                      (expected - wires == 1 ? " loop" : " loops") + " left out");
    }
}

void checkUnit(const std::string& unit, const std::string& file) {
    static const char* known = " (m, mm, cm, km, um, in, ft, mi, mil, uin)";
    if (unit.empty())
        throw ExchangeError(file, std::string("its length unit is not one the program knows") + known);
    if (!metresPerUnit(unit))
        throw ExchangeError(file, "length unit '" + unit + "' is not one the program knows" + known);
}

/// Why a file gave no shapes: its faces all lost (the first named), or none in it.
std::string noShapes(const FileFaces& faces) {
    if (faces.lost.empty()) return "OpenCASCADE found no shapes in it";
    return "no face of its " + std::to_string(faces.lost.size()) + " could be read: " + faces.lost.front();
}

/// "why", with OpenCASCADE's first failure message after it where there was one.
std::string because(const std::string& why, const MessageCollector& messages) {
    const std::string first = messages.first();
    return first.empty() ? why : why + " (" + first + ")";
}

FileFaces readStep(const std::string& file, opencascade::handle<TDocStd_Document> document, CadImport& result,
                   const MessageCollector& messages) {
    STEPCAFControl_Reader reader;
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    if (reader.ReadFile(file.c_str()) != IFSelect_RetDone)
        throw ExchangeError(file, because("not a readable STEP file", messages));
    checkLoad(reader.Reader().WS(), file, "STEP");
    TColStd_SequenceOfAsciiString lengths, angles, solidAngles;
    reader.ChangeReader().FileUnits(lengths, angles, solidAngles);
    for (int i = 1; i <= lengths.Length(); ++i) checkUnit(lengths.Value(i).ToCString(), file);
    if (lengths.IsEmpty())
        result.warnings.push_back(
            "the file declares no length unit: read as millimetres, OpenCASCADE's default");
    else
        result.fileUnit = lengths.First().ToCString();
    const bool transferred = reader.Transfer(document);
    FileFaces faces = fileFaces(reader.Reader().WS());
    if (!transferred) throw ExchangeError(file, noShapes(faces));
    result.warnings.insert(result.warnings.end(), faces.lost.begin(), faces.lost.end());
    addHealingWarnings(reader.Reader().WS(), result);
    addLostBoundWarnings(reader.Reader().WS(), result);
    return faces;
}

FileFaces readIges(const std::string& file, opencascade::handle<TDocStd_Document> document, CadImport& result,
                   const MessageCollector& messages, std::string& modelName) {
    IGESCAFControl_Reader reader;
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    if (reader.ReadFile(file.c_str()) != IFSelect_RetDone)
        throw ExchangeError(file, because("not a readable IGES file", messages));
    checkLoad(reader.WS(), file, "IGES");
    const IGESData_GlobalSection& header = reader.IGESModel()->GlobalSection();
    const int flag = header.UnitFlag();
    const std::string unit = header.UnitName().IsNull() ? "" : header.UnitName()->ToCString();
    // Flag 3: the unit is the one named. OpenCASCADE reads flag 3 with no name as 1, inches.
    std::ifstream text(file, std::ios::binary);
    const std::vector<std::string> written = igesGlobalParameters(text);
    if (written.size() > 14 && std::strtol(written[13].c_str(), nullptr, 10) == 3 && written[14].empty())
        throw ExchangeError(file,
                            "unit flag 3 (the unit named in the file) but no unit name: its length unit "
                            "is not known");
    if (flag == 3 || (flag >= 1 && flag <= 11 && !unit.empty()))
        checkUnit(unit, file);
    else if (flag < 1 || flag > 11)
        throw ExchangeError(file,
                            "unit flag " + std::to_string(flag) + " is not an IGES length unit (1 to 11)");
    result.fileUnit = unit;
    const bool transferred = reader.Transfer(document);
    FileFaces faces = fileFaces(reader.WS());
    if (!transferred) throw ExchangeError(file, noShapes(faces));
    result.warnings.insert(result.warnings.end(), faces.lost.begin(), faces.lost.end());
    addHealingWarnings(reader.WS(), result);
    addLostBoundWarnings(reader.WS(), result);
    modelName = header.SendName().IsNull() ? "" : header.SendName()->ToCString();
    return faces;
}

double netSize(const std::vector<Surface>& surfaces) {
    double size = 0;
    for (const Surface& s : surfaces)
        for (const auto& p : s.points) size = std::max({size, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return 1.0 + size;
}

/// What a part's faces give: one surface (its patches joined) or one per face.
void addSurfaces(const NamedShape& part, const std::string& name, CadModel& model, CadImport& result,
                 std::size_t& poles, const CadReadOptions& options, const std::string& file,
                 const FileFaces& fileFaces) {
    std::vector<Surface> surfaces;
    std::map<std::string, std::vector<std::string>> problems;  // the faces' labels by problem
    for (TopExp_Explorer f(part.shape, TopAbs_FACE); f.More(); f.Next()) {
        FaceSurface s = faceSurface(TopoDS::Face(f.Current()));
        if (!s.surface) {
            problems[s.problem].push_back(fileFaces.labelOf(f.Current()));
            continue;
        }
        poles += s.surface->points.size();
        if (poles > options.maxPoles)
            throw ExchangeError(file,
                                "more than " + std::to_string(options.maxPoles) + " control points in all");
        surfaces.push_back(std::move(*s.surface));
    }
    for (const auto& [problem, labels] : problems) {
        std::string which;
        std::size_t named = 0;
        for (const std::string& label : labels)
            if (!label.empty() && ++named <= 10) which += (named == 1 ? "" : ", ") + label;
        if (named > 10) which += ", ...";
        const std::size_t count = labels.size();
        result.warnings.push_back(name + ": " + std::to_string(count) + (count == 1 ? " face" : " faces") +
                                  " left out: " + problem +
                                  (named == 0 ? "" : (count == 1 ? ", face " : ", faces ") + which));
    }
    if (surfaces.size() > 1)
        if (auto joined = joinPatches(surfaces, 1e-11 * netSize(surfaces))) surfaces = {std::move(*joined)};
    for (std::size_t k = 0; k < surfaces.size(); ++k)
        model.surfaces.push_back({surfaces.size() == 1 ? name : name + "_" + std::to_string(k + 1),
                                  std::move(surfaces[k]),
                                  part.colour,
                                  {}});
}

/// A part named "SURFACE/NAME": its faces' loops become that surface's curves.
void addCurves(const NamedShape& part, CadSurface& surface, CadImport& result) {
    SurfaceCurves curves;
    curves.name = part.name.substr(surface.name.size() + 1);
    for (TopExp_Explorer f(part.shape, TopAbs_FACE); f.More(); f.Next()) {
        std::string problem;
        auto loops = faceLoops(TopoDS::Face(f.Current()), problem);
        if (!loops) {
            result.warnings.push_back(part.name + ": left out: " + problem);
            return;
        }
        unwrapLoops(*loops, surface.surface);
        outerLoopsFirst(*loops);
        for (auto& loop : *loops) curves.loops.push_back(std::move(loop));
    }
    surface.curves.push_back(std::move(curves));
}

CadModel modelOf(const std::vector<NamedShape>& parts, CadImport& result, const CadReadOptions& options,
                 const std::string& file, const FileFaces& fileFaces) {
    std::size_t faces = 0, poles = 0;
    for (const NamedShape& part : parts)
        for (TopExp_Explorer f(part.shape, TopAbs_FACE); f.More(); f.Next())
            if (++faces > options.maxFaces)
                throw ExchangeError(file, "more than " + std::to_string(options.maxFaces) + " faces");
    auto curvesOf = [&](const NamedShape& part) {
        const std::size_t slash = part.name.find('/');
        for (const NamedShape& other : parts)
            if (slash != std::string::npos && other.name == part.name.substr(0, slash)) return true;
        return false;
    };
    // Names unique, as the writer needs them: a part placed more than once in an assembly, and a
    // surface "NAME_k" that meets another's name, get "_2", "_3", ... (the first keeps its name).
    std::set<std::string> taken;
    for (const NamedShape& part : parts) taken.insert(part.name);
    const auto unique = [&taken](const std::string& name, std::set<std::string>& used) {
        std::string free = name;
        for (int k = 2; used.count(free) > 0 || (free != name && taken.count(free) > 0); ++k)
            free = name + "_" + std::to_string(k);
        used.insert(free);
        return free;
    };
    std::set<std::string> partNames;
    CadModel model;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (curvesOf(parts[i])) continue;
        const std::string name =
            unique(parts[i].name.empty() ? "part_" + std::to_string(i + 1) : parts[i].name, partNames);
        if (!TopExp_Explorer(parts[i].shape, TopAbs_FACE).More())
            result.warnings.push_back(name + ": no faces (curves or points only), left out");
        else
            addSurfaces(parts[i], name, model, result, poles, options, file, fileFaces);
    }
    std::set<std::string> surfaceNames;
    for (const CadSurface& s : model.surfaces) taken.insert(s.name);
    for (CadSurface& s : model.surfaces) s.name = unique(s.name, surfaceNames);
    for (const NamedShape& part : parts) {
        if (!curvesOf(part)) continue;
        const std::string owner = part.name.substr(0, part.name.find('/'));
        auto it = std::find_if(model.surfaces.begin(), model.surfaces.end(),
                               [&](const CadSurface& s) { return s.name == owner; });
        if (it == model.surfaces.end())
            result.warnings.push_back(part.name + ": left out: its surface " + owner +
                                      " did not come in whole");
        else
            addCurves(part, *it, result);
    }
    if (model.surfaces.empty()) {
        // The first face left out says why: one OpenCASCADE could not make, else one read and refused.
        const std::size_t all = faces + fileFaces.lost.size();
        const auto why = [&]() -> std::string {
            if (!fileFaces.lost.empty()) return ": " + fileFaces.lost.front();
            for (const std::string& w : result.warnings)
                if (w.find(" left out: ") != std::string::npos) return ": " + w;
            return result.warnings.empty() ? "" : ": " + result.warnings.front();
        };
        throw ExchangeError(file, all == 0
                                      ? "no surfaces in it (no faces at all)"
                                      : "no B-spline surface could be taken from its " + std::to_string(all) +
                                            (all == 1 ? " face" : " faces") + why());
    }
    return model;
}

/// The read itself, in the child process readCadFile starts (the lock is held by its parent).
CadImport readHere(const std::filesystem::path& path, const CadReadOptions& options,
                   const std::string& unit) {
    const std::string file = path.string();
    CadImport result;
    OcctSession session(unit, OcctSession::Locking::AlreadyHeld);
    const opencascade::handle<MessageCollector> messages = new MessageCollector;
    Message::DefaultMessenger()->AddPrinter(messages);  // for this child's life
    try {
        const opencascade::handle<TDocStd_Document> document = session.newDocument();
        std::string modelName;
        const FileFaces faces = cadFormatOf(path) == CadFormat::Step
                                    ? readStep(file, document, result, *messages)
                                    : readIges(file, document, result, *messages, modelName);
        const std::vector<NamedShape> parts = documentParts(document, modelName);
        result.model = modelOf(parts, result, options, file, faces);
        result.model.name = modelName.empty() ? path.stem().string() : modelName;
        result.model.unit = options.unit;
    } catch (const Standard_Failure& e) {
        throw ExchangeError(file, "OpenCASCADE cannot read it: " + failureText(e));
    }
    return result;
}

}  // namespace

CadImport readCadFile(const std::filesystem::path& path, const CadReadOptions& options) {
    const std::string file = path.string();
    cadFormatOf(path);
    const std::optional<std::string> unit = occtUnitCode(options.unit);
    if (!unit)
        throw ExchangeError(file,
                            "the requested length unit '" + options.unit + "' is not one the program knows");
    checkFile(path, options);
    const auto lock = OcctSession::lock();
    const std::string bytes = runIsolated([&] { return encodeImport(readHere(path, options, *unit)); }, file,
                                          options.maxMemoryBytes, options.maxSeconds);
    try {
        return decodeImport(bytes);
    } catch (const std::exception& e) {
        throw ExchangeError(file, std::string("the reader's answer cannot be used: ") + e.what());
    }
}

}  // namespace geom::exchange
