#include "geom/exchange/CadFile.h"

#include "CadDocument.h"
#include "FailureText.h"
#include "IgesDocumentWriter.h"
#include "OcctSession.h"
#include "ShapeBuild.h"
#include "StepReals.h"
#include "Units.h"

#include "geom/GeometryError.h"
#include "geom/exchange/ExchangeError.h"
#include "geom/exchange/OcctConversion.h"

#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESData_IGESWriter.hxx>
#include <IGESSelect_WorkLibrary.hxx>
#include <Interface_FloatWriter.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <TCollection_HAsciiString.hxx>
#include <XSControl_WorkSession.hxx>

#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <set>

namespace geom::exchange {

namespace {

/// Why a name would not come back as written, or empty: the readers give back printable ASCII
/// only (STEP's reads UTF-8 as Latin-1; a control character breaks an IGES file), and trim spaces
/// at either end.
std::string unwritableName(const std::string& name) {
    for (unsigned char c : name) {
        if (c < 0x20 || c == 0x7F) return "a control character";
        if (c >= 0x80) return "a character outside printable ASCII";
    }
    if (!name.empty() && (name.front() == ' ' || name.back() == ' ')) return "a space at an end";
    return {};
}

/// Refuses what a reader would not give back: a real beyond the STEP reader's limit (1e100, which
/// OpenCASCADE takes for infinite; the geometry's own validation refuses NaN) and a colour that is
/// not RGB in [0, 1].
void checkWritable(const CadSurface& s) {
    const auto large = [](double v) { return std::abs(v) > kStepRealLimit; };
    const auto point = [&](const glm::dvec3& p) { return large(p.x) || large(p.y) || large(p.z); };
    const Surface& g = s.surface;
    if (std::any_of(g.knotsU.begin(), g.knotsU.end(), large) ||
        std::any_of(g.knotsV.begin(), g.knotsV.end(), large) ||
        std::any_of(g.points.begin(), g.points.end(), point) ||
        std::any_of(g.weights.begin(), g.weights.end(), large))
        throw GeometryError("a knot, control point or weight beyond 1e100, which no reader gives back");
    for (const SurfaceCurves& c : s.curves)
        for (const SurfaceLoop& l : c.loops)
            if (std::any_of(l.points.begin(), l.points.end(), point))
                throw GeometryError("curves '" + c.name +
                                    "': a point beyond 1e100, which no reader gives back");
    if (s.colour && !(glm::all(glm::greaterThanEqual(*s.colour, glm::dvec3(0.0))) &&
                      glm::all(glm::lessThanEqual(*s.colour, glm::dvec3(1.0)))))
        throw GeometryError("its colour is not RGB within [0, 1]");
}

/// The parts a model is written as: each surface's patch faces, then its curve sets' faces.
std::vector<NamedShape> modelParts(const CadModel& model, const std::string& file) {
    if (const std::string why = unwritableName(model.name); !why.empty())
        throw ExchangeError(file, "the model's name '" + model.name + "' has " + why);
    std::vector<NamedShape> parts;
    std::set<std::string> names;
    for (std::size_t i = 0; i < model.surfaces.size(); ++i) {
        const CadSurface& s = model.surfaces[i];
        if (s.name.empty() || s.name.find('/') != std::string::npos || !names.insert(s.name).second)
            throw ExchangeError(file, "surface " + std::to_string(i + 1) + " is named '" + s.name +
                                          "': names must be unique, not empty and without '/'");
        const auto checkName = [&](const std::string& name) {
            if (const std::string why = unwritableName(name); !why.empty())
                throw ExchangeError(file, "surface '" + s.name + "': the name '" + name + "' has " + why);
        };
        checkName(s.name);
        for (const SurfaceCurves& c : s.curves) checkName(c.name);
        try {
            checkWritable(s);
            parts.push_back({s.name, patchFaces(s.surface), s.colour});
            if (s.curves.empty()) continue;
            const opencascade::handle<Geom_BSplineSurface> support = toOcct(s.surface);
            for (const SurfaceCurves& c : s.curves) {
                try {
                    parts.push_back({s.name + "/" + c.name, loopFaces(support, c.loops), s.colour});
                } catch (const GeometryError& e) {
                    throw GeometryError("curves '" + c.name + "': " + e.what());
                }
            }
        } catch (const GeometryError& e) {
            throw ExchangeError(file, "surface '" + s.name + "': " + e.what());
        } catch (const Standard_Failure& e) {
            throw ExchangeError(file, "surface '" + s.name + "': OpenCASCADE refused it: " + failureText(e));
        }
    }
    return parts;
}

/// Full precision: OpenCASCADE's writers keep 12 (STEP) or 10 (IGES) significant digits; 17 give
/// every double back exactly. (Its zero suppression cuts the exponent off such numbers.)
void fullPrecision(Interface_FloatWriter& writer) {
    writer.SetFormat("%.16E");
}

void writeText(const std::string& file, const std::function<bool(std::ostream&)>& print) {
    std::ofstream out(file, std::ios::binary);
    if (!out || !print(out) || !out.flush()) throw ExchangeError(file, "cannot be written");
}

void writeStep(const opencascade::handle<TDocStd_Document>& document, const std::string& file) {
    STEPCAFControl_Writer writer;
    writer.SetNameMode(true);
    writer.SetColorMode(true);
    if (!writer.Transfer(document, STEPControl_AsIs))
        throw ExchangeError(file, "OpenCASCADE could not translate the model to STEP");
    // What STEPControl_Writer::Write does, with full precision.
    STEPControl_Writer& translated = writer.ChangeWriter();
    StepData_StepWriter out(translated.Model());
    fullPrecision(out.FloatWriter());
    out.SendModel(opencascade::handle<StepData_Protocol>::DownCast(translated.WS()->Protocol()));
    writeText(file, [&](std::ostream& s) { return out.Print(s); });
}

void writeIges(const opencascade::handle<TDocStd_Document>& document, const std::string& file,
               const std::string& modelName) {
    IgesDocumentWriter writer;  // the unit from the session's settings; faces (144 on 128)
    writer.SetNameMode(true);
    writer.SetColorMode(true);
    if (!writer.transferDocument(document))
        throw ExchangeError(file, "OpenCASCADE could not translate the model to IGES");
    // The sender's product name carries the model name (STEP has its assembly for it).
    IGESData_GlobalSection header = writer.Model()->GlobalSection();
    header.SetSendName(new TCollection_HAsciiString(modelName.c_str()));
    header.SetFileName(new TCollection_HAsciiString(std::filesystem::path(file).filename().string().c_str()));
    writer.Model()->SetGlobalSection(header);
    // What IGESControl_Writer::Write does, with full precision.
    IGESData_IGESWriter out(writer.Model());
    fullPrecision(out.FloatWriter());
    out.SendModel(IGESSelect_WorkLibrary::DefineProtocol());
    writeText(file, [&](std::ostream& s) { return out.Print(s); });
}

}  // namespace

CadFormat cadFormatOf(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".igs" || ext == ".iges") return CadFormat::Iges;
    if (ext == ".stp" || ext == ".step") return CadFormat::Step;
    throw ExchangeError(path.string(), "unknown extension '" + ext + "': use .step, .stp, .igs or .iges");
}

void writeCadFile(const CadModel& model, const std::filesystem::path& path) {
    const std::string file = path.string();
    const CadFormat format = cadFormatOf(path);
    const std::optional<std::string> unit = occtUnitCode(model.unit);
    if (!unit)
        throw ExchangeError(file,
                            "the model's length unit '" + model.unit + "' is not one the program knows");
    if (model.surfaces.empty()) throw ExchangeError(file, "the model has no surfaces to write");
    const std::vector<NamedShape> parts = modelParts(model, file);
    OcctSession session(*unit);
    try {
        const opencascade::handle<TDocStd_Document> document = session.newDocument();
        fillDocument(document, model.name, parts, format);
        if (format == CadFormat::Step)
            writeStep(document, file);
        else
            writeIges(document, file, model.name);
    } catch (const Standard_Failure& e) {
        throw ExchangeError(file, "OpenCASCADE failed to write it: " + failureText(e));
    }
}

}  // namespace geom::exchange
