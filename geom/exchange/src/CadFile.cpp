#include "geom/exchange/CadFile.h"

#include "CadDocument.h"
#include "FailureText.h"
#include "OcctSession.h"
#include "ShapeBuild.h"
#include "Units.h"

#include "geom/GeometryError.h"
#include "geom/exchange/ExchangeError.h"
#include "geom/exchange/OcctConversion.h"

#include <IGESCAFControl_Writer.hxx>
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

#include <algorithm>
#include <cctype>
#include <fstream>
#include <functional>
#include <set>

namespace geom::exchange {

namespace {

/// The parts a model is written as: each surface's patch faces, then its curve sets' faces.
std::vector<NamedShape> modelParts(const CadModel& model, const std::string& file) {
    std::vector<NamedShape> parts;
    std::set<std::string> names;
    for (std::size_t i = 0; i < model.surfaces.size(); ++i) {
        const CadSurface& s = model.surfaces[i];
        if (s.name.empty() || s.name.find('/') != std::string::npos || !names.insert(s.name).second)
            throw ExchangeError(file, "surface " + std::to_string(i + 1) + " is named '" + s.name +
                                          "': names must be unique, not empty and without '/'");
        try {
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
    IGESCAFControl_Writer writer;  // unit and faces mode from the session's settings
    writer.SetNameMode(true);
    writer.SetColorMode(true);
    if (!writer.Transfer(document))
        throw ExchangeError(file, "OpenCASCADE could not translate the model to IGES");
    writer.ComputeModel();
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
