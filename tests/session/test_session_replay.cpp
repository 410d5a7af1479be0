// The shipped demo session replayed from its file (two of its pictures against references), picking known
// surface points shaded and in the wireframe, bad input that leaves the session going, and a recorded session
// that replays to the same result.
#include "SessionTestSupport.h"

#include "../support/VectorRaster.h"
#include "geom/Evaluate.h"

#include <glm/geometric.hpp>

#include <fstream>
#include <sstream>

namespace test_session_replay {

using Catch::Matchers::Contains;
using session_test::Driver;

namespace {

std::string read(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

bool logContains(const acsynt::Session& s, const std::string& text) {
    for (const auto& line : s.log())
        if (line.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("the shipped demo session replays headless: logo and circle mapped, fuselage reduced, pictures") {
    const auto out = session_test::outputDirectory("demo");
    std::filesystem::remove_all(out);
    auto script = phigs::ScriptInputSource::fromFile(std::filesystem::path(ACSYNT_DATA_DIR) / "demo.session",
                                                     acsynt::Session::directives());
    acsynt::SessionSettings settings;  // the demo's own 1024 x 768 screen: its picks are in those pixels
    settings.outputDirectory = out;
    acsynt::Session session(settings, script);
    phigs::vk::WorkstationDisplay display(session.workstation(), session_test::context());
    session.setSnapshot([&](const std::filesystem::path& file) {
        display.update();
        phigs::writePng(display.image(), file);
    });
    session.run();
    CHECK(session.finished());
    for (const auto& line : session.log()) {
        INFO(line);
        CHECK(line.rfind("ERROR: ", 0) != 0);
    }

    // The logo and the circle, and both carried to the reduced model (on the wing, as they were).
    REQUIRE(session.mappings().size() == 4);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(session.mappings()[i].model == "transport");
        CHECK(session.mappings()[i + 2].model == "transport_R1");
        CHECK(session.mappings()[i + 2].polylines == session.mappings()[i].polylines);
    }
    const acsynt::MappingRecord& logo = session.mappings()[0];
    CHECK(logo.curveFile == "acslogo.crv");
    CHECK(logo.component == "right_wing");
    CHECK(logo.reference.patch == 19);
    CHECK(logo.loopsPerPart == std::vector<std::size_t>{1, 1, 1, 1, 1});
    const acsynt::MappingRecord& circle = session.mappings()[1];
    CHECK(circle.curveFile == "circle.crv");
    CHECK(circle.loops == 1);
    CHECK(circle.boundaryWalks >= 1);  // out of bounds over the tip, closed along the boundary

    // The marker: pad centre (the middle of patch 19), then w at 0.55 of the patch, then one step east.
    const auto& wing = session.models().at(0).components[1];
    const acsynt::Patch& patch = wing.patches.patches[18];
    CHECK(logo.reference.u == Approx((patch.u0 + patch.u1) / 2 + (patch.u1 - patch.u0) / 8));
    CHECK(logo.reference.w == Approx(patch.w0 + 0.55 * (patch.w1 - patch.w0)));

    REQUIRE(session.reductions().size() == 1);
    const acsynt::ReductionRecord& r = session.reductions()[0];
    CHECK(r.component == "fuselage");
    CHECK(r.countUBefore * r.countWBefore == 247);
    CHECK(r.countUAfter * r.countWAfter < 247);
    CHECK(r.maxError <= 0.01);

    REQUIRE(session.pictures().size() == 7);
    for (const auto& p : session.pictures()) CHECK(std::filesystem::exists(p));
    // Two of them against references: the logo mapped on the wing (four views, centred on the
    // marker and zoomed) and the reduced fuselage's error map. The demo's picks are pixels of its
    // 1024 x 768 screen, so the pictures are compared at that size.
    for (const std::string name : {"demo_5_logo", "demo_7_reduced"}) {
        const auto picture = out / (name + ".png");
        REQUIRE(std::filesystem::exists(picture));
        session_test::compareWithReference(phigs::readPng(picture), name);
    }
    // The PDF of the mapped logo's views: vectors only, and the picture looked at and kept.
    REQUIRE(session.hardcopies() == std::vector<std::filesystem::path>{out / "demo_6_mapped.pdf"});
    CHECK(vector_test::pdfImageCount(out / "demo_6_mapped.pdf") == 0);
    session_test::compareWithReference(vector_test::rasterisePdf(out / "demo_6_mapped.pdf", 842, 595),
                                       "demo_6_mapped_pdf");
    const std::string summary = read(out / "summary.txt");
    CHECK(summary.find("mapping 1: acslogo.crv on transport/right_wing patch 19") != std::string::npos);
    CHECK(summary.find("5 parts, 5 loops (per part 1 1 1 1 1)") != std::string::npos);
    CHECK(
        summary.find("reduction 1: transport/fuselage -> transport_R1, U&W by tolerance 0.01: control points "
                     "13 x 19 = 247 -> ") != std::string::npos);
}

namespace {

/// Picks known surface points where they show and checks the component, patch, (u, w) and point.
void pickKnownPoints(Driver& d) {
    struct Probe {
        std::string component;
        double u, w;
        int view;
    };
    // Plan view (1) from above: upper surfaces; the 3D view (4) from the front left.
    const Probe probes[] = {{"right_wing", 0.5, 0.25, 1}, {"right_wing", 0.13, 0.31, 1},
                            {"fuselage", 0.42, 0.5, 1},   {"fin", 0.5, 0.3, 4},
                            {"left_wing", 0.6, 0.75, 1},  {"right_htail", 0.4, 0.3, 1}};
    const auto& components = d.session.models().current().components;
    for (const Probe& probe : probes) {
        int index = -1;
        for (std::size_t i = 0; i < components.size(); ++i)
            if (components[i].name == probe.component) index = int(i);
        REQUIRE(index >= 0);
        const acsynt::Component& c = components[std::size_t(index)];
        const glm::dvec3 point = geom::evaluate(c.surface, probe.u, probe.w);
        d.pickAt(point, probe.view);
        INFO(probe.component << " at (" << probe.u << ", " << probe.w << ") in view " << probe.view);
        REQUIRE(d.session.lastPick());
        REQUIRE(d.session.lastPickDetail());
        CHECK(d.session.lastPick()->component == index);
        CHECK(d.session.lastPick()->patch == c.patches.find(probe.u, probe.w)->number);
        CHECK(std::abs(d.session.lastPickDetail()->uv.x - probe.u) < 1e-6);
        CHECK(std::abs(d.session.lastPickDetail()->uv.y - probe.w) < 1e-6);
        CHECK(glm::distance(d.session.lastPickDetail()->point, point) < 1e-5);
        CHECK(d.session.message().rfind("PICKED " + probe.component + " PATCH ", 0) == 0);
        CHECK(logContains(d.session, "picked " + probe.component + " PATCH " +
                                         std::to_string(c.patches.find(probe.u, probe.w)->number) +
                                         " AT U = "));
    }
    // Outside the aircraft: nothing.
    d.run({"pick 5 5"});
    CHECK(d.session.message().rfind("PICKED right_htail", 0) == 0);  // unchanged: the last pick's message
}

}  // namespace

TEST_CASE("picking the screen position of a known surface point returns its component, patch and (u, w)") {
    Driver d("pick");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN"});
    pickKnownPoints(d);
}

TEST_CASE("picking in the WIREFRAME view: inside a patch (EMPTY interior) gives its (u, w) and point") {
    Driver d("pick_wireframe");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice WIREFRAME", "choice RETURN"});
    REQUIRE_FALSE(d.session.style().shaded);
    pickKnownPoints(d);
    // DEFINE POINT in the wireframe: the component, then the patch under the same point.
    const auto& wing = d.session.models()
                           .current()
                           .components[std::size_t(session_test::componentIndex(d.session, "right_wing"))];
    const glm::dvec3 p = geom::evaluate(wing.surface, 0.5, 0.38);
    d.run({"choice CURVE_MAP", "choice DEFINE_POINT"});
    d.pickAt(p, 1);
    CHECK(d.session.message() == "SELECT REFERENCE PATCH TO MAP");
    d.pickAt(p, 1);
    CHECK(d.session.message() == "ACCEPT OR REJECT PATCH");
    d.run({"choice ACCEPT"});
    REQUIRE(d.session.reference());
    CHECK(d.session.reference()->patch == wing.patches.find(0.5, 0.38)->number);
    CHECK_FALSE(d.logHasError());
}

TEST_CASE("bad input: a wrong section count, a curve that does not close, an unknown menu choice") {
    Driver d("bad_input");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm"});
    const std::size_t patches = d.session.models().current().patchCount();

    d.run({"choice READ_MODEL", "string bad_sections.acm"});
    INFO(d.session.message());
    CHECK(d.session.message().find("bad_sections.acm:") != std::string::npos);
    CHECK(d.session.message().find("sections") != std::string::npos);
    CHECK(logContains(d.session, "ERROR: "));
    CHECK(d.session.models().size() == 1);
    CHECK(d.session.models().current().patchCount() == patches);

    d.run({"choice READ_CURVE_FILE", "string open.crv"});
    CHECK(d.session.message().find("open.crv:") != std::string::npos);
    CHECK(d.session.message().find("close") != std::string::npos);
    CHECK(d.session.summary().find("mapping") == std::string::npos);

    d.run({"choice READ_MODEL", "string no_such_model.acm"});
    CHECK(d.session.message().find("no_such_model.acm") != std::string::npos);

    // A script naming a menu item the current menu does not have: the message names the line.
    const std::string text = "choice RETURN\nchoice VIEW\nchoice NO_SUCH_ITEM\nchoice FOUR_VIEWS\n";
    phigs::ScriptInputSource script(text, "bad.session", acsynt::Session::directives());
    acsynt::Session session(Driver::settings("bad_input_script"), script);
    session.run();
    bool named = false;
    for (const auto& line : session.log())
        if (line.find("ERROR: ") == 0 && line.find("bad.session line 3") != std::string::npos &&
            line.find("NO_SUCH_ITEM") != std::string::npos)
            named = true;
    CHECK(named);
    CHECK(session.fourViews());  // the session went on
    CHECK(session.message() == "FOUR VIEWS DONE");
}

TEST_CASE("a recorded session replays to the same summary") {
    std::string recording, summary;
    {
        Driver d("record");
        d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice RETURN", "choice CURVE_MAP",
               "choice LOAD_CURVE", "string circle.crv 0.08", "choice DEFINE_POINT"});
        const auto& wing = d.session.models().current().components[1];
        REQUIRE(wing.name == "right_wing");
        const glm::dvec3 p = geom::evaluate(wing.surface, 0.4, 0.25);
        d.pickAt(p, 1);
        d.pickAt(p, 1);
        d.run({"choice ACCEPT"});
        d.run({session_test::markerValuator(d.session, 1, 0.5),
               session_test::markerValuator(d.session, 2, 0.5), "choice DONE device 2", "choice MAP_CURVE"});
        REQUIRE(d.session.mappings().size() == 1);
        CHECK(d.session.mappings()[0].loops == 1);
        recording = d.session.recording();
        summary = d.session.summary();
    }
    phigs::ScriptInputSource script(recording, "recorded", acsynt::Session::directives());
    acsynt::Session replay(Driver::settings("record_replay"), script);
    replay.run();
    CHECK(replay.summary() == summary);
}

TEST_CASE("a recording notes typed strings no script line holds, and still replays") {
    std::string recording;
    {
        Driver d("record_strings");
        d.run({"choice FILE", "choice READ_MODEL"});
        phigs::InputAction blank, newline;
        blank.what = phigs::action::String{" fighter.acm", 1};  // read as it is: no such file
        newline.what = phigs::action::String{"fighter\n.acm", 1};
        for (const auto& typed : {blank, newline}) {
            d.source.push(typed);
            while (!d.source.empty() && d.session.step(std::chrono::milliseconds(0))) {
            }
        }
        d.run({"string fighter.acm", "choice RETURN"});
        recording = d.session.recording();
    }
    // The blank at the start is lost on a script line: the line is kept after a comment saying
    // so; the newline cannot be on one: the action is only noted.
    CHECK_THAT(recording, Contains("# the next line does not hold the action exactly as the operator "
                                   "made it\nstring  fighter.acm\n"));
    CHECK_THAT(recording, Contains("# no script line holds this action: string fighter?.acm\n"));
    phigs::ScriptInputSource script(recording, "recorded", acsynt::Session::directives());
    acsynt::Session replay(Driver::settings("record_strings_replay"), script);
    replay.run();
    CHECK(replay.models().current().name == "fighter");
}

TEST_CASE("a recorded session replays to the same summary on a screen of another size") {
    std::string recording, summary;
    {
        Driver d("record_sized");
        d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice RETURN", "choice VIEW",
               "choice FOUR_VIEWS", "choice RETURN", "choice CURVE_MAP", "choice LOAD_CURVE",
               "string circle.crv 0.08", "choice DEFINE_POINT"});
        const auto& wing = d.session.models().current().components[1];
        REQUIRE(wing.name == "right_wing");
        // A miss first (a corner of the first view): recorded as one, since its pixel may show
        // the model on a screen of another size.
        const acsynt::PixelBox corner = d.session.layout().viewBox(1, true);
        d.run({"pick " + std::to_string(corner.x0 + 2) + " " + std::to_string(corner.y0 + 2)});
        REQUIRE(d.session.message() == "NOTHING PICKED: TRY AGAIN");
        const glm::dvec3 p = geom::evaluate(wing.surface, 0.4, 0.25);
        d.pickAt(p, 1);
        d.pickAt(p, 4);  // the patch in the 3D view
        // The menu row and pad button by where they are on this screen, as a click makes them.
        const acsynt::PixelBox accept = d.session.layout().menuFor(2);
        d.run({"pick " + std::to_string(accept.centre().x) + " " + std::to_string(accept.y0 + 3)});
        REQUIRE(d.session.reference());
        const glm::dvec2 east = d.session.layout().padButton(6).centre();
        d.run({"pick " + std::to_string(east.x) + " " + std::to_string(east.y),
               session_test::markerValuator(d.session, 2, 0.3), "choice DONE device 2", "choice MAP_CURVE",
               "snapshot sized"});
        REQUIRE(d.session.mappings().size() == 1);
        CHECK_FALSE(d.logHasError());
        recording = d.session.recording();
        summary = d.session.summary();
    }
    INFO(recording);
    // Picks on surfaces by component, patch and (u, w), with a comment; menu rows and pad
    // buttons by name; the snapshot as it came.
    CHECK(recording.find("\npick_surface right_wing ") != std::string::npos);
    CHECK(recording.find("# picked right_wing patch ") != std::string::npos);
    CHECK(recording.find("\nchoice ACCEPT\n") != std::string::npos);
    CHECK(recording.find("\nchoice EAST device 2\n") != std::string::npos);
    CHECK(recording.find("\nsnapshot sized\n") != std::string::npos);
    CHECK(recording.find("\n# nothing picked at pixel ") != std::string::npos);
    CHECK(recording.find("\npick_nothing\n") != std::string::npos);
    CHECK(recording.find("\npick ") == std::string::npos);

