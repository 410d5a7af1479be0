// The exported transport read by OpenCASCADE's own readers: 376 B-spline faces, names, colours,
// entity types and the model's bounding box.
#include "ExchangeTestUtil.h"

#include "geom/GridEvaluator.h"
#include "geom/exchange/CadFile.h"

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <Precision.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <StepData_StepModel.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <chrono>
#include <map>
#include <set>

namespace test_transport_occt {

using namespace geom::exchange;

namespace {

/// The transport's box from its surfaces sampled densely (50 points per control point each way).
Bnd_Box transportBox() {
    Bnd_Box box;
    for (const auto& c : exchange_test::transport().components) {
        const geom::Surface& s = c.surface;
        const std::size_t n = 50 * std::max(s.countU, s.countV);
        std::vector<double> us, vs;
        for (std::size_t k = 0; k <= n; ++k) {
            us.push_back(s.domainStartU() + (s.domainEndU() - s.domainStartU()) * double(k) / double(n));
            vs.push_back(s.domainStartV() + (s.domainEndV() - s.domainStartV()) * double(k) / double(n));
        }
        for (const geom::GridSample& g : geom::GridEvaluator(s).evaluate(us, vs))
            box.Add(gp_Pnt(g.point.x, g.point.y, g.point.z));
    }
    return box;
}

/// Faces of the shape, and how many lie on B-spline surfaces.
std::pair<int, int> countFaces(const TopoDS_Shape& shape) {
    int faces = 0, bsplines = 0;
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next(), ++faces)
        bsplines +=
            !opencascade::handle<Geom_BSplineSurface>::DownCast(BRep_Tool::Surface(TopoDS::Face(f.Current())))
                 .IsNull();
    return {faces, bsplines};
}

void requireBox(const TopoDS_Shape& shape, const Bnd_Box& expected) {
    Bnd_Box box;
    BRepBndLib::AddOptimal(shape, box, false, false);
    double a[6], b[6];
    box.Get(a[0], a[1], a[2], a[3], a[4], a[5]);
    expected.Get(b[0], b[1], b[2], b[3], b[4], b[5]);
    // Dense sampling comes within 1e-4 m of the exact box; OpenCASCADE adds its tolerance.
    for (int k = 0; k < 6; ++k) CHECK(std::abs(a[k] - b[k]) <= 2e-4);
}

std::string nameOf(const TDF_Label& label) {
    opencascade::handle<TDataStd_Name> name;
    return label.FindAttribute(TDataStd_Name::GetID(), name)
               ? TCollection_AsciiString(name->Get()).ToCString()
               : "";
}

/// The names of the document's parts (the leaves under its free shapes).
std::set<std::string> partNames(const opencascade::handle<TDocStd_Document>& doc) {
    const auto shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    TDF_LabelSequence labels;
    shapes->GetShapes(labels);
    std::set<std::string> names;
    for (int i = 1; i <= labels.Length(); ++i)
        if (!shapes->IsAssembly(labels.Value(i))) names.insert(nameOf(labels.Value(i)));
    return names;
}

std::set<std::string> componentNames() {
    std::set<std::string> names;
    for (const auto& c : exchange_test::transport().components) names.insert(c.name);
    return names;
}

}  // namespace

TEST_CASE("transport: OpenCASCADE's STEP reader finds 376 B-spline faces, the products and the box",
          "[exchange][transport]") {
    const auto dir = exchange_test::scratch("transport_step");
    const auto start = std::chrono::steady_clock::now();
    writeCadFile(exchange_test::cadModelOf(exchange_test::transport()), dir / "transport.step");
    WARN("transport.step written in "
         << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s, "
         << std::filesystem::file_size(dir / "transport.step") << " bytes");
    Interface_Static::SetCVal("xstep.cascade.unit", "M");
    STEPControl_Reader reader;
    REQUIRE(reader.ReadFile((dir / "transport.step").c_str()) == IFSelect_RetDone);
    REQUIRE(reader.TransferRoots() > 0);
    const auto [faces, bsplines] = countFaces(reader.OneShape());
    CHECK(faces == 376);
    CHECK(bsplines == 376);
    requireBox(reader.OneShape(), transportBox());
    // The file's own entities: one advanced face on one B-spline surface per patch, a product each.
    std::map<std::string, int> types;
    const auto model = reader.StepModel();
    for (int i = 1; i <= model->NbEntities(); ++i) ++types[model->Entity(i)->DynamicType()->Name()];
    CHECK(types["StepShape_AdvancedFace"] == 376);
    CHECK(types["StepGeom_BSplineSurfaceWithKnots"] == 376);
    CHECK(types["StepBasic_Product"] == 9);  // the model and its 8 components

    opencascade::handle<TDocStd_Document> doc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    STEPCAFControl_Reader named;
    REQUIRE(named.ReadFile((dir / "transport.step").c_str()) == IFSelect_RetDone);
    REQUIRE(named.Transfer(doc));
    CHECK(partNames(doc) == componentNames());
    TDF_LabelSequence free;
    XCAFDoc_DocumentTool::ShapeTool(doc->Main())->GetFreeShapes(free);
    REQUIRE(free.Length() == 1);
    CHECK(nameOf(free.First()) == "transport");
    XCAFApp_Application::GetApplication()->Close(doc);  // left open, its labels and shapes leak
}

