// Models through STEP and IGES files and back: surfaces, names, colours, curves on surfaces, units.
#include "ExchangeTestUtil.h"

#include "geom/DataReduction.h"
#include "geom/exchange/CadFile.h"
#include "geom/exchange/ExchangeError.h"
#include "geom/exchange/OcctConversion.h"

#include <IGESControl_Reader.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

namespace test_cad_files {

// OpenCASCADE's data exchange allocates some tables once and never frees them (IFSelect
// editors, XCAF driver tables): not this program's leaks, for LeakSanitizer in sanitizer builds.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libTKXSBase\nleak:libTKSTEP\nleak:libTKVCAF\nleak:libTKernel\nleak:libTKXCAF\n";
}

using namespace geom::exchange;
using exchange_test::requireSameLoops;
using exchange_test::requireSamePatches;
using exchange_test::requireSameSurface;

namespace {

void requireSameModel(const CadModel& read, const CadModel& written) {
    CHECK(read.name == written.name);
    REQUIRE(read.surfaces.size() == written.surfaces.size());
    for (std::size_t i = 0; i < written.surfaces.size(); ++i) {
        const CadSurface &r = read.surfaces[i], &w = written.surfaces[i];
        INFO(w.name);
        CHECK(r.name == w.name);
        // Every patch the same; the whole surface too where it is clamped or periodic (the
        // reduced one is unclamped: it comes back clamped).
        requireSamePatches(r.surface, w.surface);
        if (w.name != "fuselage_R1") requireSameSurface(r.surface, w.surface);
        // The reduced fuselage is clamped round a smooth seam (ReductionOptions::keepSeams): both
        // readers give it back periodic, the same surface.
        if (w.name == "fuselage_R1")
            CHECK(periodicByConstruction(r.surface, true));
        else
            CHECK(periodicByConstruction(r.surface, true) == periodicByConstruction(w.surface, true));
        REQUIRE(r.colour.has_value());
        CHECK(glm::length(*r.colour - *w.colour) <= 1e-6);
        REQUIRE(r.curves.size() == w.curves.size());
        for (std::size_t k = 0; k < w.curves.size(); ++k) {
            CHECK(r.curves[k].name == w.curves[k].name);
            requireSameLoops(r.curves[k].loops, w.curves[k].loops);
        }
    }
}

}  // namespace

TEST_CASE("files: a model with a reduced surface and curves on surfaces round-trips through STEP and IGES",
          "[exchange][files]") {
    const auto dir = exchange_test::scratch("round_trip");
    const CadModel model = exchange_test::loopModel();
    for (const char* name : {"model.step", "model.igs"}) {
        INFO(name);
        const auto start = std::chrono::steady_clock::now();
        writeCadFile(model, dir / name);
        const auto written = std::chrono::steady_clock::now();
        const CadImport read = readCadFile(dir / name);
        const auto end = std::chrono::steady_clock::now();
        WARN(name << ": written in " << std::chrono::duration<double>(written - start).count()
                  << " s, read in " << std::chrono::duration<double>(end - written).count() << " s");
        for (const auto& w : read.warnings) WARN(w);
        CHECK(read.warnings.empty());
        CHECK(read.model.unit == "M");
        requireSameModel(read.model, model);
    }
    // In IGES each loop is a curve on its surface (142) with its curves in space and in (u, v)
    // (126), bounding a trimmed surface (144) on the whole surface (128).
    IGESControl_Reader reader;
    REQUIRE(reader.ReadFile((dir / "model.igs").c_str()) == IFSelect_RetDone);
    std::map<int, int> types;
    for (int i = 1; i <= reader.IGESModel()->NbEntities(); ++i)
        ++types[reader.IGESModel()->Entity(i)->TypeNumber()];
    CHECK(types[142] == 4);
    CHECK(types[126] == 8);
    CHECK(types[144] == types[128]);
    std::size_t faces = 3;  // the loop faces: the wing's two (one with a hole) and the fuselage's
    for (const CadSurface& s : model.surfaces) faces += geom::extractBezier(s.surface).size();
    CHECK(types[144] == int(faces));
}

