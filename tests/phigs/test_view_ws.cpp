#include "ErrorNumber.h"
#include "phigs/Phigs.h"
#include "phigs/store/Gdp.h"
#include "phigs/view/ViewMatrices.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>

namespace test_view_ws {

using namespace phigs;
using phigs::test::errorOf;

namespace {

glm::dvec3 project(const glm::dmat4& m, glm::dvec3 p) {
    glm::dvec4 h = m * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
}

bool near(glm::dvec3 a, glm::dvec3 b) {
    return glm::length(a - b) < 1e-12;
}

/// The error EVALUATE VIEW MAPPING MATRIX 3 gives for a valid mapping that `change` alters.
template <class Change>
int mappingError(Change change) {
    ViewMapping p;
    p.backPlaneDistance = -1;
    p.frontPlaneDistance = 1;
    p.projectionReferencePoint = {0, 0, 5};
    change(p);
    return errorOf([&] { evaluateViewMappingMatrix(p); });
}

}  // namespace

TEST_CASE("evaluate view orientation matrix", "[view]") {
    glm::dmat4 m = evaluateViewOrientationMatrix({1, 2, 3}, {0, 0, 5}, {0, 3, 0});
    CHECK(near(glm::dvec3(m * glm::dvec4(1, 2, 3, 1)), {0, 0, 0}));
    CHECK(near(glm::dvec3(m * glm::dvec4(2, 2, 3, 1)), {1, 0, 0}));
    // looking along -x with z up: n = +x, v = +z, u = v x n... = +y
    glm::dmat4 side = evaluateViewOrientationMatrix({0, 0, 0}, {1, 0, 0}, {0, 0, 1});
    CHECK(near(glm::dvec3(side * glm::dvec4(0, 1, 0, 1)), {1, 0, 0}));
    CHECK(near(glm::dvec3(side * glm::dvec4(0, 0, 1, 1)), {0, 1, 0}));
    CHECK(near(glm::dvec3(side * glm::dvec4(1, 0, 0, 1)), {0, 0, 1}));
    CHECK(errorOf([] {
              evaluateViewOrientationMatrix({}, {0, 0, 0}, {0, 1, 0});
          }) == errors::ZeroViewPlaneNormal);
    CHECK(errorOf([] { evaluateViewOrientationMatrix({}, {0, 0, 1}, {0, 0, 0}); }) == errors::ZeroViewUp);
    CHECK(errorOf([] {
              evaluateViewOrientationMatrix({}, {0, 0, 1}, {0, 0, -2});
          }) == errors::ViewUpParallelToNormal);
}

TEST_CASE("evaluate view mapping matrix: parallel and perspective", "[view]") {
    ViewMapping p;
    p.windowMin = {-2, -1};
    p.windowMax = {2, 1};
    p.viewportMin = {0, 0, 0};
    p.viewportMax = {1, 0.5, 1};
    p.projectionReferencePoint = {0, 0, 10};
    p.backPlaneDistance = -1;
    p.frontPlaneDistance = 1;
    glm::dmat4 m = evaluateViewMappingMatrix(p);
    CHECK(near(project(m, {-2, -1, -1}), {0, 0, 0}));
    CHECK(near(project(m, {2, 1, 1}), {1, 0.5, 1}));
    // oblique: the PRP off the window's centre line shears, keeping the view plane
    p.projectionReferencePoint = {1, 0, 1};
    glm::dmat4 oblique = evaluateViewMappingMatrix(p);
    CHECK(near(project(oblique, {0, 0, 0}), {0.5, 0.25, 0.5}));
    CHECK(near(project(oblique, {1, 0, 1}), {0.5, 0.25, 1}));  // along the direction of projection
    // perspective: points on a projector through the PRP map to the same x, y
    p.projection = ProjectionType::Perspective;
    p.projectionReferencePoint = {0, 0, 5};
    glm::dmat4 persp = evaluateViewMappingMatrix(p);
    CHECK(near(project(persp, {2, 1, 0}), {1, 0.5, project(persp, {2, 1, 0}).z}));
    glm::dvec3 a = project(persp, {1, 1, 0}), b = project(persp, {0.8, 0.8, 1});  // (1,1,0) seen from (0,0,5)
    CHECK(std::abs(a.x - b.x) < 1e-12);
    CHECK(std::abs(project(persp, {0, 0, 1}).z - 1.0) < 1e-12);
    CHECK(std::abs(project(persp, {0, 0, -1}).z) < 1e-12);
}

TEST_CASE("view mapping errors 151-164", "[view][errors]") {
    auto with = [](auto change) { return mappingError(change); };
    CHECK(with([](ViewMapping& p) { p.windowMax.x = -1; }) == errors::InvalidWindow);
    CHECK(with([](ViewMapping& p) { p.viewportMin.z = 0.5, p.viewportMax.z = 0.2; }) ==
          errors::InvalidViewport);
    CHECK(with([](ViewMapping& p) { p.viewportMax.x = 1.5; }) == errors::ProjectionViewportOutsideNpc);
    CHECK(with([](ViewMapping& p) { p.frontPlaneDistance = -1; }) == errors::FrontEqualsBack);
    CHECK(with([](ViewMapping& p) { p.frontPlaneDistance = -2; }) == errors::BackInFrontOfFront);
    CHECK(with([](ViewMapping& p) { p.projectionReferencePoint.z = 0; }) == errors::PrpOnViewPlane);
    CHECK(with([](ViewMapping& p) {
              p.projection = ProjectionType::Perspective;
              p.projectionReferencePoint.z = 0.5;
          }) == errors::PrpBetweenPlanes);
    CHECK(with([](ViewMapping&) {}) == 0);
}

TEST_CASE("perspective mappings give w > 0 in the view volume, the view plane on either side of the PRP",
          "[view]") {
    // With the view plane beyond the PRP (an inverted image, which the standard allows) w was
    // negative throughout the volume, so clipping dropped everything (a tester's 732 of 5,000).
    std::mt19937 rng(6122026);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int member = 0; member < 2000; ++member) {
        ViewMapping p;
        p.projection = ProjectionType::Perspective;
        p.windowMin = {-1.0 - unit(rng), -1.0 - unit(rng)};
        p.windowMax = {1.0 + unit(rng), 1.0 + unit(rng)};
        p.backPlaneDistance = -1.0 - 2.0 * unit(rng);
        p.frontPlaneDistance = 1.0 + 2.0 * unit(rng);
        const bool above = member % 2 == 0;  // the PRP in front of the front plane, or behind the back
        const double prpZ = above ? p.frontPlaneDistance + 0.5 + 4.0 * unit(rng)
                                  : p.backPlaneDistance - 0.5 - 4.0 * unit(rng);
        p.projectionReferencePoint = {unit(rng) - 0.5, unit(rng) - 0.5, prpZ};
        p.viewPlaneDistance = -8.0 + 16.0 * unit(rng);  // either side of the PRP
        if (std::abs(p.viewPlaneDistance - prpZ) < 1e-3) continue;
        const glm::dmat4 m = evaluateViewMappingMatrix(p);
        INFO("member " << member << ": PRP z " << prpZ << ", view plane " << p.viewPlaneDistance);
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 q(
                4.0 * unit(rng) - 2.0, 4.0 * unit(rng) - 2.0,
                p.backPlaneDistance + unit(rng) * (p.frontPlaneDistance - p.backPlaneDistance));
            const glm::dvec4 h = m * glm::dvec4(q, 1.0);
            CHECK(h.w > 0.0);
            // The projector from the PRP through q meets the view plane at (x, y): the window's
            // place of it is the viewport's place of (x/w, y/w).
            const glm::dvec3 prp = p.projectionReferencePoint;
            const double t = (p.viewPlaneDistance - prp.z) / (q.z - prp.z);
            const glm::dvec2 onPlane = glm::dvec2(prp) + t * (glm::dvec2(q) - glm::dvec2(prp));
            const glm::dvec2 expected = (onPlane - p.windowMin) / (p.windowMax - p.windowMin);
            CHECK(std::abs(h.x / h.w - expected.x) < 1e-9);
            CHECK(std::abs(h.y / h.w - expected.y) < 1e-9);
            CHECK((h.z / h.w >= -1e-12 && h.z / h.w <= 1.0 + 1e-12));
        }
    }
}

