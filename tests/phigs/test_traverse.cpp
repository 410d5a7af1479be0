#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <iterator>
#include <random>

namespace test_traverse {

using namespace phigs;

namespace {

struct Scene {
    Phigs phigs;
    StructureStore* store = nullptr;
    Workstation* ws = nullptr;
    Scene() {
        phigs.open();
        store = &phigs.store();
        ws = &phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    }
    void build(int id, std::initializer_list<Element> elements) {
        store->openStructure(id);
        store->emptyStructure(id);
        for (const Element& e : elements) store->insert(e);
        store->closeStructure();
    }
};

const Element line = polyline3({{0, 0, 0}, {1, 0, 0}});

const DrawPolyline& polylineOf(const DrawItem& item) {
    return std::get<DrawPolyline>(item.primitive);
}

geom::Surface bilinearPatch() {
    return geom::Surface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                         {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}});
}

}  // namespace

TEST_CASE("attributes are inherited by executed structures and restored on return", "[traverse]") {
    Scene s;
    s.build(2, {line, polylineColourIndex(3), line});
    s.build(1, {polylineColourIndex(2), IndexAttribute{ElementType::Linetype, 2}, executeStructure(2), line});
    s.ws->postStructure(1, 0.5);
    const DrawList& list = s.ws->display();
    REQUIRE(list.items.size() == 3);
    CHECK(polylineOf(list.items[0]).style->colour == glm::vec3(1, 0, 0));  // inherited colour 2
    CHECK(polylineOf(list.items[0]).style->type == LineType::Dashed);
    CHECK(polylineOf(list.items[1]).style->colour == glm::vec3(0, 1, 0));  // set in the child
    CHECK(polylineOf(list.items[2]).style->colour == glm::vec3(1, 0, 0));  // restored after return
    // the paths: structure, 1-based element number, pick id per level
    CHECK(list.items[1].source.path() == std::vector<DrawPathLevel>{{1, 3, 0}, {2, 3, 0}});
    CHECK(list.items[2].source.path() == std::vector<DrawPathLevel>{{1, 4, 0}});
    CHECK(list.items[1].source.structureVersion() == s.store->structure(2).version);
}

TEST_CASE("bundled attributes through the aspect source flags", "[traverse]") {
    Scene s;
    s.ws->setPolylineRepresentation(2, {LineType::Dotted, 3.0, Colour::indexed(4)});
    s.build(1, {IndexAttribute{ElementType::PolylineIndex, 2}, line, AsfAttribute{AspectId::LineType, false},
                AsfAttribute{AspectId::PolylineColour, false}, line,
                IndexAttribute{ElementType::PolylineIndex, 9}, line});
    s.ws->postStructure(1, 0);
    const DrawList& list = s.ws->display();
    REQUIRE(list.items.size() == 3);
    CHECK(polylineOf(list.items[0]).style->type == LineType::Solid);  // individual by default
    CHECK(polylineOf(list.items[1]).style->type == LineType::Dotted);
    CHECK(polylineOf(list.items[1]).style->colour == glm::vec3(0, 0, 1));
    CHECK(polylineOf(list.items[1]).style->width == 1.0f);            // width still individual
    CHECK(polylineOf(list.items[2]).style->type == LineType::Solid);  // undefined bundle 9 reads as bundle 1
}

