// Session replays of each menu path, driven line by line on a 320 x 240 screen, with their
// summaries checked and their pictures compared with tests/data/session/*.png.
#include "SessionTestSupport.h"

#include "geom/Evaluate.h"

#include <fstream>
#include <map>

namespace test_session_menus {

using session_test::Driver;

using session_test::componentIndex;
using session_test::pickOn;

namespace {

glm::dvec3 surfacePoint(const acsynt::Session& s, const std::string& component, double u, double w) {
    return geom::evaluate(s.models().current().components[std::size_t(componentIndex(s, component))].surface,
                          u, w);
}

void loadTransportInFourViews(Driver& d) {
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN"});
    REQUIRE(d.session.models().size() == 1);
    REQUIRE(d.session.fourViews());
}

/// DEFINE POINT on the right wing at (u, w) seen in the plan view, accepted, then DONE.
void definePoint(Driver& d, double u, double w) {
    d.run({"choice DEFINE_POINT"});
    CHECK(d.session.message() == "SELECT COMPONENT FOR MAPPING");
    const glm::dvec3 p = surfacePoint(d.session, "right_wing", u, w);
    d.pickAt(p, 1);
    CHECK(d.session.message() == "SELECT REFERENCE PATCH TO MAP");
    d.pickAt(p, 1);
    CHECK(d.session.message() == "ACCEPT OR REJECT PATCH");
    d.run({"choice ACCEPT"});
    REQUIRE(d.session.reference());
}

}  // namespace

TEST_CASE("VIEW menu: one view, four views, wireframe with hulls, shaded") {
    Driver d("view");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN"});
    CHECK(d.session.message() == "SELECT MENU ITEM");
    CHECK(d.session.models().current().patchCount() == 376);
    session_test::compareWithReference(d.picture(), "view_one_shaded");
    d.run({"choice VIEW", "choice WIREFRAME", "choice HULL_ON"});
    CHECK_FALSE(d.session.style().shaded);
    CHECK(d.session.style().hull);
    session_test::compareWithReference(d.picture(), "view_one_wireframe_hull");
    d.run({"choice HULL_OFF", "choice SHADE", "choice FOUR_VIEWS", "valuator 3 -60", "valuator 4 1.5"});
    CHECK(d.session.fourViews());
    CHECK(d.session.style().shaded);
    CHECK_FALSE(d.session.style().hull);
    session_test::compareWithReference(d.picture(), "view_four_rotated");
    d.run({"choice RESET_VIEW", "choice ONE_VIEW", "choice RETURN"});
    CHECK_FALSE(d.session.fourViews());
    CHECK(d.session.menuTitle() == "MAIN");
    CHECK_FALSE(d.logHasError());
}

TEST_CASE("CURVE MAP menu: DEFINE POINT with picks, pad and valuators, then MAP CURVE of the logo") {
    Driver d("curve_map");
    loadTransportInFourViews(d);
    d.run({"choice CURVE_MAP", "choice LOAD_CURVE", "string acslogo.crv 0.45"});
    CHECK(d.session.message() == "CURVE MODEL acslogo.crv LOADED: 5 PARTS");
    definePoint(d, 0.5, 0.38);
    const auto& wing =
        d.session.models().current().components[std::size_t(componentIndex(d.session, "right_wing"))];
    const acsynt::Patch* patch = wing.patches.find(0.5, 0.38);
    REQUIRE(patch);
    CHECK(d.session.reference()->patch == patch->number);
    // The marker starts at the patch corner (uknot[3], wknot[3]).
    CHECK(d.session.reference()->u == patch->u0);
    CHECK(d.session.reference()->w == patch->w0);
    d.run({"choice CENTRE device 2"});
    CHECK(d.session.reference()->u == Approx((patch->u0 + patch->u1) / 2));
    CHECK(d.session.reference()->w == Approx((patch->w0 + patch->w1) / 2));
    d.run({"choice NORTH_EAST device 2"});  // u and w up by an eighth of the patch
    CHECK(d.session.reference()->u == Approx((patch->u0 + patch->u1) / 2 + (patch->u1 - patch->u0) / 8));
    CHECK(d.session.reference()->w == Approx((patch->w0 + patch->w1) / 2 + (patch->w1 - patch->w0) / 8));
    d.run(
        {session_test::markerValuator(d.session, 1, 0.25), session_test::markerValuator(d.session, 2, 0.75)});
    CHECK(d.session.reference()->u == Approx(patch->u0 + 0.25 * (patch->u1 - patch->u0)));
    CHECK(d.session.reference()->w == Approx(patch->w0 + 0.75 * (patch->w1 - patch->w0)));
    d.run({"choice SOUTH_WEST device 2", "choice SOUTH_WEST device 2", "choice SOUTH_WEST device 2"});
    CHECK(d.session.reference()->u == Approx(patch->u0));  // kept inside the patch
    d.run({session_test::markerValuator(d.session, 1, 0.5), session_test::markerValuator(d.session, 2, 0.5),
           "choice DONE device 2"});
    CHECK(d.session.message().rfind("REFERENCE POINT U = ", 0) == 0);
    d.run({"choice FLIP_CURVE"});
    CHECK(d.session.message() == "CURVE FLIPPED");
    d.run({"choice FLIP_CURVE", "choice ROTATE_CURVE"});
    CHECK(d.session.message() == "CURVE ROTATED TO 90 DEGREES");
    d.run({"choice ROTATE_CURVE", "choice ROTATE_CURVE", "choice ROTATE_CURVE", "choice MAP_PREVIEW"});
    CHECK(d.session.message().find("PROJECTION LINES") != std::string::npos);
    d.run({"choice RETURN", "choice VIEW", "choice CENTRE_ON_MARKER", "valuator 4 4", "choice RETURN",
           "choice CURVE_MAP", "choice MAP_CURVE"});
    REQUIRE(d.session.mappings().size() == 1);
    const acsynt::MappingRecord& m = d.session.mappings()[0];
    CHECK(m.component == "right_wing");
    CHECK(m.parts == 5);
    CHECK(m.loops == 5);
    CHECK(m.boundaryWalks == 0);
    CHECK(m.reference.u == Approx((patch->u0 + patch->u1) / 2));
    CHECK(m.reference.w == Approx((patch->w0 + patch->w1) / 2));
    CHECK(d.session.message() == "MAPPED acslogo.crv ON right_wing: 5 LOOPS IN 5 PARTS");
    // Every mapped vertex lies on the wing.
    for (const auto& loop : m.polylines) REQUIRE(loop.size() > 4);
    session_test::compareWithReference(d.picture(), "curve_map_logo");
    CHECK(d.session.summary().find("mapping 1: acslogo.crv on transport/right_wing patch " +
                                   std::to_string(patch->number)) != std::string::npos);
    CHECK_FALSE(d.logHasError());
}

TEST_CASE(
    "CURVE MAP menu: a circle out of bounds over the wing tip closes along the boundary, then DISPLAY ALL") {
    Driver d("curve_map_tip");
    loadTransportInFourViews(d);
    d.run({"choice CURVE_MAP", "choice LOAD_CURVE", "string circle.crv 0.12"});
    definePoint(d, 0.9, 0.2);
    d.run({session_test::markerValuator(d.session, 1, 0.9), session_test::markerValuator(d.session, 2, 0.5),
           "choice DONE device 2", "choice MAP_CURVE"});
    REQUIRE(d.session.mappings().size() == 1);
    CHECK(d.session.mappings()[0].loops == 1);
    CHECK(d.session.mappings()[0].boundaryWalks >= 1);
    d.run({"choice LOAD_CURVE", "string circle.crv 0.1"});
    definePoint(d, 0.5, 0.25);
    d.run({"choice DONE device 2", "choice MAP_CURVE", "choice DISPLAY_ALL"});
    REQUIRE(d.session.mappings().size() == 2);
    CHECK(d.session.mappings()[1].loops == 1);
    CHECK(d.session.mappings()[1].boundaryWalks == 0);
    CHECK(d.session.message() == "DISPLAYING 2 MAPPED CURVES");
    session_test::compareWithReference(d.picture(), "curve_map_display_all");
    CHECK_FALSE(d.logHasError());
}

TEST_CASE("CURVE MAP menu: REJECT goes back to the patch choice, MAP CURVE needs a curve and a point") {
    Driver d("curve_map_reject");
    loadTransportInFourViews(d);
    d.run({"choice CURVE_MAP", "choice MAP_CURVE"});
    CHECK(d.session.message() == "NO CURVE LOADED: USE LOAD CURVE FIRST");
    d.run({"choice LOAD_CURVE", "string circle.crv 0.1", "choice MAP_CURVE"});
    CHECK(d.session.message() == "NO REFERENCE POINT: USE DEFINE POINT AND DONE FIRST");
    d.run({"choice DEFINE_POINT"});
    const glm::dvec3 p = surfacePoint(d.session, "right_wing", 0.5, 0.3);
    d.pickAt(p, 1);
    d.pickAt(p, 1);
    d.run({"choice REJECT"});
    CHECK(d.session.message() == "SELECT REFERENCE PATCH TO MAP");
    CHECK(d.session.style().colourfulComponent == componentIndex(d.session, "right_wing"));
    session_test::compareWithReference(d.picture(), "curve_map_patch_colours");
    // Only the wing is drawn now: the fuselage's place is empty.
    d.pickAt(surfacePoint(d.session, "fuselage", 0.5, 0.5), 1);
    CHECK(d.session.message() == "NOTHING PICKED: TRY AGAIN");
    d.pickAt(p, 1);
    d.run({"choice ACCEPT", "choice DONE device 2", "choice MAP_CURVE"});
    CHECK(d.session.mappings().size() == 1);
}

TEST_CASE("SURF_REDN menu: by count and by tolerance, U, W, U & W, error map, the original kept in MODELS") {
    Driver d("reduction");
    loadTransportInFourViews(d);
    const glm::dvec3 top = surfacePoint(d.session, "fuselage", 0.5, 0.5);
    d.run({"choice SURF_REDN", "choice BY_COUNT", "choice REDUCE_U"});
    CHECK(d.session.message() == "SELECT COMPONENT TO REDUCE");
    d.pickAt(top, 1);
    CHECK(d.session.message() == "ENTER NUMBER OF KNOTS TO BE REMOVED IN U DIRECTION");
    d.run({"string 3"});
    REQUIRE(d.session.reductions().size() == 1);
    const acsynt::ReductionRecord& byCount = d.session.reductions()[0];
    CHECK(byCount.component == "fuselage");
    CHECK(byCount.countUBefore == 13);
    CHECK(byCount.countUAfter == 10);
    CHECK(byCount.countWAfter == byCount.countWBefore);
    CHECK(d.session.message().rfind("DATA REDUCTION IN U DIRECTION COMPLETE", 0) == 0);
    CHECK(d.session.models().size() == 2);
    CHECK(d.session.models().current().name == "transport_R1");

    d.run({"choice BY_TOLERANCE", "choice REDUCE_W"});
    d.pickAt(top, 1);
    CHECK(d.session.message() == "ENTER TOLERANCE FOR fuselage");
    d.run({"string 0.01"});
    REQUIRE(d.session.reductions().size() == 2);
    const acsynt::ReductionRecord& byTolerance = d.session.reductions()[1];
    CHECK(byTolerance.model == "transport_R1");
    CHECK(byTolerance.countWAfter < byTolerance.countWBefore);
    CHECK(byTolerance.countUAfter == byTolerance.countUBefore);
    CHECK(byTolerance.maxError <= 0.01);
    CHECK(d.session.message().rfind("DATA REDUCTION IN W DIRECTION COMPLETE", 0) == 0);

    d.run({"choice REDUCE_U&W"});
    d.pickAt(surfacePoint(d.session, "right_wing", 0.5, 0.25), 1);
    d.run({"string 0.005"});
    REQUIRE(d.session.reductions().size() == 3);
    CHECK(d.session.reductions()[2].component == "right_wing");
    CHECK(d.session.reductions()[2].maxError <= 0.005);
    CHECK(d.session.message().rfind("DATA REDUCTION IN U AND W DIRECTIONS COMPLETE", 0) == 0);
    CHECK(d.session.models().size() == 4);

    d.run({"choice ERROR_MAP"});
    CHECK(d.session.message().rfind("ERROR MAP: BLUE 0 TO RED ", 0) == 0);
    session_test::compareWithReference(d.picture(), "reduction_error_map");
    d.run({"choice ERROR_MAP"});
    CHECK(d.session.message() == "ERROR MAP OFF");
    d.run({"string x"});
    CHECK(d.session.message() == "NO TEXT EXPECTED: 'x'");
    d.run({"choice REDUCE_U"});
    d.pickAt(top, 1);
    d.run({"string -1"});
    CHECK(d.session.message() == "BAD INPUT IN SRF_REDUCTION: '-1': expected a positive length");
    CHECK(d.session.reductions().size() == 3);
    const std::string summary = d.session.summary();
    CHECK(summary.find(
              "reduction 1: transport/fuselage -> transport_R1, U by count 3: control points 13 x 19 = "
              "247 -> 10 x 19 = 190") != std::string::npos);
}

TEST_CASE("MODELS menu: list, next, previous, rename, delete") {
    Driver d("models");
    d.run({"choice CURVE_MAP"});
    CHECK(d.session.message() == "NO GEOMETRY FILE FOUND!");
    CHECK(d.session.menuTitle() == "MAIN");
    d.run({"choice SURF_REDN"});
    CHECK(d.session.message() == "NO GEOMETRY FILE FOUND!");
    d.run({"choice MODELS", "choice LIST"});
    CHECK(d.session.message() == "NO GEOMETRY FILE FOUND!");
    d.run({"choice RETURN", "choice FILE", "choice READ_MODEL", "string transport.acm", "choice READ_MODEL",
           "string fighter.acm", "choice RETURN", "choice MODELS", "choice LIST"});
    CHECK(d.session.message() == "MODELS: transport fighter*");
    d.run({"choice NEXT_MODEL"});
    CHECK(d.session.message() == "NEXT MODEL DOES NOT EXIST");
    d.run({"choice PREVIOUS_MODEL"});
    CHECK(d.session.message() == "MODEL CHANGE COMPLETE.  CURRENT MODEL NAME = transport");
    CHECK(d.session.models().current().name == "transport");
    d.run({"choice NAME_MODEL"});
    CHECK(d.session.message() == "PLEASE ENTER MODEL NAME");
    d.run({"string airliner"});
    CHECK(d.session.message() == "CURRENT MODEL NAMED airliner");
    d.run({"choice NAME_MODEL", "string not a name!"});
    CHECK(d.session.message() == "BAD INPUT IN MODELS");
    CHECK(d.session.models().current().name == "airliner");
    d.run({"choice NEXT_MODEL"});
    session_test::compareWithReference(d.picture(), "models_fighter");
    d.run({"choice DELETE_MODEL"});
    CHECK(d.session.message() == "MODEL fighter DELETED.  CURRENT MODEL NAME = airliner");
    CHECK(d.session.models().size() == 1);
    CHECK(d.session.models().current().patchCount() == 376);
    CHECK(d.session.workstation().display().items.size() > 376);
}

TEST_CASE("FILE menu: save and read back a model, archive and retrieve its structures, read a curve file") {
    Driver d("file");
    const auto out = session_test::outputDirectory("file");
    std::filesystem::remove_all(out);
    d.run({"choice FILE", "choice SAVE_MODEL"});
    CHECK(d.session.message() == "NO GEOMETRY FILE FOUND!");
    d.run({"choice READ_MODEL", "string fighter.acm", "choice SAVE_MODEL", "string saved.acm"});
    CHECK(d.session.message() ==
          "MODEL fighter SAVED TO " + (out / "saved.acm").string() + ": 6 COMPONENTS, 0 MAPPED CURVES");
    REQUIRE(std::filesystem::exists(out / "saved.acm"));
    d.run({"choice READ_MODEL", "string " + (out / "saved.acm").string()});
    CHECK(d.session.message() ==
          "MODEL fighter READ AS fighter_2 (fighter IS LOADED): 6 COMPONENTS, 192 PATCHES");
    CHECK(d.session.models().size() == 2);

    // Read back beside the original once that is renamed: the saved file holds the same surfaces.
    d.run({"choice RETURN", "choice MODELS", "choice DELETE_MODEL", "choice NAME_MODEL", "string original",
           "choice RETURN", "choice FILE", "choice READ_MODEL", "string " + (out / "saved.acm").string()});
    CHECK(d.session.message() == "MODEL fighter READ: 6 COMPONENTS, 192 PATCHES");
    REQUIRE(d.session.models().size() == 2);
    const acsynt::Model& original = d.session.models().at(0);
    const acsynt::Model& readBack = d.session.models().at(1);
    CHECK(original.name == "original");
    CHECK(readBack.name == "fighter");
    CHECK(d.session.models().current().name == "fighter");
    REQUIRE(readBack.components.size() == original.components.size());
    CHECK(readBack.patchCount() == original.patchCount());
    for (std::size_t c = 0; c < original.components.size(); ++c) {
        const acsynt::Component& a = original.components[c];
        const acsynt::Component& b = readBack.components[c];
        INFO("component " << a.name);
        CHECK(b.name == a.name);
        CHECK(b.patches.patches.size() == a.patches.patches.size());
        CHECK(b.surface.countU == a.surface.countU);
        CHECK(b.surface.countV == a.surface.countV);
        for (const glm::dvec2 uw : {glm::dvec2(0.0, 0.0), glm::dvec2(0.3, 0.7), glm::dvec2(0.5, 0.5),
                                    glm::dvec2(0.9, 0.15), glm::dvec2(1.0, 1.0)})
            CHECK(glm::length(geom::evaluate(b.surface, uw.x, uw.y) - geom::evaluate(a.surface, uw.x, uw.y)) <
                  1e-12);
    }

    // ARCHIVE the network of the model root, spoil two of its structures, RETRIEVE puts them back.
    phigs::StructureStore& store = d.session.phigs().store();
    std::map<int, int> elementCounts;
    for (const int id : store.network(acsynt::structures::modelRoot))
        elementCounts[id] = store.elementCount(id);
    d.run({"choice ARCHIVE", "string fighter.phar"});
    CHECK(d.session.message().rfind("ARCHIVED ", 0) == 0);
    const std::size_t structures = std::size_t(std::stoi(d.session.message().substr(9)));
    CHECK(structures ==
          1 + 6 + 192 + 3);  // root, components, patches, overlays (hulls are off, not in the network)
    CHECK(elementCounts.size() == structures);
    const int component = acsynt::structures::component(1), patch = acsynt::structures::patch(1, 5);
    REQUIRE(elementCounts.count(component));
    REQUIRE(elementCounts.count(patch));
    REQUIRE(elementCounts[component] > 0);
    REQUIRE(elementCounts[patch] > 0);
    store.emptyStructure(component);
    store.deleteStructure(patch);
    REQUIRE(store.elementCount(component) == 0);
    REQUIRE_FALSE(store.exists(patch));
    d.run({"choice RETRIEVE", "string " + (out / "fighter.phar").string()});
    CHECK(d.session.message() ==
          "RETRIEVED " + std::to_string(structures) + " STRUCTURES FROM " + (out / "fighter.phar").string());
    for (const auto& [id, count] : elementCounts) {
        INFO("structure " << id);
        REQUIRE(store.exists(id));
        CHECK(store.elementCount(id) == count);
    }
    d.run({"choice RETRIEVE", "string missing.phar"});
    CHECK(d.session.message() == "ARCHIVE FILE missing.phar NOT FOUND");
    d.run({"choice READ_CURVE_FILE", "string acslogo.crv"});
    CHECK(d.session.message() == "CURVE MODEL acslogo.crv LOADED: 5 PARTS");
    d.run({"choice EXIT"});
    CHECK(d.session.finished());
}

/// Every element of every structure in the network of the model root.
std::map<int, std::vector<phigs::Element>> modelStructures(Driver& d) {
    const phigs::StructureStore& store = d.session.phigs().store();
    std::map<int, std::vector<phigs::Element>> out;
    for (const int id : store.network(acsynt::structures::modelRoot))
        for (int k = 1; k <= store.elementCount(id); ++k) out[id].push_back(store.elementAt(id, k));
    return out;
}

TEST_CASE("FILE menu: RETRIEVE takes back only a picture of the current model, in the session's style") {
    Driver d("retrieve");
    const auto out = session_test::outputDirectory("retrieve");
    std::filesystem::remove_all(out);
    const std::string archive = (out / "fighter.phar").string();
    // Written in wireframe, taken back while shaded: the session's style stays on the screen.
    d.run({"choice VIEW", "choice WIREFRAME", "choice RETURN", "choice FILE", "choice READ_MODEL",
           "string fighter.acm", "choice ARCHIVE", "string fighter.phar", "choice RETURN", "choice VIEW",
           "choice SHADE", "choice RETURN", "choice FILE"});
    REQUIRE(std::filesystem::exists(archive));
    const auto fighter = modelStructures(d);
    d.run({"choice RETRIEVE", "string " + archive});
    CHECK(d.session.message().rfind("RETRIEVED ", 0) == 0);
    CHECK(modelStructures(d) == fighter);

    // Another model's archive would put the fighter on the screen while picks and mappings go to
    // the transport: refused, nothing changed.
    d.run({"choice READ_MODEL", "string transport.acm"});
    const auto transport = modelStructures(d);
    const std::size_t failed = d.session.failedLines();
    d.run({"choice RETRIEVE", "string " + archive});
    CHECK(d.session.failedLines() == failed + 1);
    CHECK(d.session.message().rfind("ARCHIVE " + archive + " IS NOT A PICTURE OF MODEL transport: STRUCTURE ",
                                    0) == 0);
    CHECK(modelStructures(d) == transport);
}

TEST_CASE("numbered choices: `choice N` takes the Nth item of the menu shown") {
    Driver d("numbered");
    d.run({"choice 1"});  // MAIN: FILE
    CHECK(d.session.menuTitle() == "FILE");
    d.run({"choice 2", "string fighter.acm"});  // READ_MODEL
    CHECK(d.session.message() == "MODEL fighter READ: 6 COMPONENTS, 192 PATCHES");
    d.run({"choice 1", "choice 2"});  // RETURN, then MAIN: VIEW
    CHECK(d.session.menuTitle() == "VIEW");
    d.run({"choice 3", "choice 5", "choice 6"});  // FOUR_VIEWS, WIREFRAME, HULL_ON
    CHECK(d.session.fourViews());
    CHECK_FALSE(d.session.style().shaded);
    CHECK(d.session.style().hull);
    d.run({"choice 7", "choice 4", "choice 2"});  // HULL_OFF, SHADE, ONE_VIEW
    CHECK_FALSE(d.session.fourViews());
    CHECK(d.session.style().shaded);
    CHECK_FALSE(d.session.style().hull);
    d.run({"choice 1", "choice 5"});  // RETURN, then MAIN: MODELS
    CHECK(d.session.menuTitle() == "MODELS");
    d.run({"choice 5", "string jet"});  // NAME_MODEL
    CHECK(d.session.message() == "CURRENT MODEL NAMED jet");
    d.run({"choice 4"});  // LIST
    CHECK(d.session.message() == "MODELS: jet*");
    d.run({"choice 2"});  // NEXT_MODEL
    CHECK(d.session.message() == "NEXT MODEL DOES NOT EXIST");
    // A number past the end of the menu is refused with the range: the menu stays, the session goes on.
    d.run({"choice 7"});
    CHECK(d.session.message().find("CHOICE 1 has alternatives 1..6") != std::string::npos);
    CHECK(d.logHasError());
    CHECK(d.session.menuTitle() == "MODELS");
    CHECK(d.session.models().size() == 1);
    d.run({"choice 1", "choice 8"});  // RETURN, then MAIN: EXIT
    CHECK(d.session.finished());
}

TEST_CASE("lines no menu or device takes are refused and counted, naming the line") {
    // Choice 0 (PHIGS's NOCHOICE) chooses no item, and a device the workstation lacks reaches no
    // device: each is an error of its own line, and the menu stays. (A break with nothing
    // requested stays quiet: it is how Escape cancels in a window.)
    struct Case {
        std::string line, says;
    };
    const std::vector<Case> cases{{"choice 0", "NO MENU ITEM CHOSEN (CHOICE 0): THE ITEMS ARE 1..8"},
                                  {"choice FILE device 7", "reached no device"},
                                  {"valuator 9 0.5", "reached no device"}};
    for (const Case& c : cases) {
        Driver d("refused_lines");
        INFO(c.line);
        d.run({c.line});
        CHECK(d.session.failedLines() == 1);
        CHECK(d.session.message().find(c.says) != std::string::npos);
        CHECK(d.session.menuTitle() == "MAIN");
        REQUIRE_FALSE(d.session.log().empty());
        CHECK(d.session.log().back().rfind("ERROR: ", 0) == 0);
        d.run({"choice FILE"});  // the session goes on
        CHECK(d.session.menuTitle() == "FILE");
        CHECK(d.session.failedLines() == 1);
    }
}

TEST_CASE("a pick on a row of the menu panel chooses that item, as a click in a window does") {
    Driver d("menu_pick");
    auto pickItem = [&](const std::string& item) {
        const auto& items = d.session.menuItems();
        const auto it = std::find(items.begin(), items.end(), item);
        REQUIRE(it != items.end());
        const phigs::ChoicePanel panel{1, d.session.layout().menuFor(items.size()).echoVolume(), items};
        const auto [a, b] = panel.row(int(it - items.begin()) + 1);
        const glm::dvec2 centre = (a + b) / 2.0;
        d.run({"pick " + std::to_string(centre.x) + " " + std::to_string(centre.y)});
    };
    pickItem("VIEW");
    CHECK(d.session.menuTitle() == "VIEW");
    pickItem("FOUR_VIEWS");
    CHECK(d.session.fourViews());
    pickItem("RETURN");
    CHECK(d.session.menuTitle() == "MAIN");
    session_test::compareWithReference(d.picture(), "menu_main_empty");
}

}  // namespace test_session_menus
