// Files written by OpenCASCADE itself, from shapes it built, read by our reader.
#include "ExchangeTestUtil.h"

#include "geom/exchange/Bicubic.h"
#include "geom/exchange/CadFile.h"
#include "geom/exchange/ExchangeError.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <GC_MakeCircle.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>

#include <set>

namespace test_occt_written {

using namespace geom::exchange;

namespace {

/// A box, a cylinder (its discs are planes trimmed by circles), a sphere and a torus, in
/// millimetres, side by side, every face converted to a B-spline by OpenCASCADE.
TopoDS_Shape primitives() {
    BRep_Builder b;
    TopoDS_Compound all;
    b.MakeCompound(all);
    b.Add(all, BRepPrimAPI_MakeBox(100, 60, 40).Shape());
    b.Add(all, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(200, 0, 0), gp::DZ()), 30, 80).Shape());
    b.Add(all, BRepPrimAPI_MakeSphere(gp_Pnt(400, 0, 0), 50).Shape());
    b.Add(all, BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(600, 0, 0), gp::DZ()), 70, 20).Shape());
    return BRepBuilderAPI_NurbsConvert(all, true).Shape();
}

/// How far p (metres) lies from the nearest of the primitives' surfaces.
double offPrimitives(const glm::dvec3& mm) {
    const glm::dvec3 p = mm * 1000.0;  // back to millimetres
    auto clampTo = [](double x, double lo, double hi) { return std::max(lo, std::min(hi, x)); };
    // Box: inside its bounds, on one of its sides.
    const glm::dvec3 lo(0, 0, 0), hi(100, 60, 40);
    double outside = 0, side = INFINITY;
    for (int k = 0; k < 3; ++k) {
        outside = std::max(outside, std::abs(p[k] - clampTo(p[k], lo[k], hi[k])));
        side = std::min({side, std::abs(p[k] - lo[k]), std::abs(p[k] - hi[k])});
    }
    const double box = std::max(outside, side);
    const glm::dvec3 c = p - glm::dvec3(200, 0, 0);
    const double cylinder =
        std::max(std::abs(std::hypot(c.x, c.y) - 30), std::abs(c.z - clampTo(c.z, 0, 80)));
    const double sphere = std::abs(glm::length(p - glm::dvec3(400, 0, 0)) - 50);
    const glm::dvec3 t = p - glm::dvec3(600, 0, 0);
    const double torus = std::abs(std::hypot(std::hypot(t.x, t.y) - 70, t.z) - 20);
    return std::min({box, cylinder, sphere, torus}) / 1000.0;
}

double largestOffset(const geom::Surface& s) {
    double off = 0;
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j)
            off = std::max(off, offPrimitives(geom::evaluate(
                                    s, s.domainStartU() + (s.domainEndU() - s.domainStartU()) * i / 10,
                                    s.domainStartV() + (s.domainEndV() - s.domainStartV()) * j / 10)));
    return off;
}

void checkImport(const CadImport& read) {
    // The box's six faces, the cylinder's side, the sphere and the torus; the cylinder's discs
    // are trimmed by circles inside their planes and are left out with a warning.
    CHECK(read.model.surfaces.size() == 9);
    REQUIRE(read.warnings.size() == 1);
    CHECK_THAT(read.warnings.front(), Catch::Contains("2 faces left out: a face trimmed inside its"));
    std::set<std::string> names;
    for (const CadSurface& s : read.model.surfaces) {
        INFO(s.name);
        names.insert(s.name);
        CHECK(largestOffset(s.surface) <= 1e-9);  // millimetres read as metres, exactly on the shapes
        const BicubicSurface b = toBicubic(s.surface, 1e-6);
        CHECK(b.surface.degreeU == 3);
        CHECK(b.surface.degreeV == 3);
        CHECK_FALSE(b.surface.rational());
        CHECK(b.exact == !s.surface.rational());
        CHECK(b.maxError <= 1e-6);
        CHECK(largestOffset(b.surface) <= b.maxError + 1e-9);
    }
    CHECK(names.size() == read.model.surfaces.size());  // unique names
}

}  // namespace