TEST_CASE("files: lengths are written in the model's unit and converted on read",
          "[exchange][files][units]") {
    const auto dir = exchange_test::scratch("units");
    const CadModel metres = exchange_test::cadModelOf(exchange_test::transport());
    CadModel millimetres = metres;
    millimetres.unit = "MM";
    for (CadSurface& s : millimetres.surfaces)
        for (glm::dvec3& p : s.surface.points) p *= 1000.0;
    for (const char* name : {"mm.step", "mm.igs"}) {
        INFO(name);
        writeCadFile(millimetres, dir / name);
        const CadImport read = readCadFile(dir / name);  // in metres
        CHECK((read.fileUnit == "millimetre" || read.fileUnit == "MM"));
        REQUIRE(read.model.surfaces.size() == metres.surfaces.size());
        for (std::size_t i = 0; i < metres.surfaces.size(); ++i)
            requireSameSurface(read.model.surfaces[i].surface, metres.surfaces[i].surface, 1e-12);
        CadReadOptions inches;
        inches.unit = "IN";
        const CadImport inInches = readCadFile(dir / name, inches);
        CHECK(inInches.model.unit == "IN");
        const glm::dvec3 p = inInches.model.surfaces[1].surface.points[5] * 0.0254;
        CHECK(glm::length(p - metres.surfaces[1].surface.points[5]) <= 1e-12);
    }
    // OpenCASCADE's own reader, working in millimetres, sees metres written as metres.
    writeCadFile(metres, dir / "m.step");
    STEPControl_Reader reader;
    REQUIRE(reader.ReadFile((dir / "m.step").c_str()) == IFSelect_RetDone);
    TColStd_SequenceOfAsciiString lengths, angles, solid;
    reader.FileUnits(lengths, angles, solid);
    REQUIRE(lengths.Length() >= 1);
    CHECK(std::string(lengths.First().ToCString()) == "metre");
    // An unknown unit or extension is refused before anything is written.
    CadModel furlongs = metres;
    furlongs.unit = "furlong";
    CHECK_THROWS_WITH(writeCadFile(furlongs, dir / "f.step"), Catch::Contains("furlong"));
    CHECK_FALSE(std::filesystem::exists(dir / "f.step"));
    CHECK_THROWS_WITH(writeCadFile(metres, dir / "model.dxf"), Catch::Contains("unknown extension '.dxf'"));
}

TEST_CASE("files: colours are written as the model's numbers (sRGB), not re-encoded", "[exchange][files]") {
    const auto dir = exchange_test::scratch("colours");
    CadModel model = exchange_test::cadModelOf(exchange_test::transport());
    std::mt19937 random(31);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    for (CadSurface& s : model.surfaces) s.colour = glm::dvec3(unit(random), unit(random), unit(random));
    auto text = [](const std::filesystem::path& file) {
        std::ostringstream all;
        all << std::ifstream(file).rdbuf();
        return all.str();
    };
    // Every colour in the file is one of the model's, to the file's precision.
    auto isModelColour = [&](glm::dvec3 c) {
        return std::any_of(model.surfaces.begin(), model.surfaces.end(),
                           [&](const CadSurface& s) { return glm::length(c - *s.colour) <= 1e-6; });
    };
    writeCadFile(model, dir / "colours.step");
    const std::string step = text(dir / "colours.step");
    int found = 0;
    for (std::size_t at = step.find("COLOUR_RGB("); at != std::string::npos;
         at = step.find("COLOUR_RGB(", at + 1)) {
        glm::dvec3 c;
        const std::size_t comma = step.find(',', at);
        REQUIRE(std::sscanf(step.c_str() + comma + 1, "%lf,%lf,%lf", &c.x, &c.y, &c.z) == 3);
        CHECK(isModelColour(c));
        ++found;
    }
    CHECK(found >= 1);
    // IGES: colour definitions (entity 314) in percent.
    writeCadFile(model, dir / "colours.igs");
    const std::string iges = text(dir / "colours.igs");
    found = 0;
    std::istringstream lines(iges);
    for (std::string line; std::getline(lines, line);)
        if (line.size() >= 73 && line[72] == 'P' && line.rfind("314,", 0) == 0) {
            // Its parameters (columns 1-64) may go on over the next line.
            std::string parameters = line.substr(4, 60), next;
            if (std::getline(lines, next)) parameters += next.substr(0, 64);
            glm::dvec3 c;
            REQUIRE(std::sscanf(parameters.c_str(), "%lf,%lf,%lf", &c.x, &c.y, &c.z) == 3);
            CHECK(isModelColour(c / 100.0));
            ++found;
        }
    CHECK(found >= 1);
    // And back: the model's numbers.
    const CadImport read = readCadFile(dir / "colours.step");
    for (std::size_t i = 0; i < model.surfaces.size(); ++i)
        CHECK(glm::length(*read.model.surfaces.at(i).colour - *model.surfaces[i].colour) <= 1e-6);
}