TEST_CASE("types, widths and sizes the workstation lacks are drawn as the nearest it has", "[traverse]") {
    // ISO 9592: a line or edge type not available is drawn as 1, a marker type as 3, a width or
    // size as the nearest available: the description's limits, whatever the element asked.
    Scene s;
    const PrimitiveLimits& limits = s.ws->description().primitives;
    std::mt19937 random(2026);
    std::uniform_int_distribution<int> type(-4, 12);
    const double scales[] = {0.0, 1e-6, 0.05, 0.5, 1.0, 3.0, 15.9, 16.1, 40.0, 200.0, 1e9};
    for (int trial = 0; trial < 60; ++trial) {
        const int lineType = type(random), markerType = type(random), edgeType = type(random);
        const double width = scales[random() % std::size(scales)],
                     size = scales[random() % std::size(scales)];
        s.build(1, {IndexAttribute{ElementType::Linetype, lineType},
                    RealAttribute{ElementType::LinewidthScaleFactor, width},
                    IndexAttribute{ElementType::MarkerType, markerType},
                    RealAttribute{ElementType::MarkerSizeScaleFactor, size},
                    IndexAttribute{ElementType::Edgetype, edgeType},
                    RealAttribute{ElementType::EdgewidthScaleFactor, width},
                    IndexAttribute{ElementType::EdgeFlag, 1}, line, polymarker3({{0, 0, 0}}),
                    fillArea3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})});
        s.ws->postStructure(1, 0);
        const DrawList& list = s.ws->display();
        REQUIRE(list.items.size() == 3);
        INFO("line type " << lineType << ", marker type " << markerType << ", edge type " << edgeType
                          << ", width " << width << ", size " << size);
        const LineStyle& l = *polylineOf(list.items[0]).style;
        const MarkerStyle& m = *std::get<DrawPolymarker>(list.items[1].primitive).style;
        const EdgeStyle& e = *std::get<ItemRef<DrawFillArea>>(list.items[2].primitive)->edges;
        CHECK(int(l.type) == (lineType >= 1 && lineType <= limits.lineTypes ? lineType : 1));
        CHECK(int(e.type) == (edgeType >= 1 && edgeType <= limits.lineTypes ? edgeType : 1));
        CHECK(int(m.type) == (markerType >= 1 && markerType <= limits.markerTypes ? markerType : 3));
        const double drawnWidth = double(l.width) * limits.nominalLineWidth;
        CHECK(drawnWidth >= limits.minLineWidth * (1 - 1e-6));
        CHECK(drawnWidth <= limits.maxLineWidth * (1 + 1e-6));
        CHECK(double(e.width) == Approx(double(l.width)));
        const double drawnSize = double(m.scale) * limits.nominalMarkerSize;
        CHECK(drawnSize >= limits.minMarkerSize * (1 - 1e-6));
        CHECK(drawnSize <= limits.maxMarkerSize * (1 + 1e-6));
        if (width * limits.nominalLineWidth >= limits.minLineWidth &&
            width * limits.nominalLineWidth <= limits.maxLineWidth)
            CHECK(double(l.width) == Approx(width));
        if (size * limits.nominalMarkerSize >= limits.minMarkerSize &&
            size * limits.nominalMarkerSize <= limits.maxMarkerSize)
            CHECK(double(m.scale) == Approx(size));
        s.ws->unpostStructure(1);
    }
}

TEST_CASE("hatch styles the workstation lacks are drawn as style 1, on both sides", "[traverse]") {
    // ISO 9592: an interior style index not available is drawn as 1; a pattern index is not a
    // hatch style and keeps its value.
    Scene s;
    const PrimitiveLimits& limits = s.ws->description().primitives;
    REQUIRE(limits.hatchStyles == 6);  // what prim.frag and the vector painter draw
    std::mt19937 random(77);
    std::uniform_int_distribution<int> index(-3, 12);
    for (int trial = 0; trial < 40; ++trial) {
        const int front = index(random), back = index(random);
        const int frontStyle = int(trial % 2 ? InteriorStyle::Hatch : InteriorStyle::Pattern);
        s.build(1, {IndexAttribute{ElementType::InteriorStyle, frontStyle},
                    IndexAttribute{ElementType::InteriorStyleIndex, front},
                    IndexAttribute{ElementType::BackInteriorStyle, int(InteriorStyle::Hatch)},
                    IndexAttribute{ElementType::BackInteriorStyleIndex, back},
                    fillArea3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})});
        s.ws->postStructure(1, 0);
        const DrawList& list = s.ws->display();
        REQUIRE(list.items.size() == 1);
        INFO("front style " << frontStyle << " index " << front << ", back index " << back);
        const InteriorStyleSet& in = *std::get<ItemRef<DrawFillArea>>(list.items[0].primitive)->interior;
        const bool hatch = in.style == InteriorStyle::Hatch;
        CHECK(in.styleIndex == (!hatch || (front >= 1 && front <= 6) ? front : 1));
        CHECK(in.back.styleIndex == (back >= 1 && back <= 6 ? back : 1));
        s.ws->unpostStructure(1);
    }
}