TEST_CASE("OpenCASCADE's files: a STEP file it wrote from primitives it built", "[exchange][occt]") {
    const auto dir = exchange_test::scratch("occt_step");
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    Interface_Static::SetCVal("write.step.unit", "MM");
    STEPControl_Writer writer;
    REQUIRE(writer.Transfer(primitives(), STEPControl_AsIs) == IFSelect_RetDone);
    REQUIRE(writer.Write((dir / "primitives.step").c_str()) == IFSelect_RetDone);
    const CadImport read = readCadFile(dir / "primitives.step");
    CHECK(read.fileUnit == "millimetre");
    checkImport(read);
}

TEST_CASE("OpenCASCADE's files: an IGES file it wrote from primitives it built", "[exchange][occt]") {
    const auto dir = exchange_test::scratch("occt_iges");
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    IGESControl_Writer writer("MM", 0);
    REQUIRE(writer.AddShape(primitives()));
    writer.ComputeModel();
    REQUIRE(writer.Write((dir / "primitives.igs").c_str()));
    const CadImport read = readCadFile(dir / "primitives.igs");
    CHECK(read.fileUnit == "MM");
    checkImport(read);
}

TEST_CASE("OpenCASCADE's files: cones, a sphere and a filleted box in STEP, unconverted",
          "[exchange][occt]") {
    // BRepTools::UVBounds puts these faces' boxes past their surfaces' bounds by rounding (a
    // cone's u from -4e-13, a corner sphere's v from -pi/2 - 3e-13), which OpenCASCADE's
    // conversion to a B-spline refuses: the reader must keep the cones and the fillets' corners.
    const auto dir = exchange_test::scratch("occt_quadrics");
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(100, 60, 40).Shape();
    BRepFilletAPI_MakeFillet fillet(box);
    for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) fillet.Add(5, TopoDS::Edge(e.Current()));
    struct Case {
        std::string name;
        TopoDS_Shape shape;
        std::size_t discs;  // planes trimmed by circles: left out, warned
    };
    const std::vector<Case> shapes{
        {"cone", BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 0, 0), gp::DZ()), 30, 0, 60).Shape(), 1},
        {"frustum", BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 0, 0), gp::DZ()), 30, 10, 60).Shape(), 2},
        {"sphere", BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), 50).Shape(), 0},
        {"fillet", fillet.Shape(), 0}};
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    Interface_Static::SetCVal("write.step.unit", "MM");
    for (const auto& [name, shape, discs] : shapes) {
        INFO(name);
        std::size_t faces = 0;
        for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) ++faces;
        const auto file = dir / (name + ".step");
        STEPControl_Writer writer;
        REQUIRE(writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone);
        REQUIRE(writer.Write(file.c_str()) == IFSelect_RetDone);
        CadImport read;
        try {
            read = readCadFile(file, {.unit = "MM"});
        } catch (const ExchangeError& e) {
            FAIL_CHECK(e.what());
            continue;
        }
        for (const std::string& w : read.warnings) {
            INFO(w);
            CHECK_THAT(w, Catch::Contains("a face trimmed inside its Plane surface"));
        }
        CHECK(read.warnings.size() == (discs > 0 ? 1 : 0));
        CHECK(read.model.surfaces.size() == faces - discs);  // every other face a surface of its own
        // Every surface lies on the shape OpenCASCADE built, corners and middle.
        double off = 0;
        for (const CadSurface& s : read.model.surfaces)
            for (int i = 0; i <= 4; ++i)
                for (int j = 0; j <= 4; ++j) {
                    const glm::dvec3 p =
                        geom::evaluate(s.surface,
                                       s.surface.domainStartU() +
                                           (s.surface.domainEndU() - s.surface.domainStartU()) * i / 4,
                                       s.surface.domainStartV() +
                                           (s.surface.domainEndV() - s.surface.domainStartV()) * j / 4);
                    BRepExtrema_DistShapeShape distance(
                        BRepBuilderAPI_MakeVertex(gp_Pnt(p.x, p.y, p.z)).Vertex(), shape);
                    REQUIRE(distance.IsDone());
                    off = std::max(off, distance.Value());
                }
        CHECK(off <= 1e-9);
    }
}