TEST_CASE("files: every unit the model may name is the file's unit, its lengths in it",
          "[exchange][files][units]") {
    // OpenCASCADE's settings know inches as "INCH", not "IN", and keep the unit set before when
    // given a code they do not know: each listed unit must reach the file as itself.
    const auto dir = exchange_test::scratch("every_unit");
    const acsynt::Component& wing = exchange_test::transport().components[1];
    CadModel metres{"wing", "M", {{wing.name, geom::extractBezier(wing.surface)[0].surface, {}, {}}}};
    for (const std::string unit : {"M", "MM", "CM", "KM", "UM", "IN", "FT", "MI", "MIL", "UIN", "inch",
                                   "millimetre", "foot", "mile", "micrometre", "microinch"}) {
        const double size = *metresPerUnit(unit);
        CadModel model = metres;  // the same wing, its lengths in the unit
        model.unit = unit;
        for (glm::dvec3& p : model.surfaces[0].surface.points) p /= size;
        for (const char* extension : {".step", ".igs"}) {
            const auto file = dir / (unit + extension);
            INFO(file.filename().string());
            writeCadFile(model, file);
            const CadImport read = readCadFile(file);  // in metres
            INFO("the file's unit: " << read.fileUnit);
            REQUIRE(metresPerUnit(read.fileUnit));
            CHECK(*metresPerUnit(read.fileUnit) == size);
            REQUIRE(read.model.surfaces.size() == 1);
            const auto& a = read.model.surfaces[0].surface.points;
            const auto& b = metres.surfaces[0].surface.points;
            REQUIRE(a.size() == b.size());
            double gap = 0;
            for (std::size_t i = 0; i < a.size(); ++i) gap = std::max(gap, glm::length(a[i] - b[i]));
            CHECK(gap <= 1e-12 * 30);
        }
    }
}

}  // namespace test_cad_files