TEST_CASE("view utilities refuse an input that is not finite, naming it", "[view][errors]") {
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    CHECK(errorOf([&] {
              evaluateViewOrientationMatrix({0, 0, 0}, {0, 0, nan}, {0, 1, 0});
          }) == errors::NonFiniteValue);
    CHECK(errorOf([&] {
              evaluateViewOrientationMatrix({inf, 0, 0}, {0, 0, 1}, {0, 1, 0});
          }) == errors::NonFiniteValue);
    CHECK(errorOf([&] {
              evaluateViewOrientationMatrix({0, 0, 0}, {0, 0, 1}, {nan, 1, 0});
          }) == errors::NonFiniteValue);
    auto with = [](auto change) { return mappingError(change); };
    CHECK(with([&](ViewMapping& p) { p.windowMin.x = nan; }) == errors::NonFiniteValue);
    CHECK(with([&](ViewMapping& p) { p.viewportMax.y = nan; }) == errors::NonFiniteValue);
    CHECK(with([&](ViewMapping& p) { p.projectionReferencePoint.z = nan; }) == errors::NonFiniteValue);
    CHECK(with([&](ViewMapping& p) { p.viewPlaneDistance = inf; }) == errors::NonFiniteValue);
    CHECK(with([&](ViewMapping& p) { p.backPlaneDistance = -inf; }) == errors::NonFiniteValue);
    ErrorLog log;
    try {
        ViewMapping p;
        p.projectionReferencePoint.x = nan;
        evaluateViewMappingMatrix(p, &log);
    } catch (const Error&) {
    }
    REQUIRE(!log.entries().empty());
    CHECK(log.entries().back().detail.find("projection reference point") != std::string::npos);
}

