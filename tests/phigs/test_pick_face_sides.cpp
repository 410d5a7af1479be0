// The pick of a fill area takes the side the view shows: with face distinguishing on a back-facing
// area is hit by its back interior style (SOLID, HATCH, PATTERN inside; HOLLOW on its outline only;
// EMPTY not at all), a culled side is not hit, and visible edges are hit whichever side shows.
// Seeded random polygons in random planes, wound either way, with or without a facet normal,
// under a random rotation about the view axis, mirrored or not.
#include "PickScenes.h"

#include "phigs/pick/Picker.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/view/ViewMatrices.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <random>

namespace test_pick_face_sides {

using namespace phigs;
using phigs::test::item;
using phigs::test::unitList;

namespace {

InteriorStyle randomStyle(std::mt19937& rng) {
    return static_cast<InteriorStyle>(std::uniform_int_distribution<int>(0, 4)(rng));
}

bool filled(InteriorStyle s) {
    return s != InteriorStyle::Hollow && s != InteriorStyle::Empty;
}

}  // namespace

TEST_CASE("pick face sides: each side of a fill area is hit by its own style", "[pick]") {
    std::mt19937 rng(0x5eed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const Picker picker;
    int backHits = 0, backOutlines = 0, frontMisses = 0;
    for (int round = 0; round < 400; ++round) {
        // A regular polygon about (0.5, 0.5, 0.5) in a plane seen at least a little face on.
        glm::dvec3 n;
        do n = glm::dvec3(unit(rng), unit(rng), unit(rng));
        while (glm::length(n) < 0.2 || std::abs(n.z) < 0.4 * glm::length(n));
        n = glm::normalize(n);
        const glm::dvec3 u =
            glm::normalize(glm::cross(std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), n));
        const glm::dvec3 v = glm::cross(n, u);  // u, v, n right-handed: counter-clockwise about n
        const int corners = std::uniform_int_distribution<int>(3, 7)(rng);
        const bool reversed = rng() % 2;  // wound clockwise about n
        DrawFillArea f;
        f.contours.emplace_back();
        for (int k = 0; k < corners; ++k) {
            const double a = (reversed ? -1.0 : 1.0) * 6.283185307179586 * k / corners;
            f.contours[0].push_back(glm::dvec3(0.5) + 0.3 * (std::cos(a) * u + std::sin(a) * v));
        }
        // The front's normal in modelling coordinates: the winding's, or a given facet normal's.
        glm::dvec3 front = reversed ? -n : n;
        const int given = std::uniform_int_distribution<int>(0, 2)(rng);
        if (given) f.facetNormal = front = given == 1 ? n : -n;
        InteriorStyleSet& in = f.interior.edit();
        in.style = randomStyle(rng);
        in.back.style = randomStyle(rng);
        in.distinguishBackFaces = rng() % 2;
        in.cull = static_cast<CullMode>(std::uniform_int_distribution<int>(0, 2)(rng));
        f.edges.edit().visible = rng() % 4 == 0;
        DrawItem i = item(f, {{1, 1, 0}});
        // A rotation about the view's axis keeps the side shown; a mirror of x turns it over.
        const bool mirror = rng() % 2;
        glm::dmat4 m =
            glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5)) *
            glm::rotate(glm::dmat4(1.0), 6.283185307179586 * (unit(rng) + 1) / 2, glm::dvec3(0, 0, 1)) *
            glm::translate(glm::dmat4(1.0), glm::dvec3(-0.5, -0.5, -0.5));
        if (mirror)
            m = m * glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 0, 0)), glm::dvec3(-1, 1, 1));
        i.context.edit().modelTransform = m;
        DrawList list = unitList();
        list.items.push_back(i);

        // The view looks down -z (world = NPC): the front shows when its world normal has z > 0. A
        // given normal keeps its z under both transforms; the winding's turns over in the mirror.
        const bool back = given ? front.z < 0 : (front.z > 0) == mirror;
        const bool culled = in.cull == (back ? CullMode::BackFaces : CullMode::FrontFaces);
        const InteriorStyle shown = back && in.distinguishBackFaces ? in.back.style : in.style;
        const bool inside = !culled && filled(shown);
        const bool outline = inside || (!culled && shown == InteriorStyle::Hollow) || f.edges->visible;
        const glm::dvec3 edgeMiddle =
            glm::dvec3(m * glm::dvec4((f.contours[0][0] + f.contours[0][1]) / 2.0, 1.0));
        INFO("round " << round << ": back " << back << ", styles " << int(in.style) << " / "
                      << int(in.back.style) << ", distinguishing " << in.distinguishBackFaces << ", cull "
                      << int(in.cull) << ", edges " << f.edges->visible);
        CHECK(bool(picker.nearest(list, {0.5, 0.5}, 0.001)) == inside);
        CHECK(bool(picker.nearest(list, glm::dvec2(edgeMiddle), 0.001)) == outline);
        backHits += back && inside && shown != in.style;
        backOutlines += back && !inside && outline && shown == InteriorStyle::Hollow;
        frontMisses += !back && !inside && filled(in.back.style);
    }
    // The sequence reaches the cases the front-only rule got wrong.
    CHECK(backHits > 10);
    CHECK(backOutlines > 10);
    CHECK(frontMisses > 10);
}