    for (const auto& [w, h] : {std::pair{640, 480}, std::pair{1024, 768}}) {
        INFO(w << " x " << h);
        acsynt::SessionSettings settings = Driver::settings("record_sized");  // same picture paths
        settings.width = w;
        settings.height = h;
        phigs::ScriptInputSource script(recording, "recorded", acsynt::Session::directives());
        acsynt::Session replay(settings, script);
        replay.setSnapshot([](const std::filesystem::path&) {});
        replay.run();
        CHECK(replay.failedLines() == 0);
        CHECK(replay.summary() == summary);
    }
}

TEST_CASE("a recorded surface pick that no longer shows there is refused by name, not taken elsewhere") {
    Driver d("record_hidden");
    d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN"});
    const auto& wing = d.session.models().current().components[1];
    REQUIRE(wing.name == "right_wing");
    const auto line = [&](double u, double w) {
        const acsynt::Patch* p = wing.patches.find(u, w);
        REQUIRE(p);
        char text[160];
        std::snprintf(text, sizeof text, "pick_surface right_wing %d %.17g %.17g 1", p->number, u, w);
        return std::string(text);
    };
    // The upper surface (w < 0.5) in the plan view from above: picked, with the recorded (u, w).
    d.run({line(0.4, 0.25)});
    REQUIRE(d.session.lastPick());
    CHECK(d.session.lastPick()->patch == wing.patches.find(0.4, 0.25)->number);
    CHECK(d.session.lastPickDetail()->uv == glm::dvec2(0.4, 0.25));
    // The lower surface there is hidden by the upper one: refused, not taken as the upper patch.
    const std::size_t failed = d.session.failedLines();
    d.run({line(0.4, 0.75)});
    CHECK(d.session.message().rfind("RECORDED PICK OF right_wing PATCH ", 0) == 0);
    CHECK(d.session.message().find("IS NOT WHAT SHOWS AT PIXEL") != std::string::npos);
    CHECK(d.session.lastPickDetail()->uv == glm::dvec2(0.4, 0.25));
    // (u, w) outside the surface's domain: this line fails, the session goes on (it ended with
    // exit 1, evaluate's message and no log).
    const std::size_t before = d.session.failedLines();
    d.run({"pick_surface right_wing 1 2 0.5 1"});
    CHECK(d.session.message() ==
          "BAD RECORDED PICK 'pick_surface right_wing 1 2 0.5 1': U AND W OF right_wing LIE IN [0, 1] AND "
          "[0, 1]");
    CHECK(d.session.failedLines() == before + 1);
    d.run({"choice VIEW", "choice ONE_VIEW", "choice RETURN", "pick_surface right_wing 1 0.5 0.5 4"});
    CHECK(
        d.session.message() ==
        "BAD RECORDED PICK 'pick_surface right_wing 1 0.5 0.5 4': VIEW '4' IS NOT 1..1 (COMPONENT PATCH U W "
        "VIEW)");
    d.run({"pick_surface no_such_part 1 0.5 0.5 1"});
    CHECK(d.session.message() == "RECORDED PICK: MODEL fighter HAS NO COMPONENT no_such_part");
    CHECK(d.session.failedLines() == failed + 4);
    // Each wrong field is the one named; a patch the component lacks is said to be missing.
    d.run({"pick_surface right_wing 1 nan 0.5 1"});
    CHECK(d.session.message().find(": U 'nan' IS NOT A NUMBER") != std::string::npos);
    d.run({"pick_surface right_wing 0.5 0.5 0.5 1"});
    CHECK(d.session.message().find(": PATCH '0.5' IS NOT A WHOLE NUMBER FROM 1") != std::string::npos);
    d.run({"pick_surface right_wing 1 0.5 x 1"});
    CHECK(d.session.message().find(": W 'x' IS NOT A NUMBER") != std::string::npos);
    d.run({"pick_surface right_wing 99999 0.5 0.5 1"});
    CHECK(d.session.message() ==
          "RECORDED PICK: right_wing HAS " + std::to_string(wing.patches.size()) + " PATCHES, NOT 99999");
    // A pick off the screen is a mistake in the script, not a miss; a view past the poles too.
    d.run({"pick 1e9 1e9", "pick -5 10"});
    CHECK(d.session.message() == "PICK AT -5 10 IS OFF THE 320 X 240 SCREEN");
    d.run({"view 0 95 1"});
    CHECK(d.session.message().rfind("BAD VIEW: ", 0) == 0);
    d.run({"view 0 30 1 1e300 0 0"});
    CHECK(d.session.message().find("BAD VIEW: the centre must lie within 1E6") != std::string::npos);
    CHECK(d.session.failedLines() == failed + 12);
}

}  // namespace test_session_replay