TEST_CASE("view table: entry 0 fixed, capacity, clip limits, input priority", "[view][ws]") {
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
    ViewRepresentation v;
    CHECK(errorOf([&] { ws.setViewRepresentation(0, v); }) == errors::ViewIndexBelowOne);
    CHECK(errorOf([&] { ws.setViewRepresentation(ws.description().viewTableSize, v); }) ==
          errors::ViewTableFull);
    v.clipMin = {0.5, 0, 0};
    v.clipMax = {0.5, 1, 1};
    CHECK(errorOf([&] { ws.setViewRepresentation(1, v); }) == errors::InvalidClipLimits);
    v.clipMax = {1.5, 1, 1};
    CHECK(errorOf([&] { ws.setViewRepresentation(1, v); }) == errors::ClipLimitsOutsideNpc);
    v.clipMax = {1, 1, 1};
    ws.setViewRepresentation(1, v);
    ws.setViewRepresentation(3, v);
    CHECK(ws.tables().views.definedIndices() == std::vector<int>{0, 1, 3});
    CHECK(ws.tables().views.inputPriority() == std::vector<int>{0, 1, 3});
    ws.setViewTransformationInputPriority(3, 0, true);
    CHECK(ws.tables().views.inputPriority() == std::vector<int>{3, 0, 1});
    ws.setViewTransformationInputPriority(3, 1, false);
    CHECK(ws.tables().views.inputPriority() == std::vector<int>{0, 1, 3});
    CHECK(errorOf([&] { ws.setViewTransformationInputPriority(2, 1, true); }) ==
          errors::RepresentationNotDefined);
}

