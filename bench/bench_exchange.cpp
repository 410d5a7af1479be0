// IGES and STEP export of one large component, as the design program's EXPORT writes it: the
// transport's fuselage (apps/acsynt/data/transport.acm, 160 Bézier patches) with each knot span
// split in 1, 2, 3, 4, 6 and 7 by knot insertion (up to 7,840 patches; a saved model holds at most
// 8,192), written by geom::exchange::writeCadFile. Same-run baselines: STEP of
// the same model, and OpenCASCADE's own IGES writer (IGESCAFControl_Writer::Transfer, with its
// shape processing) on the same faces up to 2,048 patches, beyond which its time grows as the
// square of the patches. Prints the figures and ends with one JSON object.
#include "BenchClock.h"
#include "acsynt/Model.h"
#include "geom/BezierExtraction.h"
#include "geom/KnotInsertion.h"
#include "geom/exchange/CadFile.h"
#include "geom/exchange/OcctConversion.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <Precision.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using bench::cpuSeconds;
using bench::wallSeconds;

/// Each knot span of one direction's domain [from, to] split into `parts` equal spans.
std::vector<double> splitSpans(const std::vector<double>& knots, double from, double to, int parts) {
    std::vector<double> inserted;
    for (std::size_t i = 0; i + 1 < knots.size(); ++i)
        if (knots[i + 1] > knots[i] && knots[i] >= from && knots[i + 1] <= to)
            for (int k = 1; k < parts; ++k)
                inserted.push_back(knots[i] + (knots[i + 1] - knots[i]) * k / parts);
    return inserted;
}

std::size_t patchCount(const geom::Surface& s) {
    return geom::extractBezier(s).size();
}

/// The surface with each knot span of both directions split into `parts`.
geom::Surface refined(const geom::Surface& base, int parts) {
    const geom::Surface u =
        geom::refineKnotsU(base, splitSpans(base.knotsU, base.domainStartU(), base.domainEndU(), parts));
    return geom::refineKnotsV(u, splitSpans(u.knotsV, u.domainStartV(), u.domainEndV(), parts));
}

/// OpenCASCADE's own IGES writer on the faces writeCadFile writes (one face a Bézier patch).
void writeStockIges(const geom::Surface& surface, const std::string& file) {
    BRep_Builder b;
    TopoDS_Compound faces;
    b.MakeCompound(faces);
    for (const geom::BezierSurfacePiece& piece : geom::extractBezier(surface))
        b.Add(faces, BRepBuilderAPI_MakeFace(
                         geom::exchange::toOcct(piece.surface, geom::exchange::Periodicity::Never),
                         Precision::Confusion())
                         .Face());
    opencascade::handle<TDocStd_Document> document;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
    const TDF_Label label = XCAFDoc_DocumentTool::ShapeTool(document->Main())->AddShape(faces, false);
    TDataStd_Name::Set(label, "fuselage");
    IGESCAFControl_Writer writer;
    writer.SetNameMode(true);
    if (!writer.Transfer(document) || !writer.Write(file.c_str()))
        std::fprintf(stderr, "stock IGES failed\n");
    XCAFApp_Application::GetApplication()->Close(document);
}

struct Timing {
    double cpu = 0, wall = 0;
};

template <class F>
Timing timed(F&& f) {
    const double c = cpuSeconds(), w = wallSeconds();
    f();
    return {cpuSeconds() - c, wallSeconds() - w};
}

}  // namespace

int main() {
    const acsynt::Model transport = acsynt::loadModel(std::string(ACSYNT_DATA_DIR) + "/transport.acm");
    const acsynt::Component* fuselage = nullptr;
    for (const acsynt::Component& c : transport.components)
        if (c.name == "fuselage") fuselage = &c;
    if (!fuselage) return std::fprintf(stderr, "no fuselage in the transport model\n"), 1;
    const auto dir = std::filesystem::temp_directory_path() / "bench_exchange";
    std::filesystem::create_directories(dir);
    {  // OpenCASCADE's first write sets up its translators: not a cost of the first size.
        geom::exchange::CadModel warm{"warm", "M", {{"fuselage", fuselage->surface, std::nullopt, {}}}};
        geom::exchange::writeCadFile(warm, dir / "warm.igs");
        geom::exchange::writeCadFile(warm, dir / "warm.step");
        writeStockIges(fuselage->surface, (dir / "warm_stock.igs").string());
    }
    const double start = cpuSeconds(), wallStart = wallSeconds();
    std::string json = "{";
    double firstIges = 0, firstStep = 0, lastIges = 0, lastStep = 0;
    std::printf("%8s %10s %10s %12s %12s %14s\n", "patches", "IGES s", "STEP s", "IGES us/p", "STEP us/p",
                "stock IGES s");
    for (const int parts : {1, 2, 3, 4, 6, 7}) {
        geom::exchange::CadModel model;
        model.name = "transport";
        model.surfaces.push_back(
            {"fuselage", refined(fuselage->surface, parts), glm::dvec3(0.85, 0.85, 0.88), {}});
        const std::size_t patches = patchCount(model.surfaces[0].surface);
        const Timing iges = timed([&] { geom::exchange::writeCadFile(model, dir / "model.igs"); });
        const Timing step = timed([&] { geom::exchange::writeCadFile(model, dir / "model.step"); });
        Timing stock{-1, -1};
        if (patches <= 2048)
            stock = timed([&] { writeStockIges(model.surfaces[0].surface, (dir / "stock.igs").string()); });
        const double igesPer = 1e6 * iges.cpu / double(patches), stepPer = 1e6 * step.cpu / double(patches);
        if (firstIges == 0) firstIges = igesPer, firstStep = stepPer;
        lastIges = igesPer, lastStep = stepPer;
        std::printf("%8zu %10.3f %10.3f %12.1f %12.1f %14s\n", patches, iges.cpu, step.cpu, igesPer, stepPer,
                    stock.cpu >= 0 ? std::to_string(stock.cpu).c_str() : "-");
        const std::string row = "\"split" + std::to_string(parts) + "_";
        json += row + "patches\": " + std::to_string(patches) + ", " + row +
                "iges_cpu_s\": " + std::to_string(iges.cpu) + ", " + row +
                "iges_wall_s\": " + std::to_string(iges.wall) + ", " + row +
                "step_cpu_s\": " + std::to_string(step.cpu) + ", " + row +
                "iges_us_per_patch\": " + std::to_string(igesPer) + ", " + row +
                "step_us_per_patch\": " + std::to_string(stepPer) + ", ";
        if (stock.cpu >= 0)
            json += row + "stock_iges_cpu_s\": " + std::to_string(stock.cpu) + ", " + row +
                    "stock_over_iges\": " + std::to_string(stock.cpu / iges.cpu) + ", ";
    }
    std::filesystem::remove_all(dir);
    json += "\"iges_per_patch_growth\": " + std::to_string(lastIges / firstIges) +
            ", \"step_per_patch_growth\": " + std::to_string(lastStep / firstStep) +
            ", \"cpu_seconds\": " + std::to_string(cpuSeconds() - start) +
            ", \"wall_seconds\": " + std::to_string(wallSeconds() - wallStart) + "}";
    std::printf("%s\n", json.c_str());
}
