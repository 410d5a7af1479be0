// FILE > EXPORT and FILE > IMPORT: the model with its mapped curves through STEP and IGES and
// back as a new model; a reduced model; bad files and names.
#include "SessionTestSupport.h"

#include "../exchange/ExchangeTestUtil.h"
#include "acsynt/DataFolders.h"
#include "geom/Evaluate.h"
#include "geom/Primitives.h"
#include "geom/exchange/CadFile.h"
#include "geom/exchange/OcctConversion.h"

#include <fstream>
#include <iterator>

namespace test_session_exchange {

using session_test::Driver;

namespace {

const acsynt::Component& component(const acsynt::Model& m, const std::string& name) {
    const acsynt::Component* c = m.find(name);
    REQUIRE(c);
    return *c;
}

/// The transport with the ACSYNT logo (or `curve`) mapped onto its right wing (as the demo does).
void transportWithLogo(Driver& d, const std::string& curve = "acslogo.crv") {
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice CURVE_MAP", "choice LOAD_CURVE",
           "string " + curve + " 0.45", "choice DEFINE_POINT"});
    const glm::dvec3 p =
        geom::evaluate(component(d.session.models().current(), "right_wing").surface, 0.5, 0.38);
    d.pickAt(p, 1);
    d.pickAt(p, 1);
    d.run({"choice ACCEPT", "choice CENTRE device 2", "choice DONE device 2", "choice MAP_CURVE",
           "choice RETURN"});
    REQUIRE(d.session.mappings().size() == 1);
    REQUIRE(d.session.mappings()[0].loops == 5);
}

/// The imported model (current) against the original: components, their surfaces (exactly, or
/// patch by patch), patch lists; and the mapped curves' loops in space and in (u, w).
void requireSameModel(const acsynt::Session& s, const acsynt::Model& original, bool wholeSurfaces) {
    const acsynt::Model& imported = s.models().current();
    REQUIRE(imported.components.size() == original.components.size());
    for (std::size_t i = 0; i < original.components.size(); ++i) {
        const acsynt::Component &a = imported.components[i], &b = original.components[i];
        INFO(b.name);
        CHECK(a.name == b.name);
        CHECK(glm::length(a.colour - b.colour) <= 1e-6);
        // Closed where it was: periodic, or (a reduced fuselage) clamped with a smooth seam.
        CHECK(a.closedU == b.closedU);
        CHECK(a.closedW == b.closedW);
        exchange_test::requireSamePatches(a.surface, b.surface);
        if (wholeSurfaces) exchange_test::requireSameSurface(a.surface, b.surface);
        REQUIRE(a.patches.patches.size() == b.patches.patches.size());
    }
    std::vector<const acsynt::MappingRecord*> mine, theirs;
    for (const auto& m : s.mappings()) (m.model == imported.name ? mine : theirs).push_back(&m);
    REQUIRE(mine.size() == theirs.size());
    for (std::size_t k = 0; k < mine.size(); ++k) {
        CHECK(mine[k]->component == theirs[k]->component);
        CHECK(mine[k]->curveFile == theirs[k]->curveFile);
        REQUIRE(mine[k]->polylines.size() == theirs[k]->polylines.size());
        for (std::size_t l = 0; l < mine[k]->polylines.size(); ++l) {
            const auto &a = mine[k]->polylines[l], &b = theirs[k]->polylines[l];
            const auto &au = mine[k]->uvPolylines[l], &bu = theirs[k]->uvPolylines[l];
            REQUIRE(a.size() == b.size());
            REQUIRE(au.size() == bu.size());
            double gap = 0;
            for (std::size_t v = 0; v < a.size(); ++v)
                gap = std::max({gap, glm::length(a[v] - b[v]), glm::length(au[v] - bu[v])});
            CHECK(gap <= 1e-12);
        }
    }
}

}  // namespace