TEST_CASE("a negative character height or expansion factor is drawn by its absolute value", "[traverse]") {
    // ISO 9592: the absolute values are used; the text's layout then matches the positive one's.
    Scene s;
    std::mt19937 random(5);
    std::uniform_real_distribution<double> magnitude(0.01, 2.0);
    for (int trial = 0; trial < 20; ++trial) {
        const double height = magnitude(random), expansion = magnitude(random),
                     annoHeight = magnitude(random);
        const double sh = trial % 2 ? -1 : 1, se = trial % 3 ? -1 : 1;
        s.build(1, {RealAttribute{ElementType::CharacterHeight, sh * height},
                    RealAttribute{ElementType::CharacterExpansionFactor, se * expansion},
                    RealAttribute{ElementType::AnnotationTextCharacterHeight, -annoHeight},
                    TextElement{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "Wing", false},
                    AnnotationTextElement{{0, 0, 0}, {0.1, 0.1, 0}, "note", false}});
        s.ws->postStructure(1, 0);
        const DrawList& list = s.ws->display();
        REQUIRE(list.items.size() == 2);
        const TextStyle& text = *primitiveAs<DrawText>(list.items[0].primitive).style;
        const TextStyle& note = *primitiveAs<DrawText>(list.items[1].primitive).style;
        CHECK(text.height == Approx(height));
        CHECK(double(text.expansion) == Approx(expansion));
        CHECK(note.height == Approx(annoHeight));
        s.ws->unpostStructure(1);
    }
}

TEST_CASE("colours: direct RGB and indices through the colour table", "[traverse]") {
    Scene s;
    s.ws->setColourRepresentation(12, {0.25, 0.5, 0.75});
    s.build(1, {polylineColourIndex(12), line,
                ColourAttribute{ElementType::PolylineColour, Colour::fromRgb({0.1, 0.2, 0.3})}, line,
                polylineColourIndex(200), line});
    s.ws->postStructure(1, 0);
    const DrawList& list = s.ws->display();
    CHECK(polylineOf(list.items[0]).style->colour == glm::vec3(0.25f, 0.5f, 0.75f));
    CHECK(polylineOf(list.items[1]).style->colour == glm::vec3(0.1f, 0.2f, 0.3f));
    CHECK(polylineOf(list.items[2]).style->colour == glm::vec3(1.0f));  // undefined index reads as 1
    CHECK(list.background == glm::vec3(0.0f));
}

TEST_CASE("modelling transforms: composition order, global and inheritance", "[traverse]") {
    Scene s;
    glm::dmat4 t = glm::translate(glm::dmat4(1.0), {1, 0, 0});
    glm::dmat4 r = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), {0, 0, 1});
    glm::dmat4 g = glm::scale(glm::dmat4(1.0), {2, 2, 2});
    s.build(2, {localTransformation3(t, Composition::Replace), line});
    s.build(1, {localTransformation3(t, Composition::Replace),
                localTransformation3(r, Composition::Preconcatenate), line,
                localTransformation3(t, Composition::Replace),
                localTransformation3(r, Composition::Postconcatenate), line, globalTransformation3(g),
                executeStructure(2), line});
    s.ws->postStructure(1, 0);
    const DrawList& list = s.ws->display();
    REQUIRE(list.items.size() == 4);
    CHECK(list.items[0].modelTransform().get() == t * r);  // preconcatenate: R applied first
    CHECK(list.items[1].modelTransform().get() == r * t);  // postconcatenate: R applied last
    // the child's global is the parent's composite (G * (R * T)), its local starts as identity
    CHECK(list.items[2].modelTransform().get() == (g * (r * t)) * t);
    CHECK(list.items[3].modelTransform().get() == g * (r * t));  // restored
}