TEST_CASE("pick face sides: the side a view shows is the side the projection winds counter-clockwise",
          "[pick]") {
    // render::sideShown, which the renderers and the pick use for outlines, against the winding in
    // NPC of a triangle counter-clockwise about the plane's normal, under random parallel and
    // perspective views.
    std::mt19937 rng(0x51de);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    auto randomUnit = [&] {
        glm::dvec3 v;
        do v = glm::dvec3(unit(rng), unit(rng), unit(rng));
        while (glm::length(v) < 0.2 || glm::length(v) > 1.0);
        return glm::normalize(v);
    };
    int checked = 0, fronts = 0;
    for (int round = 0; round < 2000; ++round) {
        const glm::dvec3 normal = randomUnit(), up = randomUnit();
        if (glm::length(glm::cross(normal, up)) < 0.2) continue;
        ViewMapping mapping;
        mapping.windowMin = glm::dvec2(-1.0), mapping.windowMax = glm::dvec2(1.0);
        mapping.backPlaneDistance = -1.0, mapping.frontPlaneDistance = 1.0;
        if (round % 2) {
            mapping.projection = ProjectionType::Perspective;
            mapping.projectionReferencePoint = {unit(rng) * 0.5, unit(rng) * 0.5, 3.0 + unit(rng)};
        }
        const glm::dmat4 worldToNpc =
            evaluateViewMappingMatrix(mapping) * evaluateViewOrientationMatrix(glm::dvec3(0.0), normal, up);
        const glm::dvec3 n = randomUnit(), p(unit(rng) * 0.5, unit(rng) * 0.5, unit(rng) * 0.5);
        const glm::dvec3 u =
            glm::normalize(glm::cross(std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), n));
        const glm::dvec3 v = glm::cross(n, u);
        glm::dvec2 q[3];
        bool valid = true;
        const glm::dvec3 corners[3] = {p, p + 0.1 * u, p + 0.1 * v};
        for (int k = 0; k < 3; ++k) {
            const glm::dvec4 h = worldToNpc * glm::dvec4(corners[k], 1.0);
            valid = valid && h.w > 0.0;
            q[k] = glm::dvec2(h) / h.w;
        }
        const double winding = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
        if (!valid || std::abs(winding) < 1e-6) continue;
        ++checked;
        fronts += winding > 0;
        CHECK(render::sideShown(glm::dvec4(n, -glm::dot(n, p)), worldToNpc) == (winding > 0 ? 1 : -1));
    }
    CHECK(checked > 1500);
    CHECK(fronts > checked / 4);
    CHECK(fronts < 3 * checked / 4);
}