TEST_CASE("transport: OpenCASCADE's IGES reader finds 376 B-spline faces (144 on 128) in named groups",
          "[exchange][transport]") {
    const auto dir = exchange_test::scratch("transport_iges");
    writeCadFile(exchange_test::cadModelOf(exchange_test::transport()), dir / "transport.igs");
    Interface_Static::SetCVal("xstep.cascade.unit", "M");
    IGESControl_Reader reader;
    REQUIRE(reader.ReadFile((dir / "transport.igs").c_str()) == IFSelect_RetDone);
    REQUIRE(reader.TransferRoots() > 0);
    const auto [faces, bsplines] = countFaces(reader.OneShape());
    CHECK(faces == 376);
    CHECK(bsplines == 376);
    requireBox(reader.OneShape(), transportBox());
    std::map<int, int> types;
    std::set<std::string> groups;
    const auto model = reader.IGESModel();
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const auto entity = model->Entity(i);
        ++types[entity->TypeNumber()];
        if (entity->TypeNumber() == 402 && entity->HasName()) groups.insert(entity->NameValue()->ToCString());
    }
    CHECK(types[128] == 376);  // a B-spline surface per patch
    CHECK(types[144] == 376);  // a face on it, bounded by the surface's own boundary
    CHECK(types[142] == 0);    // curves on surfaces come with mapped curves only
    CHECK(types[402] == 8);    // a named group per component
    CHECK(groups == componentNames());
    CHECK(std::string(model->GlobalSection().SendName()->ToCString()) == "transport");
    CHECK(model->GlobalSection().UnitFlag() == 6);  // metres
    // As OpenCASCADE's own writer fills them: the faces' tolerance, and the largest coordinate of
    // the shapes' boxes (their control points' bounds, so at least the model's extent).
    CHECK(model->GlobalSection().Resolution() == Approx(Precision::Confusion()));
    double box[6];
    transportBox().Get(box[0], box[1], box[2], box[3], box[4], box[5]);
    double extent = 0.0;
    for (double b : box) extent = std::max(extent, std::abs(b));
    CHECK(model->GlobalSection().MaxCoord() >= extent - 2e-4);
    CHECK(model->GlobalSection().MaxCoord() <= 1.1 * extent);

    opencascade::handle<TDocStd_Document> doc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    IGESCAFControl_Reader named;
    REQUIRE(named.ReadFile((dir / "transport.igs").c_str()) == IFSelect_RetDone);
    REQUIRE(named.Transfer(doc));
    CHECK(partNames(doc) == componentNames());
    XCAFApp_Application::GetApplication()->Close(doc);
}

TEST_CASE("transport: our reader gives back its 8 components and 376 patches from both files",
          "[exchange][transport]") {
    const auto dir = exchange_test::scratch("transport_back");
    const acsynt::Model& model = exchange_test::transport();
    for (const char* name : {"transport.step", "transport.igs"}) {
        INFO(name);
        writeCadFile(exchange_test::cadModelOf(model), dir / name);
        const auto start = std::chrono::steady_clock::now();
        const CadImport read = readCadFile(dir / name);
        WARN(name << " read back in "
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s");
        CHECK(read.model.name == "transport");
        REQUIRE(read.model.surfaces.size() == model.components.size());
        std::size_t patches = 0;
        for (std::size_t i = 0; i < model.components.size(); ++i) {
            INFO(model.components[i].name);
            CHECK(read.model.surfaces[i].name == model.components[i].name);
            exchange_test::requireSameSurface(read.model.surfaces[i].surface, model.components[i].surface);
            patches += acsynt::buildPatches(read.model.surfaces[i].surface).patches.size();
        }
        CHECK(patches == 376);
    }
}

}  // namespace test_transport_occt