TEST_CASE("preconcatenate applies the new matrix first, as PHIGS programs compose parts", "[traverse]") {
    // REPLACE by a translation, then PRECONCATENATE a scale: a part is scaled in its own
    // coordinates, then placed (PEX and PHIGS implementations: L' = L * T, column vectors).
    Scene s;
    const glm::dmat4 place = glm::translate(glm::dmat4(1.0), {0.5, 0.5, 0});
    const glm::dmat4 grow = glm::scale(glm::dmat4(1.0), {2, 2, 1});
    s.build(1, {localTransformation3(place, Composition::Replace),
                localTransformation3(grow, Composition::Preconcatenate), line,
                localTransformation3(grow, Composition::Replace),
                localTransformation3(place, Composition::Postconcatenate), line});
    s.ws->postStructure(1, 0);
    const DrawList& list = s.ws->display();
    REQUIRE(list.items.size() == 2);
    // (0.1, 0.1) scaled to (0.2, 0.2), then moved to (0.7, 0.7), both ways of writing it.
    for (std::size_t i = 0; i < 2; ++i) {
        const glm::dvec4 corner = list.items[i].modelTransform().get() * glm::dvec4(0.1, 0.1, 0, 1);
        CHECK(glm::length(glm::dvec3(corner) - glm::dvec3(0.7, 0.7, 0)) < 1e-12);
    }
}

TEST_CASE("name sets: invisibility, highlighting and pick filters", "[traverse]") {
    Scene s;
    s.build(2, {removeNamesFromSet({1}), line});
    s.build(1, {addNamesToSet({1, 2}), line, executeStructure(2), line, removeNamesFromSet({2}), line});
    s.ws->postStructure(1, 0);
    s.ws->setHighlightingFilter({{1}, {}});
    s.ws->setInvisibilityFilter({{2}, {1}});  // invisible: has 2 and not 1
    s.ws->setPickFilter(NameSetFilter{{2}, {}});
    const DrawList& list = s.ws->display();
    // child: names {2} -> invisible; parent line after return {1,2}; last line {1}
    REQUIRE(list.items.size() == 3);
    CHECK(list.items[0].highlighted());
    CHECK(list.items[0].pickable());
    CHECK(list.items[1].source.path().back().elementNumber == 4);
    CHECK(list.items[2].highlighted());
    CHECK_FALSE(list.items[2].pickable());  // names {1}: not in the pick filter
    // a pick traversal with its own filters leaves the display alone
    TraversalFilters pickOnly;
    pickOnly.pick = NameSetFilter{{1}, {2}};
    DrawList picked = s.ws->traverse(pickOnly);
    REQUIRE(picked.items.size() == 4);
    CHECK_FALSE(picked.items[0].pickable());
    CHECK(picked.items[3].pickable());
    CHECK_FALSE(picked.items[1].pickable());  // child {2}
}

TEST_CASE("posted networks are drawn in priority order, ties in posting order", "[traverse]") {
    Scene s;
    s.build(1, {pickId(1), line});
    s.build(2, {pickId(2), line});
    s.build(3, {pickId(3), line});
    s.ws->postStructure(1, 0.9);
    s.ws->postStructure(2, 0.1);
    s.ws->postStructure(3, 0.9);
    const DrawList& list = s.ws->display();
    std::vector<int> order;
    for (const auto& item : list.items) order.push_back(item.source.path().back().pickId);
    CHECK(order == std::vector<int>{2, 1, 3});
    CHECK(s.ws->postedStructures() == std::vector<PostedStructure>{{2, 0.1}, {1, 0.9}, {3, 0.9}});
    s.ws->postStructure(1, 0.95);  // reposting changes the priority
    CHECK(s.ws->postedStructures().back() == PostedStructure{1, 0.95});
    CHECK_THROWS_AS(s.ws->postStructure(1, 1.5), Error);
}