namespace test_cad_files {

TEST_CASE("files: a loop OpenCASCADE leaves out of a face is reported, never lost silently",
          "[exchange][files]") {
    // On wavy rational surfaces OpenCASCADE's shape healing takes some holes for wires of null
    // area (ShapeFix_Face::FixSmallAreaWire) and skips them, in IGES about one face in three of
    // these, in STEP rarely; not always with a message of its own.
    const auto dir = exchange_test::scratch("healed_holes");
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int lost = 0;
    for (int member = 0; member < 40; ++member) {
        const int p = 1 + int(rng() % 7), q = 1 + int(rng() % 2);
        const std::size_t nu = std::size_t(p) + 1 + rng() % 5, nv = std::size_t(q) + 1 + rng() % 5;
        auto knots = [](int degree, std::size_t count) {
            std::vector<double> k(std::size_t(degree) + 1, 0.0);
            for (std::size_t i = 1; i + std::size_t(degree) < count; ++i) k.push_back(double(i));
            k.insert(k.end(), std::size_t(degree) + 1, double(count - std::size_t(degree)));
            return k;
        };
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j) {
                points.push_back({double(i) + 0.3 * unit(rng), double(j) + 0.3 * unit(rng), unit(rng)});
                weights.push_back(std::pow(10.0, 2.0 * unit(rng)));
            }
        const geom::Surface s(p, q, knots(p, nu), knots(q, nv), nu, nv, points, weights);
        const glm::dvec2 centre(
            s.domainStartU() + (s.domainEndU() - s.domainStartU()) * (0.5 + 0.1 * unit(rng)),
            s.domainStartV() + (s.domainEndV() - s.domainStartV()) * (0.5 + 0.1 * unit(rng)));
        auto loop = [&](double scale, int n, double turn) {
            SurfaceLoop l;
            for (int k = 0; k <= n; ++k) {
                const double a = turn * 2.0 * M_PI * (k % n) / n;
                l.uv.push_back(centre +
                               scale * glm::dvec2((s.domainEndU() - s.domainStartU()) * std::cos(a),
                                                  (s.domainEndV() - s.domainStartV()) * std::sin(a)));
                l.points.push_back(geom::evaluate(s, l.uv.back().x, l.uv.back().y));
            }
            return l;
        };
        const CadModel model{
            "m", "M", {{"s", s, glm::dvec3(0.4), {{"crv", {loop(0.3, 20, 1.0), loop(0.08, 8, -1.0)}}}}}};
        for (const char* name : {"holes.igs", "holes.step"}) {
            writeCadFile(model, dir / name);
            const CadImport read = readCadFile(dir / name);
            INFO(name << ", member " << member << ": degrees " << p << " x " << q);
            REQUIRE(read.model.surfaces.size() == 1);
            auto warned = [&](const std::string& what) {
                return std::any_of(read.warnings.begin(), read.warnings.end(),
                                   [&](const std::string& w) { return w.find(what) != std::string::npos; });
            };
            const auto& curves = read.model.surfaces[0].curves;
            const std::size_t loops = curves.empty() ? 0 : curves[0].loops.size();
            CHECK(curves.size() <= 1);
            CHECK(loops <= 2);
            if (loops < 2) {
                ++lost;
                // A loop skipped, and the whole set where healing made the other's edges curves.
                CHECK((warned("came back from OpenCASCADE with") || curves.empty()));
                if (curves.empty()) CHECK(warned("s/crv: left out"));
            }
        }
    }
    CHECK(lost > 0);  // the case the test is for happened
}

}  // namespace test_cad_files