TEST_CASE("workstation tables, window, viewport and HLHSR mode with their errors", "[ws][errors]") {
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(4, WorkstationType::Hardcopy);
    CHECK(ws.type() == WorkstationType::Hardcopy);
    CHECK(errorOf([&] { ws.setColourRepresentation(-1, {0, 0, 0}); }) == errors::ColourIndexBelowZero);
    CHECK(errorOf([&] { ws.setColourRepresentation(3, {0, 2, 0}); }) == errors::BadColour);
    ws.setColourRepresentation(0, {0.2, 0.2, 0.2});
    CHECK(ws.tables().colours.get(0) == glm::dvec3(0.2));
    CHECK(errorOf([&] { ws.setPolylineRepresentation(0, {}); }) == errors::BundleIndexBelowOne);
    CHECK(errorOf([&] {
              ws.setPolylineRepresentation(2, {static_cast<LineType>(9), 1, Colour::indexed(1)});
          }) == errors::BadLineType);
    for (int i = 2; i <= ws.description().bundleTableSize; ++i) ws.setEdgeRepresentation(i, {});
    CHECK(errorOf([&] { ws.setEdgeRepresentation(100, {}); }) == errors::BundleTableFull);
    CHECK(errorOf([&] { ws.setHlhsrMode(7); }) == errors::BadHlhsrMode);
    CHECK(errorOf([&] { ws.setWorkstationWindow({0, 0, 0}, {0, 1, 1}); }) == errors::InvalidWindow);
    CHECK(errorOf([&] {
              ws.setWorkstationWindow({0, 0, 0}, {2, 1, 1});
          }) == errors::WorkstationWindowOutsideNpc);
    CHECK(errorOf([&] {
              ws.setWorkstationViewport({0, 0, 0}, {1e6, 1, 1});
          }) == errors::WorkstationViewportOutsideDisplay);
    ws.setWorkstationWindow({0, 0, 0}, {0.5, 0.5, 1});
    ws.setWorkstationViewport({0, 0, 0}, {100, 100, 1});
    const DrawList& list = ws.display();
    CHECK(list.windowMax == glm::dvec3(0.5, 0.5, 1));
    CHECK(list.viewportMax == glm::dvec3(100, 100, 1));
    CHECK(list.background == glm::vec3(0.2f));
}