TEST_CASE("draw list content for a small network: views, lights, depth cue, primitives", "[traverse]") {
    Scene s;
    ViewRepresentation view;
    view.orientation = glm::translate(glm::dmat4(1.0), {0, 0, -1});
    view.clipMax = {1, 1, 0.5};
    s.ws->setViewRepresentation(2, view);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, 0, -1};
    s.ws->setLightSourceRepresentation(2, sun);
    DepthCue cue;
    cue.enabled = true;
    s.ws->setDepthCueRepresentation(1, cue);
    s.ws->setHlhsrMode(1);
    FillAreaSetWithDataElement data;
    data.contours = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    data.vertexColours = {{Colour::indexed(2), Colour::fromRgb({0, 0, 0.5}), Colour::indexed(3)}};
    s.build(1, {viewIndex(2), LightSourceStateAttribute{{1, 2}, {}},
                IndexAttribute{ElementType::DepthCueIndex, 1}, IndexAttribute{ElementType::InteriorStyle, 1},
                IndexAttribute{ElementType::InteriorShadingMethod, int(ShadingMethod::Colour)},
                fillArea3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}), data,
                TextElement{{1, 2, 3}, {1, 0, 0}, {0, 1, 0}, "Wing", false},
                AnnotationTextElement{{0, 0, 0}, {0.1, 0.1, 0}, "note", false}, viewIndex(7),
                polymarker3({{0, 0, 0}})});
    s.ws->postStructure(1, 0);
    const DrawList& list = s.ws->display();
    REQUIRE(list.items.size() == 5);
    REQUIRE(list.views.size() == 3);
    CHECK(list.views[2].orientation == view.orientation);
    CHECK(list.views[2].clipMax.z == 0.5);
    CHECK(list.items[0].viewIndex() == 2);
    CHECK(list.items[4].viewIndex() == 0);  // undefined view 7 uses view 0
    REQUIRE(list.lightSets.size() == 1);
    CHECK(list.lightSets[0].size() == 2);
    CHECK(list.lightSets[0][1].type == LightType::Directional);
    CHECK(list.items[0].lightSet() == 0);
    REQUIRE(list.depthCues.size() == 1);
    CHECK(list.items[0].depthCue() == 0);
    CHECK(list.hiddenSurfaceRemoval);
    const auto& fill = primitiveAs<DrawFillArea>(list.items[0].primitive);
    CHECK(fill.interior->style == InteriorStyle::Solid);
    const auto& withData = primitiveAs<DrawFillArea>(list.items[1].primitive);
    REQUIRE(withData.vertexColours.size() == 1);
    CHECK(withData.vertexColours[0] == std::vector<glm::vec3>{{1, 0, 0}, {0, 0, 0.5f}, {0, 1, 0}});
    CHECK(primitiveAs<DrawText>(list.items[2].primitive).text == "Wing");
    CHECK(primitiveAs<DrawText>(list.items[3].primitive).annotation);
    CHECK(list.viewportMax.x == s.ws->description().displaySize.x);
}

TEST_CASE("meshes: triangle strip, quadrilateral mesh and cell array", "[traverse]") {
    Scene s;
    s.build(1, {TriangleStripElement{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {}, {}},
                QuadrilateralMeshElement{
                    2, 3, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}}, {}, {}},
                CellArrayElement{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, 2, 1, {2, 3}, false}});
    s.ws->postStructure(1, 0);
    const DrawList& list = s.ws->display();
    REQUIRE(list.items.size() == 3);
    const MeshData& strip = *primitiveAs<DrawMesh>(list.items[0].primitive).mesh;
    CHECK(strip.triangles ==
          std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3});  // alternate winding kept counter-clockwise
    CHECK(primitiveAs<DrawMesh>(list.items[1].primitive).mesh->triangles.size() == 12);
    const MeshData& cells = *primitiveAs<DrawMesh>(list.items[2].primitive).mesh;
    CHECK(cells.triangles.size() == 12);
    CHECK(cells.colours[0] == glm::vec3(1, 0, 0));
    CHECK(cells.colours[4] == glm::vec3(0, 1, 0));
}