TEST_CASE("OpenCASCADE's files: a STEP assembly with one part placed twice", "[exchange][occt]") {
    // Both placements gave surfaces of the same names, and the model read could not be written.
    const auto dir = exchange_test::scratch("occt_assembly");
    opencascade::handle<TDocStd_Document> document;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
    const opencascade::handle<XCAFDoc_ShapeTool> shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
    const TDF_Label part = shapes->AddShape(BRepPrimAPI_MakeBox(10, 20, 30).Shape(), false);
    TDataStd_Name::Set(part, "bracket");
    const TDF_Label assembly = shapes->NewShape();
    TDataStd_Name::Set(assembly, "assy");
    gp_Trsf left, right;
    left.SetTranslation(gp_Vec(100, 0, 0));
    right.SetRotation(gp::OZ(), M_PI / 2);
    shapes->AddComponent(assembly, part, TopLoc_Location(left));
    shapes->AddComponent(assembly, part, TopLoc_Location(right));
    shapes->UpdateAssemblies();
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    Interface_Static::SetCVal("write.step.unit", "MM");
    STEPCAFControl_Writer writer;
    REQUIRE(writer.Transfer(document, STEPControl_AsIs));
    REQUIRE(writer.Write((dir / "assembly.step").c_str()) == IFSelect_RetDone);
    XCAFApp_Application::GetApplication()->Close(document);

    const CadImport read = readCadFile(dir / "assembly.step");
    CHECK(read.warnings.empty());
    REQUIRE(read.model.surfaces.size() == 12);  // a box's six faces, twice
    std::set<std::string> names;
    for (const CadSurface& s : read.model.surfaces) names.insert(s.name);
    CHECK(names.size() == 12);
    CHECK(names.count("bracket_1") == 1);  // the first placement keeps the part's name
    // The model read is written and read back as it is.
    writeCadFile(read.model, dir / "again.step");
    const CadImport again = readCadFile(dir / "again.step");
    REQUIRE(again.model.surfaces.size() == 12);
    for (std::size_t i = 0; i < 12; ++i) {
        CHECK(again.model.surfaces[i].name == read.model.surfaces[i].name);
        exchange_test::requireSameSurface(again.model.surfaces[i].surface, read.model.surfaces[i].surface);
    }
}

TEST_CASE("OpenCASCADE's files: curves only, no surface", "[exchange][occt]") {
    const auto dir = exchange_test::scratch("occt_curves");
    const TopoDS_Edge circle = BRepBuilderAPI_MakeEdge(GC_MakeCircle(gp_Ax2(), 10).Value()).Edge();
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    STEPControl_Writer step;
    REQUIRE(step.Transfer(circle, STEPControl_AsIs) == IFSelect_RetDone);
    REQUIRE(step.Write((dir / "circle.step").c_str()) == IFSelect_RetDone);
    IGESControl_Writer iges("MM", 0);
    REQUIRE(iges.AddShape(circle));
    iges.ComputeModel();
    REQUIRE(iges.Write((dir / "circle.igs").c_str()));
    for (const char* name : {"circle.step", "circle.igs"}) {
        INFO(name);
        CHECK_THROWS_WITH(readCadFile(dir / name),
                          Catch::Contains((dir / name).string()) && Catch::Contains("no surfaces in it"));
    }
}

}  // namespace test_occt_written