TEST_CASE("FILE menu: EXPORT the transport with a mapped logo to STEP and IGES, IMPORT each back") {
    Driver d("exchange");
    transportWithLogo(d);
    for (const char* name : {"transport.step", "transport.igs"}) {
        d.run({"choice FILE", "choice EXPORT", std::string("string ") + name});
        const auto path = session_test::outputDirectory("exchange") / name;
        CHECK(d.session.message() == "MODEL transport EXPORTED TO " + path.string() +
                                         ": 8 COMPONENTS, 376 PATCHES, 1 MAPPED CURVES");
        CHECK(std::filesystem::exists(path));
        d.run({"choice RETURN"});
    }
    const acsynt::Model original = d.session.models().current();
    d.run({"choice MODELS", "choice NAME_MODEL", "string original", "choice RETURN"});
    for (const char* name : {"transport.step", "transport.igs"}) {
        INFO(name);
        const auto path = session_test::outputDirectory("exchange") / name;
        d.run({"choice FILE", "choice IMPORT", "string " + path.string()});
        CHECK(d.session.message() == "MODEL transport IMPORTED: 8 COMPONENTS, 376 PATCHES, 1 MAPPED CURVES");
        d.run({"choice RETURN"});
        REQUIRE(d.session.models().size() == 2);
        // IMPORT is a change of its own: UNDO takes back the imported model alone.
        d.run({"undo"});
        CHECK(d.session.message() == "UNDONE: IMPORT transport");
        CHECK(d.session.models().size() == 1);
        d.run({"redo"});
        REQUIRE(d.session.models().size() == 2);
        requireSameModel(d.session, original, true);
        d.run({"choice CURVE_MAP", "choice DISPLAY_ALL"});
        CHECK(d.session.message() == "DISPLAYING 1 MAPPED CURVES");
        // An imported model is saved as it is (its surfaces), as any other.
        d.run({"choice RETURN", "choice FILE", "choice SAVE_MODEL", "string imported.acs"});
        CHECK(d.session.message().rfind("MODEL transport SAVED TO ", 0) == 0);
        // ... and read back with its mapped loops (which came with no reference point).
        std::vector<acsynt::MappingRecord> before;
        for (const auto& m : d.session.mappings())
            if (m.model == d.session.models().current().name) before.push_back(m);
        REQUIRE(before.size() == 1);
        const auto saved = session_test::outputDirectory("exchange") / "imported.acs";
        d.run({"choice READ_MODEL", "string " + saved.string()});
        REQUIRE(d.session.models().size() == 3);
        std::vector<acsynt::MappingRecord> after;
        for (const auto& m : d.session.mappings())
            if (m.model == d.session.models().current().name) after.push_back(m);
        REQUIRE(after.size() == 1);
        CHECK(after[0].polylines == before[0].polylines);
        CHECK(after[0].uvPolylines == before[0].uvPolylines);
        d.run({"choice RETURN", "choice MODELS", "choice DELETE_MODEL", "choice DELETE_MODEL",
               "choice RETURN"});
        CHECK(d.session.models().size() == 1);
    }
}

TEST_CASE("FILE menu: EXPORT a curve mapped from a file whose name is not ASCII") {
    // The name was refused by the writer ("outside printable ASCII") and nothing was written.
    Driver d("exchange_name");
    const auto out = session_test::outputDirectory("exchange_name");
    const auto curve = out / "Fl\xC3\xBCgel_logo.crv";
    std::filesystem::path logo;
    for (const auto& folder : acsynt::dataFolders())
        if (logo.empty() && std::filesystem::exists(folder / "acslogo.crv")) logo = folder / "acslogo.crv";
    REQUIRE_FALSE(logo.empty());
    std::filesystem::create_directories(out);
    std::filesystem::copy_file(logo, curve, std::filesystem::copy_options::overwrite_existing);
    transportWithLogo(d, curve.string());
    const std::vector<std::string> files{"name.step", "name.igs"};
    for (const std::string& name : files) {
        d.run({"choice FILE", "choice EXPORT", "string " + name});
        CHECK(d.session.message().find("1 MAPPED CURVES") != std::string::npos);
        d.run({"choice RETURN"});
    }
    d.run({"choice MODELS", "choice NAME_MODEL", "string original", "choice RETURN"});
    for (const std::string& name : files) {
        d.run({"choice FILE", "choice IMPORT", "string " + (out / name).string()});
        INFO(name << ": " << d.session.message());
        REQUIRE(d.session.mappings().size() == 2);
        CHECK(d.session.mappings()[1].curveFile.find("Fl_gel_logo.crv") != std::string::npos);
        d.run({"choice RETURN", "choice MODELS", "choice DELETE_MODEL", "choice RETURN"});
        REQUIRE(d.session.mappings().size() == 1);
    }
}

TEST_CASE("FILE menu: a reduced model round-trips patch by patch") {
    Driver d("exchange_reduced");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice SURF_REDN",
           "choice BY_TOLERANCE", "choice REDUCE_U&W"});
    const glm::dvec3 top =
        geom::evaluate(component(d.session.models().current(), "fuselage").surface, 0.5, 0.5);
    d.pickAt(top, 1);
    d.run({"string 0.01", "choice RETURN"});
    REQUIRE(d.session.models().current().name == "transport_R1");
    const acsynt::Model reduced = d.session.models().current();
    d.run({"choice FILE", "choice EXPORT", "string reduced.step", "choice RETURN", "choice MODELS",
           "choice NAME_MODEL", "string reduced", "choice RETURN"});
    const auto path = session_test::outputDirectory("exchange_reduced") / "reduced.step";
    d.run({"choice FILE", "choice IMPORT", "string " + path.string()});
    REQUIRE(d.session.models().current().name == "transport_R1");
    // The reduced fuselage (clamped, no longer periodic) comes back clamped and still closed round
    // w: its patches are the same; every other component is the same surface.
    requireSameModel(d.session, reduced, false);
    const acsynt::Model& imported = d.session.models().current();
    for (std::size_t i = 1; i < reduced.components.size(); ++i)
        exchange_test::requireSameSurface(imported.components[i].surface, reduced.components[i].surface);
}