TEST_CASE("iso-curves of a trimmed surface stop at its trim loops", "[traverse]") {
    // A flat patch (x = u, y = v) with a round hole of random centre and radius: no step of an
    // iso-curve crosses the hole, and the curves still run where the surface is kept.
    Scene s;
    std::mt19937 random(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 8; ++trial) {
        const glm::dvec2 centre(0.3 + 0.4 * unit(random), 0.3 + 0.4 * unit(random));
        const double radius = 0.1 + 0.15 * unit(random);
        NurbsSurfaceElement trimmed{bilinearPatch(), {}};
        std::vector<glm::dvec3> circle;
        for (int k = 0; k <= 48; ++k) {
            const double a = 6.283185307179586 * k / 48.0;
            circle.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a), 0.0});
        }
        std::vector<double> knots{0.0, 0.0};
        for (int k = 1; k < 48; ++k) knots.push_back(k);
        knots.insert(knots.end(), {48.0, 48.0});
        const std::vector<glm::dvec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}};
        trimmed.trimLoops = {{geom::Curve(1, {0, 0, 1, 2, 3, 4, 4}, square)},
                             {geom::Curve(1, knots, circle)}};
        SurfaceCharacteristicsAttribute iso;
        iso.style = 3;
        iso.curvesU = iso.curvesV = 9;
        s.build(1,
                {ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, 24, 24}, iso, trimmed});
        s.ws->postStructure(1, 0);
        const DrawList& list = s.ws->display();
        REQUIRE(list.items.size() == 1);
        const MeshData& mesh = *primitiveAs<DrawMesh>(list.items[0].primitive).mesh;
        INFO("trial " << trial << ": hole at " << centre.x << ", " << centre.y << " radius " << radius);
        std::size_t steps = 0, crossing = 0;
        for (const auto& line : mesh.isoLines)
            for (std::size_t k = 0; k + 1 < line.size(); ++k) {
                const glm::dvec3 middle =
                    (glm::dvec3(mesh.positions[line[k]]) + glm::dvec3(mesh.positions[line[k + 1]])) / 2.0;
                ++steps;
                // A step that crosses the hole passes well inside it (the polygon stands in for
                // the circle within a cell).
                crossing += glm::length(glm::dvec2(middle) - centre) < radius - 0.05;
            }
        CHECK(steps > 100);
        CHECK(crossing == 0);
        s.ws->unpostStructure(1);
    }
}

TEST_CASE("NURBS surfaces and curves: tessellation, trimming, cached per element and version", "[traverse]") {
    Scene s;
    NurbsSurfaceElement patch{bilinearPatch(), {}};
    NurbsSurfaceElement trimmed = patch;
    // keep the lower-left half of the domain (a triangle loop in (u, v))
    trimmed.trimLoops = {{geom::Curve(1, {0, 0, 1, 2, 3, 3}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}})}};
    NurbsCurveElement curve{geom::Curve(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}), 0, 0};
    s.build(2, {patch});
    s.build(3, {ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, 4, 4}, trimmed, curve});
    s.build(1, {executeStructure(2), executeStructure(3)});
    s.ws->postStructure(1, 0);
    DrawList first = s.ws->display();
    REQUIRE(first.items.size() == 3);
    const auto& mesh = primitiveAs<DrawMesh>(first.items[0].primitive);
    REQUIRE(mesh.surface);
    CHECK(mesh.mesh->positions.size() == 81);  // workstation dependent: 8 segments per span
    CHECK(mesh.mesh->triangles.size() == 8 * 8 * 2 * 3);
    CHECK(mesh.mesh->normals[0] == glm::vec3(0, 0, 1));  // Su x Sv for this patch
    const auto& cut = primitiveAs<DrawMesh>(first.items[1].primitive);
    CHECK(cut.mesh->triangles.size() ==
          4 * 3 * 3);  // of 32 triangles of a 4 x 4 grid, the 12 below the diagonal
    // The loop goes with the mesh, for the pick: what it keeps, exactly.
    CHECK(mesh.mesh->trimLoops.empty());
    REQUIRE(cut.mesh->trimLoops.size() == 1);
    CHECK(cut.mesh->keeps({0.45, 0.5}));
    CHECK_FALSE(cut.mesh->keeps({0.55, 0.5}));
    const auto& drawnCurve = primitiveAs<DrawCurve>(first.items[2].primitive);
    CHECK(drawnCurve.points.size() == 9);
    CHECK(drawnCurve.points[4] == glm::dvec3(1, 0.5, 0));

    auto& counters = s.ws->traverser().cache().counters();
    CHECK(counters.surfacesTessellated == 2);
    CHECK(counters.curvesTessellated == 1);
    // an edit of structure 3 re-tessellates only what it touched
    s.store->openStructure(3);
    s.store->setElementPointer(3);
    s.store->setEditMode(EditMode::Replace);
    s.store->insert(curve);
    s.store->closeStructure();
    DrawList second = s.ws->display();
    CHECK(counters.surfacesTessellated == 2);
    CHECK(counters.curvesTessellated == 2);
    CHECK(primitiveAs<DrawMesh>(second.items[0].primitive).mesh == mesh.mesh);  // the same pointer
    CHECK(primitiveAs<DrawMesh>(second.items[1].primitive).mesh == cut.mesh);
    CHECK(second.items[1].source.structureVersion() != first.items[1].source.structureVersion());
    CHECK(second.generation != first.generation);
    // changing the approximation criteria re-tessellates that surface
    s.store->openStructure(3);
    s.store->setElementPointer(1);
    s.store->insert(ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, 2, 2});
    s.store->closeStructure();
    DrawList third = s.ws->display();
    CHECK(counters.surfacesTessellated == 3);
    CHECK(primitiveAs<DrawMesh>(third.items[1].primitive).mesh->triangles.size() == 2 * 3);
}