namespace test_cad_files {

TEST_CASE("files: a hole a period away from its loop across the seam stays its hole", "[exchange][files]") {
    // The loop across the fuselage's seam has its middle at the domain's start; the hole's lies
    // at its end, a period away. The writer took it for no loop's hole (a face of its own, turned
    // round), and a reader that took a hole for the outer wire gave the loops in the wrong order.
    const auto dir = exchange_test::scratch("seam_hole");
    CadModel model = exchange_test::cadModelOf(exchange_test::transport());
    model.surfaces.resize(1);
    const geom::Surface& body = model.surfaces[0].surface;
    REQUIRE(periodicByConstruction(body, true));
    const double period = body.domainEndV() - body.domainStartV();
    const double start = body.domainStartV();
    model.surfaces[0].curves.push_back(
        {"seam.crv",
         {exchange_test::ellipse(body, {0.5, start}, {0.1, 0.05 * period}, 30, true),
          exchange_test::ellipse(body, {0.5, start + 0.99 * period}, {0.02, 0.01 * period}, 13, false)}});
    for (const char* name : {"seam_hole.step", "seam_hole.igs"}) {
        INFO(name);
        writeCadFile(model, dir / name);
        const CadImport read = readCadFile(dir / name);
        REQUIRE(read.model.surfaces.size() == 1);
        REQUIRE(read.model.surfaces[0].curves.size() == 1);
        exchange_test::requireSameLoops(read.model.surfaces[0].curves[0].loops,
                                        model.surfaces[0].curves[0].loops, 1e-9);
    }
}

TEST_CASE("files: loops on wavy rational periodic surfaces come back on their points", "[exchange][files]") {
    // OpenCASCADE's STEP reader refits pcurves; on these it can put them far off the surface, and
    // Gauss-Newton from there ran off to (u, v) near 1e100.
    const auto dir = exchange_test::scratch("wavy_periodic_loops");
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0;
    for (int member = 0; member < 40; ++member) {
        const int p = 1 + int(rng() % 7), q = 1 + int(rng() % 4);
        const std::size_t nu = std::size_t(p) + 1 + rng() % 3,
                          spans = std::size_t(std::max(q, 2)) + 1 + rng() % 3;
        std::vector<double> ku(std::size_t(p) + 1, 0.0), kv;
        for (std::size_t i = 1; i + std::size_t(p) < nu; ++i) ku.push_back(double(i));
        ku.insert(ku.end(), std::size_t(p) + 1, double(nu - std::size_t(p)));
        for (int k = -q; k <= int(spans) + q; ++k) kv.push_back(double(k));
        const std::size_t nv = spans + std::size_t(q);
        std::vector<glm::dvec3> points(nu * nv);
        std::vector<double> weights(nu * nv);
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j) {
                const std::size_t k = i * nv + j, jj = j % spans;
                if (j >= spans) {
                    points[k] = points[k - spans], weights[k] = weights[k - spans];
                    continue;
                }
                const double a = 2.0 * M_PI * double(jj) / double(spans);
                points[k] = {2.0 * std::cos(a) * (1.0 + 0.3 * unit(rng)),
                             2.0 * std::sin(a) * (1.0 + 0.3 * unit(rng)), double(i) + 0.3 * unit(rng)};
                weights[k] = std::pow(10.0, 2.0 * unit(rng));
            }
        const geom::Surface s(p, q, ku, kv, nu, nv, points, weights);
        const double u0 = s.domainStartU(), du = s.domainEndU() - u0, v0 = s.domainStartV(),
                     dv = s.domainEndV() - v0;
        SurfaceLoop loop;
        const glm::dvec2 centre(u0 + du * (0.5 + 0.1 * unit(rng)), v0 + dv * 0.05 * unit(rng));
        const int n = 8 + int(rng() % 32);
        for (int k = 0; k <= n; ++k) {
            const double a = 2.0 * M_PI * (k % n) / n;
            loop.uv.push_back(centre + glm::dvec2(0.3 * du * std::cos(a), 0.2 * dv * std::sin(a)));
            const double v = loop.uv.back().y - std::floor((loop.uv.back().y - v0) / dv) * dv;
            loop.points.push_back(geom::evaluate(s, loop.uv.back().x, v));
        }
        const CadModel model{"m", "M", {{"s", s, glm::dvec3(0.4), {{"crv", {loop}}}}}};
        writeCadFile(model, dir / "wavy.step");
        const CadImport read = readCadFile(dir / "wavy.step");
        INFO("member " << member << ": degrees " << p << " x " << q);
        REQUIRE(read.model.surfaces.size() == 1);
        const CadSurface& back = read.model.surfaces[0];
        if (back.curves.empty()) continue;  // left out, with a warning (edges made curves by healing)
        for (const SurfaceLoop& l : back.curves[0].loops)
            for (std::size_t k = 0; k < l.points.size(); ++k) {
                const double v = l.uv[k].y - std::floor((l.uv[k].y - back.surface.domainStartV()) / dv) * dv;
                CHECK(glm::length(geom::evaluate(back.surface, l.uv[k].x, v) - l.points[k]) <= 1e-7);
            }
        ++checked;
    }
    CHECK(checked >= 25);
}

}  // namespace test_cad_files