TEST_CASE("NaN and infinite reals in the workstation's tables are refused, the tables unchanged",
          "[ws][errors][bad-input]") {
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    const WorkstationTables before = ws.tables();
    // Every bound of the window and viewport, NaN: its own error, as a reversed pair is.
    for (int i = 0; i < 6; ++i) {
        glm::dvec3 lo(0.0), hi(1.0), vlo(0.0), vhi(100.0, 100.0, 1.0);
        (i < 3 ? lo : hi)[i % 3] = nan;
        (i < 3 ? vlo : vhi)[i % 3] = nan;
        INFO("bound " << i);
        CHECK(errorOf([&] { ws.setWorkstationWindow(lo, hi); }) == errors::InvalidWindow);
        CHECK(errorOf([&] { ws.setWorkstationViewport(vlo, vhi); }) == errors::InvalidViewport);
    }
    CHECK(errorOf([&] {
              ws.setWorkstationWindow({0, 0, 0}, {inf, 1, 1});
          }) == errors::WorkstationWindowOutsideNpc);
    // Views: NaN clip limits are 153, a NaN or infinite matrix entry -208.
    for (int i = 0; i < 6; ++i) {
        ViewRepresentation v;
        (i < 3 ? v.clipMin : v.clipMax)[i % 3] = nan;
        CHECK(errorOf([&] { ws.setViewRepresentation(1, v); }) == errors::InvalidClipLimits);
    }
    for (int entry = 0; entry < 32; ++entry) {
        ViewRepresentation v;
        (entry < 16 ? v.orientation : v.mapping)[entry % 4][(entry / 4) % 4] = entry % 2 ? nan : -inf;
        CHECK(errorOf([&] { ws.setViewRepresentation(1, v); }) == errors::NonFiniteValue);
    }
    // Bundles: widths, scales, spacings, area properties, approximation values.
    PolylineBundle line;
    line.width = nan;
    CHECK(errorOf([&] { ws.setPolylineRepresentation(2, line); }) == errors::NonFiniteValue);
    line = {};
    line.approximation.valueU = inf;
    CHECK(errorOf([&] { ws.setPolylineRepresentation(2, line); }) == errors::NonFiniteValue);
    PolymarkerBundle marker;
    marker.scale = nan;
    CHECK(errorOf([&] { ws.setPolymarkerRepresentation(2, marker); }) == errors::NonFiniteValue);
    TextBundle text;
    text.spacing = nan;
    CHECK(errorOf([&] { ws.setTextRepresentation(2, text); }) == errors::NonFiniteValue);
    EdgeBundle edge;
    edge.width = inf;
    CHECK(errorOf([&] { ws.setEdgeRepresentation(2, edge); }) == errors::NonFiniteValue);
    InteriorBundle interior;
    interior.backProperties.specularExponent = nan;
    CHECK(errorOf([&] { ws.setInteriorRepresentation(2, interior); }) == errors::NonFiniteValue);
    // Lights and depth cues: a NaN colour component is 136, any other NaN real -208.
    Light light;
    light.colour = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    CHECK(errorOf([&] { ws.setLightSourceRepresentation(1, light); }) == errors::BadDirectColour);
    light = {};
    light.direction.y = nan;
    CHECK(errorOf([&] { ws.setLightSourceRepresentation(1, light); }) == errors::NonFiniteValue);
    light = {};
    light.spreadAngle = std::numeric_limits<float>::infinity();
    CHECK(errorOf([&] { ws.setLightSourceRepresentation(1, light); }) == errors::NonFiniteValue);
    DepthCue cue;
    cue.backPlane = nan;
    CHECK(errorOf([&] { ws.setDepthCueRepresentation(1, cue); }) == errors::NonFiniteValue);
    cue = {};
    CHECK(errorOf([&] {
              ws.setDepthCueRepresentation(1, cue, Colour::fromRgb({0.0, nan, 0.0}));
          }) == errors::BadDirectColour);
    // Nothing refused reached a table.
    CHECK(ws.tables().windowMin == before.windowMin);
    CHECK(ws.tables().windowMax == before.windowMax);
    CHECK(ws.tables().viewportMin == before.viewportMin);
    CHECK(ws.tables().viewportMax == before.viewportMax);
    CHECK(ws.tables().views.definedIndices() == before.views.definedIndices());
    CHECK(ws.tables().polylines.definedIndices() == before.polylines.definedIndices());
    CHECK(ws.tables().lights == before.lights);
    CHECK(ws.tables().depthCues == before.depthCues);
    // A finite entry still goes in.
    ws.setWorkstationWindow({0, 0, 0}, {0.5, 0.5, 1});
    CHECK(ws.tables().windowMax == glm::dvec3(0.5, 0.5, 1));
}

TEST_CASE("a window's display surface follows its drawable, the whole-surface viewport with it", "[ws]") {
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
    CHECK(ws.displaySize() == glm::dvec2(1024, 768));
    const std::uint64_t before = ws.regenerations();
    ws.display();
    ws.setDisplaySize({1600, 900});
    CHECK(ws.displaySize() == glm::dvec2(1600, 900));
    CHECK(ws.description().displaySize == glm::dvec2(1600, 900));
    const DrawList& wide = ws.display();
    CHECK(ws.regenerations() > before + 1);  // a new size is a new picture
    CHECK(wide.displaySize == glm::dvec2(1600, 900));
    CHECK(wide.viewportMax == glm::dvec3(1600, 900, 1));   // it covered the surface: it still does
    ws.setWorkstationViewport({0, 0, 0}, {1200, 900, 1});  // allowed now, refused at 1024 x 768
    ws.setDisplaySize({800, 600});
    CHECK(ws.display().viewportMax == glm::dvec3(1200, 900, 1));  // a chosen viewport stays
    CHECK(errorOf([&] { ws.setDisplaySize({0, 600}); }) == errors::InvalidViewport);
    CHECK(errorOf([&] { ws.setDisplaySize({800, -1}); }) == errors::InvalidViewport);
    CHECK(ws.displaySize() == glm::dvec2(800, 600));  // unchanged by the refusals
}