TEST_CASE("incremental traversal reuses unchanged subtrees and equals a full traversal", "[traverse]") {
    Scene s;
    Light ambient;
    s.ws->setLightSourceRepresentation(3, ambient);
    s.build(10, {line, pickId(4), polymarker3({{0, 0, 0}})});
    s.build(11, {LightSourceStateAttribute{{3}, {}}, line, executeStructure(10)});
    s.build(1, {addNamesToSet({1}), executeStructure(11),
                localTransformation3(glm::dmat4(2.0), Composition::Replace), executeStructure(11),
                executeStructure(10)});
    s.ws->postStructure(1, 0);
    s.ws->setHighlightingFilter({{1}, {}});
    auto summary = [](const DrawList& list) {
        std::vector<std::tuple<std::vector<DrawPathLevel>, glm::dmat4, bool, int, std::size_t>> out;
        for (const auto& item : list.items)
            out.emplace_back(item.source.path(), item.modelTransform().get(), item.highlighted(),
                             item.lightSet(), item.primitive.index());
        return out;
    };
    Traverser& traverser = s.ws->traverser();
    DrawList first = s.ws->display();
    CHECK(traverser.elementsReused() == 0);
    s.ws->redrawAllStructures();
    // the second traversal walks only structure 1; the three executes are reused
    CHECK(traverser.elementsTraversed() == 5);
    CHECK(traverser.elementsReused() == 6 + 6 + 3);
    CHECK(summary(s.ws->display()) == summary(first));
    // edit the shared leaf: its subtrees are walked again, nothing else
    s.store->openStructure(10);
    s.store->insert(line);
    s.store->closeStructure();
    DrawList edited = s.ws->display();
    CHECK(edited.items.size() == first.items.size() + 3);
    traverser.setIncremental(false);
    s.ws->redrawAllStructures();
    CHECK(summary(s.ws->display()) == summary(edited));
    CHECK(traverser.elementsReused() == 0);
}

TEST_CASE("chordal deviation criteria tessellate adaptively through geom, within the tolerance",
          "[traverse]") {
    Scene s;
    // a quarter cylinder of radius 1 (rational, exact): the mesh must stay within 1e-3 of it
    const double w = std::sqrt(0.5);
    geom::Surface cylinder(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, 3, 2,
                           {{1, 0, 0}, {1, 0, 1}, {1, 1, 0}, {1, 1, 1}, {0, 1, 0}, {0, 1, 1}},
                           {1, 1, w, w, 1, 1});
    geom::Curve arc(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, w, 1});
    s.build(1, {ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 6, 1e-3, 1e-3},
                ApproximationAttribute{ElementType::CurveApproximationCriteria, 6, 1e-3, 0},
                NurbsSurfaceElement{cylinder, {}}, NurbsCurveElement{arc, 0, 0}});
    s.ws->postStructure(1, 0);
    const DrawList& list = s.ws->display();
    REQUIRE(list.items.size() == 2);
    const MeshData& mesh = *primitiveAs<DrawMesh>(list.items[0].primitive).mesh;
    REQUIRE(mesh.triangles.size() >= 3);
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        glm::dvec3 centre = (glm::dvec3(mesh.positions[mesh.triangles[t]]) +
                             glm::dvec3(mesh.positions[mesh.triangles[t + 1]]) +
                             glm::dvec3(mesh.positions[mesh.triangles[t + 2]])) /
                            3.0;
        CHECK(std::abs(std::hypot(centre.x, centre.y) - 1.0) < 1.5e-3);
    }
    const auto& points = primitiveAs<DrawCurve>(list.items[1].primitive).points;
    REQUIRE(points.size() >= 3);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        glm::dvec3 mid = (points[i] + points[i + 1]) / 2.0;
        CHECK(std::abs(std::hypot(mid.x, mid.y) - 1.0) < 1.5e-3);
    }
}