TEST_CASE("FILE menu: IMPORT of a rational surface logs the bicubic error it kept, readable") {
    // A cylinder (rational) comes in as bicubic within the import tolerance: the log says within
    // how much, in metres, as a number with its digits (such errors lie below a micrometre).
    Driver d("exchange_rational");
    const auto file = session_test::outputDirectory("exchange_rational") / "tube.step";
    std::filesystem::create_directories(file.parent_path());
    geom::exchange::CadModel tube;
    tube.name = "tube";
    tube.surfaces.push_back({"fuselage", geom::makeCylinder(0.5, 3.0), std::nullopt, {}});
    geom::exchange::writeCadFile(tube, file);
    d.run({"choice FILE", "choice IMPORT", "string " + file.string()});
    REQUIRE(d.session.models().size() == 1);
    std::string line;
    for (const std::string& l : d.session.log())
        if (l.find("made bicubic within") != std::string::npos) line = l;
    INFO(line);
    REQUIRE_FALSE(line.empty());
    const std::size_t at = line.find("within ") + 7;
    const std::string shown = line.substr(at, line.find(' ', at) - at);
    const double error = std::stod(shown);
    CHECK(error > 0.0);
    CHECK(error <= 1e-4);
    // Significant digits shown (three asked; a fixed six-decimal format would show one or none).
    std::string mantissa = shown.substr(0, shown.find('e'));
    std::erase(mantissa, '.');
    mantissa.erase(0, mantissa.find_first_not_of('0'));
    CHECK(mantissa.size() >= 2);
}

TEST_CASE("FILE menu: IMPORT refuses coordinates past what a saved model holds") {
    // A surface point at 1e15 m was imported (the views blank), saved, and the saved file was then
    // refused by READ MODEL ("beyond 1000000000"): the model is refused at IMPORT instead.
    Driver d("exchange_far");
    const auto dir = session_test::outputDirectory("exchange_far");
    std::filesystem::create_directories(dir);
    for (const double x : {1e15, -2e9}) {
        INFO(x);
        geom::exchange::CadModel model = exchange_test::cadModelOf(exchange_test::transport());
        model.surfaces.resize(1);
        model.surfaces[0].name = "fin";
        model.surfaces[0].surface.points[model.surfaces[0].surface.points.size() / 2].x = x;
        const auto file = dir / "far.step";
        geom::exchange::writeCadFile(model, file);
        d.run({"choice FILE", "choice IMPORT", "string " + file.string()});
        CHECK(d.session.message() == file.string() +
                                         ": a control point of fin is beyond 1000000000 m, the largest "
                                         "coordinate a saved model holds");
        CHECK(d.session.models().size() == 0);
        d.run({"choice RETURN"});
    }
}

TEST_CASE("FILE menu: bad EXPORT and IMPORT names and files leave the models as they were") {
    Driver d("exchange_bad");
    d.run({"choice FILE", "choice EXPORT"});
    CHECK(d.session.message() == "NO GEOMETRY FILE FOUND!");
    d.run({"choice IMPORT", "string missing.step"});
    CHECK(d.session.message() == "missing.step: no such file");
    CHECK(d.logHasError());
    CHECK(d.session.models().empty());
    d.run({"choice READ_MODEL", "string transport.acm"});
    REQUIRE(d.session.models().size() == 1);
    d.run({"choice EXPORT", "string ../escape.step"});
    CHECK(d.session.message().find("MUST BE A FILE NAME INSIDE THE OUTPUT DIRECTORY") != std::string::npos);
    d.run({"choice EXPORT", "string model.dxf"});
    CHECK(d.session.message().find("unknown extension '.dxf'") != std::string::npos);
    d.run({"choice EXPORT", "string whole.step"});
    const auto dir = session_test::outputDirectory("exchange_bad");
    // A truncated copy is refused with the STEP reader's reason; the model list stays as it was.
    std::ifstream in(dir / "whole.step", std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    std::ofstream(dir / "cut.step", std::ios::binary) << text.substr(0, text.size() / 2);
    d.run({"choice IMPORT", "string " + (dir / "cut.step").string()});
    CHECK(d.session.message().find("cut.step: not a readable STEP file") != std::string::npos);
    d.run({"choice IMPORT", "string transport.acm"});
    CHECK(d.session.message().find("unknown extension '.acm'") != std::string::npos);
    d.run({"choice IMPORT", "string " + (dir / "whole.step").string()});
    CHECK(d.session.message() == "A MODEL NAMED transport IS ALREADY LOADED");
    CHECK(d.session.models().size() == 1);
    CHECK(d.session.models().current().name == "transport");
    // The FILE menu by number: EXPORT is 7, IMPORT 8, HARDCOPY 9, EXIT 10.
    d.run({"choice 8"});
    CHECK(d.session.message() == "ENTER IGES OR STEP FILE NAME TO IMPORT");
    d.run({"string missing.igs", "choice 10"});
    CHECK(d.session.finished());
}

}  // namespace test_session_exchange