TEST_CASE("deferral and modification modes, the state of visual representation, update", "[ws]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
    store.openStructure(1);
    store.insert(polyline3({{0, 0, 0}, {1, 1, 0}}));
    store.closeStructure();
    ws.postStructure(1, 0.5);
    CHECK(ws.display().items.size() == 1);
    CHECK(ws.visualState() == VisualState::Correct);

    ws.setDeferralState(DeferralMode::Wait, ModificationMode::Nive);
    store.openStructure(1);
    store.insert(polyline3({{0, 0, 0}, {1, 0, 0}}));
    store.closeStructure();
    CHECK(ws.visualState() == VisualState::Deferred);
    std::uint64_t regenerations = ws.regenerations();
    CHECK(ws.display().items.size() == 1);  // not shown yet
    CHECK(ws.regenerations() == regenerations);
    ws.update(Regeneration::Postpone);
    CHECK(ws.display().items.size() == 1);
    ws.update(Regeneration::Perform);
    CHECK(ws.display().items.size() == 2);
    CHECK(ws.visualState() == VisualState::Correct);
    ws.update(Regeneration::Perform);  // nothing changed: no regeneration
    CHECK(ws.regenerations() == regenerations + 1);

    ws.setDeferralState(DeferralMode::Asti, ModificationMode::Uqum);
    ws.setColourRepresentation(1, {0.5, 0.5, 0.5});
    CHECK(ws.display().items[0].primitive.index() == 0);
    CHECK(ws.visualState() == VisualState::Simulated);  // shown by a quick update, not guaranteed
    ws.redrawAllStructures();
    CHECK(ws.visualState() == VisualState::Correct);

    ws.setDeferralState(DeferralMode::Asap, ModificationMode::Nive);
    ws.unpostStructure(1);
    CHECK(ws.display().items.empty());
    ws.postStructure(1, 0.2);
    ws.unpostAllStructures();
    CHECK(ws.postedStructures().empty());
    CHECK(ws.visualState() == VisualState::Correct);
}

TEST_CASE("every workstation type lists exactly the GDPs traversal draws", "[ws][gdp]") {
    for (WorkstationType type :
         {WorkstationType::OffscreenImage, WorkstationType::Window, WorkstationType::Hardcopy,
          WorkstationType::PdfFile, WorkstationType::SvgFile, WorkstationType::EpsFile}) {
        const WorkstationDescription d = describeWorkstationType(type);
        for (int id = -100; id <= 100; ++id) {
            INFO(d.name << " GDP " << id);
            const bool listed3 = std::find(d.gdps3.begin(), d.gdps3.end(), id) != d.gdps3.end();
            const bool listed = std::find(d.gdps.begin(), d.gdps.end(), id) != d.gdps.end();
            CHECK(listed3 == isRegisteredGdp(id));
            CHECK(listed == isRegisteredGdp(id));
        }
        CHECK(d.gses.empty());  // no GSE is registered
    }
}

TEST_CASE("workstation types and their descriptions", "[ws]") {
    Phigs phigs;
    phigs.open();
    // The offscreen image is OUTIN: its input comes from a script source (headless programs).
    CHECK(phigs.openWorkstation(1, WorkstationType::OffscreenImage).description().category ==
          WorkstationCategory::OutIn);
    CHECK(phigs.openWorkstation(2, WorkstationType::Window).description().category ==
          WorkstationCategory::OutIn);
    CHECK(phigs.openWorkstation(3, WorkstationType::Hardcopy).description().name == "hardcopy");
    CHECK(phigs.workstation(3).description().category == WorkstationCategory::Output);
    CHECK(describeWorkstationType(WorkstationType::PdfFile).category == WorkstationCategory::Output);
    CHECK(phigs.openWorkstationIds() == std::vector<int>{1, 2, 3});
    phigs.workstation(1).postStructure(5, 0.5);
    phigs.workstation(3).postStructure(5, 0.1);
    CHECK(phigs.workstationsPostedTo(5) == std::vector<int>{1, 3});
    CHECK(errorOf([&] { phigs.workstationsPostedTo(6); }) == errors::StructureDoesNotExist);
    phigs.closeWorkstation(2);
    CHECK(phigs.openWorkstationIds() == std::vector<int>{1, 3});
    CHECK(errorOf([&] { phigs.closeWorkstation(2); }) == errors::WorkstationNotOpen);
}

}  // namespace test_view_ws