TEST_CASE("model clipping volume: world half spaces, indicator, intersect, restore", "[traverse]") {
    Scene s;
    glm::dmat4 shift = glm::translate(glm::dmat4(1.0), {0, 0, 5});
    s.build(2, {line, ModelClipElement{2, {{{0, 0, 0}, {1, 0, 0}}}, false}, line, RestoreModelClipElement{},
                line});
    s.build(1, {localTransformation3(shift, Composition::Replace),
                ModelClipElement{1, {{{0, 0, 1}, {0, 0, -1}}}, false}, line,
                IndexAttribute{ElementType::ModelClippingIndicator, 1}, line, executeStructure(2)});
    s.ws->postStructure(1, 0);
    const DrawList& list = s.ws->display();
    REQUIRE(list.items.size() == 5);
    CHECK(list.items[0].modelClipPlanes().empty());  // indicator off
    // z <= 1 in modelling coordinates, shifted by 5: keep z <= 6 in the world
    CHECK(list.items[1].modelClipPlanes() == std::vector<glm::dvec4>{{0, 0, -1, 6}});
    CHECK(list.items[2].modelClipPlanes() == std::vector<glm::dvec4>{{0, 0, -1, 6}});  // inherited
    CHECK(list.items[3].modelClipPlanes().size() == 2);  // intersected in the child
    CHECK(list.items[3].modelClipPlanes()[1] == glm::dvec4(1, 0, 0, 0));
    CHECK(list.items[4].modelClipPlanes() ==
          std::vector<glm::dvec4>{{0, 0, -1, 6}});  // restored to the inherited one
}

TEST_CASE("a network nested deeper than the limit gives an error, not a crash", "[traverse][errors]") {
    Scene s;
    const int depth = static_cast<int>(kMaxNetworkDepth) + 5;
    for (int id = depth; id >= 1; --id) s.build(id, {executeStructure(id + 1)});
    s.ws->postStructure(1, 0);
    try {
        s.ws->display();
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.number() == errors::NetworkTooDeep);
    }
    CHECK_THROWS_AS(s.store->pathsToDescendants(1, StructurePathOrder::TopFirst, 0), Error);
    CHECK(s.store->pathsToAncestors(depth, StructurePathOrder::TopFirst, 0).front().size() ==
          std::size_t(depth));
}

TEST_CASE("an edit replaces only its structure's segments of the draw list, the others are shared",
          "[traverse]") {
    Scene s;
    for (int leaf = 2; leaf <= 6; ++leaf)
        s.build(leaf, {polylineColourIndex(leaf), line, line, pickId(leaf), polymarker3({{0, 0, leaf}})});
    s.build(1, {executeStructure(2), executeStructure(3), line, executeStructure(4), executeStructure(5),
                executeStructure(6)});
    s.ws->postStructure(1, 0);
    DrawList before = s.ws->display();
    REQUIRE(before.items.size() == 5 * 3 + 1);
    s.store->openStructure(4);
    s.store->insert(line);
    s.store->closeStructure();
    const DrawList& after = s.ws->display();
    REQUIRE(after.items.size() == before.items.size() + 1);
    CHECK(s.ws->traverser().elementsTraversed() == 6 + 6);  // the root and the edited leaf
    auto owner = [](const DrawItems::SegmentPtr& segment) {
        return segment->items.front().source.path().back().structureId;
    };
    int shared = 0, fresh = 0;
    for (const auto& segment : after.items.segments()) {
        bool reused = std::find(before.items.segments().begin(), before.items.segments().end(), segment) !=
                      before.items.segments().end();
        if (owner(segment) == 4 || owner(segment) == 1) {
            CHECK(!reused);
            ++fresh;
        } else {
            CHECK(reused);
            ++shared;
        }
    }
    CHECK(shared == 4);
    CHECK(fresh == 2);
    // the draw list still reads like a vector, and writing copies a shared segment first
    DrawList copy = after;
    copy.items[0].context.edit().highlighted = true;
    CHECK(!after.items[0].highlighted());
    CHECK(std::distance(after.items.begin(), after.items.end()) == static_cast<long>(after.items.size()));
}

}  // namespace test_traverse