TEST_CASE("pick face sides: a surface is hit exactly where the side it shows is detectable", "[pick]") {
    // The cylinder's normal Su x Sv points inward: its near wall shows the back, its far wall the
    // front. The line through the aperture passes a side that is HOLLOW or culled; an EMPTY side
    // of a surface stays detectable (a wireframe picks inside its patches).
    const double r = 0.3;
    const InteriorStyle styles[] = {InteriorStyle::Hollow, InteriorStyle::Solid, InteriorStyle::Empty,
                                    InteriorStyle::Hatch};
    int nearHits = 0, farHits = 0;
    for (const InteriorStyle front : styles)
        for (const InteriorStyle back : styles)
            for (const CullMode cull : {CullMode::None, CullMode::BackFaces, CullMode::FrontFaces}) {
                DrawList list = unitList();
                DrawItem i = test::surfaceItem(test::cylinder(r), {{1, 2, 3}});
                i.context.edit().modelTransform = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5));
                InteriorStyleSet& in = editPrimitive<DrawMesh>(i.primitive).interior.edit();
                in.style = front;
                in.back.style = back;
                in.distinguishBackFaces = true;
                in.cull = cull;
                list.items.push_back(i);
                const Picker picker;
                const auto hit = picker.nearest(list, {0.55, 0.4}, 0.001);
                const bool nearFilled = back != InteriorStyle::Hollow && cull != CullMode::BackFaces;
                const bool farFilled = front != InteriorStyle::Hollow && cull != CullMode::FrontFaces;
                CHECK(hit.has_value() == (nearFilled || farFilled));
                if (!hit) continue;
                REQUIRE(hit->surface);  // exact, (u, v) and all
                const double z = std::sqrt(r * r - 0.05 * 0.05);
                CHECK(hit->surface->point.z == Approx(nearFilled ? z : -z).margin(1e-9));
                CHECK(glm::dot(hit->surface->normal, glm::dvec3(0, 0, 1)) * (nearFilled ? -1 : 1) > 0.0);
                nearHits += nearFilled, farHits += !nearFilled;
            }
    CHECK(nearHits > 0);
    CHECK(farHits > 0);
}

TEST_CASE("pick face sides: an edge-on mesh triangle shows its front", "[pick]") {
    // Triangles in planes through the view axis: each projects to a segment through (0.5, 0.5),
    // hit on its edges when its front is outlined or filled, whichever way it is wound. Their
    // directions keep the projected winding exactly zero (x or y alike, or x = y).
    std::mt19937 rng(0xed9e);
    std::uniform_real_distribution<double> apex(0.2, 0.45);
    const glm::dvec3 directions[] = {{1, 0, 0},  {0, 1, 0},     {-1, 0, 0},
                                     {0, -1, 0}, {0.7, 0.7, 0}, {-0.7, -0.7, 0}};
    const InteriorStyle styles[] = {InteriorStyle::Hollow, InteriorStyle::Solid, InteriorStyle::Empty};
    int hits = 0;
    for (int round = 0; round < 60; ++round) {
        const double r = apex(rng);
        const glm::dvec3 d = directions[round % 6];
        auto mesh = std::make_shared<MeshData>();
        for (const glm::dvec3& p : {glm::dvec3(0.5, 0.5, 0.2) - r * d, glm::dvec3(0.5, 0.5, 0.2) + r * d,
                                    glm::dvec3(0.5, 0.5, 0.8) + 0.3 * r * d})
            mesh->positions.push_back(glm::vec3(p));
        mesh->triangles =
            round / 6 % 2 ? std::vector<std::uint32_t>{0, 1, 2} : std::vector<std::uint32_t>{0, 2, 1};
        for (const InteriorStyle front : styles)
            for (const InteriorStyle back : styles) {
                DrawList list = unitList();
                DrawMesh m;
                m.mesh = mesh;
                InteriorStyleSet& in = m.interior.edit();
                in.style = front;
                in.back.style = back;
                in.distinguishBackFaces = true;
                in.backColour = glm::vec3(0.2f);  // HOLLOW sides of their own colours: outlined per side
                list.items.push_back(item(m, {{1, 2, 3}}));
                const Picker picker;
                const bool hit =
                    picker.nearest(list, glm::dvec2(0.5, 0.5) + 0.05 * glm::dvec2(d), 0.002).has_value();
                CHECK(hit == (front != InteriorStyle::Empty));
                hits += hit;
            }
    }
    CHECK(hits == 60 * 6);
}

}  // namespace test_pick_face_sides
