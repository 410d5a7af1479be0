#include "PickScenes.h"

#include "geom/Evaluate.h"
#include "phigs/pick/Picker.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

namespace test_pick_surface {

using namespace phigs;
using phigs::test::cylinder;
using phigs::test::item;
using phigs::test::surfaceItem;
using phigs::test::unitList;

namespace {

/// Clamped uniform knots of a degree-p curve with n control points on [0, 1].
std::vector<double> uniformKnots(int p, std::size_t n) {
    std::vector<double> k;
    const std::size_t spans = n - static_cast<std::size_t>(p);
    for (int i = 0; i <= p; ++i) k.push_back(0.0);
    for (std::size_t i = 1; i < spans; ++i) k.push_back(static_cast<double>(i) / static_cast<double>(spans));
    for (int i = 0; i <= p; ++i) k.push_back(1.0);
    return k;
}

/// Greville abscissae: control points there make the coordinate equal the parameter.
std::vector<double> greville(const std::vector<double>& knots, int p, std::size_t n) {
    std::vector<double> g;
    for (std::size_t i = 0; i < n; ++i) {
        double s = 0;
        for (int k = 1; k <= p; ++k) s += knots[i + static_cast<std::size_t>(k)];
        g.push_back(s / p);
    }
    return g;
}

/// A bicubic height field over [0,1]^2 with x(u) = u and y(v) = v exactly (3 x 4 Bézier pieces),
/// heights between 0.2 and 0.8: a vertical line at (X, Y) meets it only at (u, v) = (X, Y).
std::shared_ptr<const geom::Surface> heightField() {
    const std::size_t nu = 6, nv = 7;
    const auto ku = uniformKnots(3, nu), kv = uniformKnots(3, nv);
    const auto gu = greville(ku, 3, nu), gv = greville(kv, 3, nv);
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j)
            points.emplace_back(
                gu[i], gv[j],
                0.5 + 0.3 * std::sin(3.0 * static_cast<double>(i) + 2.0 * static_cast<double>(j)));
    return std::make_shared<const geom::Surface>(3, 3, ku, kv, nu, nv, points);
}

}  // namespace

TEST_CASE("pick surface: 10,000 random picks of a bicubic surface agree with the exact answer", "[pick]") {
    DrawList list = unitList();
    const auto surface = heightField();
    list.items.push_back(surfaceItem(surface, {{4, 6, 2}}));
    const Picker picker;
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> coordinate(0.001, 0.999);
    int checked = 0;
    for (int i = 0; i < 10000; ++i) {
        const glm::dvec2 at(coordinate(random), coordinate(random));
        const auto hits = picker.hits(list, at, 0.001);
        REQUIRE(hits.size() == 1);
        REQUIRE(hits[0].surface);
        const SurfacePickDetail& d = *hits[0].surface;
        // The exact answer: (u, v) = (X, Y), the point S(X, Y).
        const glm::dvec3 exact = geom::evaluate(*surface, at.x, at.y);
        REQUIRE(std::abs(d.uv.x - at.x) < 1e-9);
        REQUIRE(std::abs(d.uv.y - at.y) < 1e-9);
        REQUIRE(glm::length(d.point - exact) < 1e-9);
        REQUIRE(glm::length(d.point - geom::evaluate(*surface, d.uv.x, d.uv.y)) < 1e-9);
        REQUIRE(hits[0].depth == Approx(exact.z).margin(1e-9));
        const std::size_t spanU = static_cast<std::size_t>(std::min(2.0, std::floor(at.x * 3)));
        const std::size_t spanV = static_cast<std::size_t>(std::min(3.0, std::floor(at.y * 4)));
        // Points within 1e-9 of a knot line may be given to either neighbour.
        const bool nearKnot = std::abs(at.x * 3 - std::round(at.x * 3)) < 1e-8 ||
                              std::abs(at.y * 4 - std::round(at.y * 4)) < 1e-8;
        if (!nearKnot) REQUIRE(d.bezierPiece == spanU * 4 + spanV);
        // The normal is a unit vector perpendicular to both tangents, facing +z here.
        const auto der = geom::derivatives(*surface, d.uv.x, d.uv.y, 1);
        REQUIRE(glm::length(d.normal) == Approx(1.0).epsilon(1e-12));
        REQUIRE(std::abs(glm::dot(d.normal, glm::normalize(der.at(1, 0)))) < 1e-9);
        REQUIRE(std::abs(glm::dot(d.normal, glm::normalize(der.at(0, 1)))) < 1e-9);
        ++checked;
    }
    CHECK(checked == 10000);
    // Outside the surface's extent nothing is hit.
    list.windowMax = glm::dvec3(2.0);
    CHECK(picker.hits(list, {1.5, 0.5}, 0.001).empty());
}

TEST_CASE("pick surface: a hole trimmed away picks what lies behind it", "[pick]") {
    // The height field trimmed to a square with a round hole (even-odd loops in (u, v)), a
    // fill area behind it: picks in the hole reach the fill area, picks elsewhere the surface.
    DrawList list = unitList();
    const auto surface = heightField();
    DrawFillArea behind;
    behind.contours = {{{0, 0, 0.01}, {1, 0, 0.01}, {1, 1, 0.01}, {0, 1, 0.01}}};
    behind.interior.edit().style = InteriorStyle::Solid;
    list.items.push_back(item(behind, {{1, 1, 0}}));
    DrawItem trimmed = surfaceItem(surface, {{2, 1, 0}});
    auto mesh = std::make_shared<MeshData>();
    mesh->trimLoops = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
    for (int k = 0; k < 64; ++k) {
        const double a = 6.283185307179586 * k / 64.0;
        mesh->trimLoops[1].push_back({0.5 + 0.2 * std::cos(a), 0.5 + 0.2 * std::sin(a)});
    }
    editPrimitive<DrawMesh>(trimmed.primitive).mesh = mesh;
    list.items.push_back(trimmed);
    const Picker picker;
    std::mt19937 random(77);
    std::uniform_real_distribution<double> coordinate(0.02, 0.98);
    int inHole = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::dvec2 at(coordinate(random), coordinate(random));
        const double r = glm::length(at - glm::dvec2(0.5));
        if (std::abs(r - 0.2) < 0.01) continue;  // the hole's polygon and circle part there
        const PickMeasure hit = picker.pick(list, at, {0.0005});
        REQUIRE(hit.status == InputStatus::Ok);
        INFO("pick at (" << at.x << ", " << at.y << ")");
        CHECK(hit.path.front().structureId == (r < 0.2 ? 1 : 2));
        inHole += r < 0.2;
    }
    CHECK(inHole > 20);
}

TEST_CASE("pick surface: a rational cylinder is hit on its near side, exactly", "[pick]") {
    DrawList list = unitList();
    const double r = 0.3;
    DrawItem i = surfaceItem(cylinder(r), {{1, 2, 3}});
    i.context.edit().modelTransform = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5));
    list.items.push_back(i);
    const Picker picker;
    for (double x : {0.3, 0.45, 0.5, 0.62, 0.79}) {
        const auto hit = picker.nearest(list, {x, 0.4}, 0.001);
        REQUIRE(hit);
        REQUIRE(hit->surface);
        const glm::dvec3 p = hit->surface->point;  // modelling coordinates
        const double dx = x - 0.5;
        CHECK(p.x == Approx(dx).margin(1e-9));
        CHECK(p.y == Approx(-0.1).margin(1e-9));
        CHECK(p.z == Approx(std::sqrt(r * r - dx * dx)).margin(1e-9));  // the near (front) side
        CHECK(hit->depth == Approx(0.5 + p.z).margin(1e-9));
        CHECK(hit->surface->bezierPiece == (dx > 0 ? 0u : 1u));
        // The normal is radial.
        CHECK(std::abs(glm::dot(hit->surface->normal, glm::normalize(glm::dvec3(p.x, 0, p.z)))) ==
              Approx(1.0).epsilon(1e-9));
    }
    CHECK_FALSE(picker.nearest(list, {0.85, 0.4}, 0.001));
}

TEST_CASE("pick surface: rotated and clipped surfaces, nearest of several, path kept", "[pick]") {
    DrawList list = unitList();
    const double r = 0.3;
    // The big cylinder tilted about x, so the line crosses it obliquely.
    DrawItem tilted = surfaceItem(cylinder(r), {{1, 1, 1}});
    tilted.context.edit().modelTransform = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.4)) *
                                           glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(1, 0, 0));
    list.items.push_back(tilted);
    DrawItem front = surfaceItem(cylinder(0.1), {{2, 5, 9}});
    front.context.edit().modelTransform = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.75));
    list.items.push_back(front);
    const Picker picker;

    const auto hits = picker.hits(list, {0.52, 0.5}, 0.001);
    REQUIRE(hits.size() == 2);
    CHECK(hits[0].item == 1);
    CHECK(hits[1].item == 0);
    for (const auto& h : hits) {
        const auto& item = list.items[h.item];
        const auto& surface = *primitiveAs<DrawMesh>(item.primitive).surface;
        const glm::dvec3 p = h.surface->point;
        CHECK(glm::length(p - geom::evaluate(surface, h.surface->uv.x, h.surface->uv.y)) < 1e-9);
        const glm::dvec3 world = glm::dvec3(item.modelTransform().get() * glm::dvec4(p, 1.0));
        CHECK(world.x == Approx(0.52).margin(1e-9));
        CHECK(world.y == Approx(0.5).margin(1e-9));
        CHECK(std::hypot(p.x, p.z) == Approx(h.item == 0 ? r : 0.1).margin(1e-9));
    }
    CHECK(picker.pick(list, {0.52, 0.5}, {0.001}).path == std::vector<PickPathItem>{{2, 5, 9}});

    // Clip the front cylinder's near side away (z = 0.75 + 0.098): its back side
    // (z = 0.75 - 0.098) is still hit, behind the big cylinder's near side (about 0.71).
    list.views[0].clipMax.z = 0.8;
    const auto clipped = picker.hits(list, {0.52, 0.5}, 0.001);
    REQUIRE(clipped.size() == 2);
    CHECK(clipped[0].item == 0);
    CHECK(clipped[0].depth > 0.7);
    CHECK(clipped[1].item == 1);
    CHECK(clipped[1].depth == Approx(0.75 - std::sqrt(0.01 - 0.02 * 0.02)).margin(1e-9));
    CHECK(clipped[1].surface->point.z < 0);
    CHECK(picker.pick(list, {0.52, 0.5}, {0.001}).path == std::vector<PickPathItem>{{1, 1, 1}});
}

TEST_CASE("pick surface: a surface with a mesh falls back to the mesh at its silhouette", "[pick]") {
    DrawList list = unitList();
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {{0.2f, 0.2f, 0.5f}, {0.8f, 0.2f, 0.5f}, {0.8f, 0.8f, 0.5f}, {0.2f, 0.8f, 0.5f}};
    mesh->triangles = {0, 1, 2, 0, 2, 3};
    DrawMesh m;
    m.mesh = mesh;
    m.interior.edit().style = InteriorStyle::Solid;
    // An exact plane z = 0.5 over [0.2, 0.8]^2, bilinear.
    m.surface = std::make_shared<const geom::Surface>(
        1, 1, std::vector<double>{0, 0, 1, 1}, std::vector<double>{0, 0, 1, 1}, 2, 2,
        std::vector<glm::dvec3>{{0.2, 0.2, 0.5}, {0.2, 0.8, 0.5}, {0.8, 0.2, 0.5}, {0.8, 0.8, 0.5}});
    list.items.push_back(item(m, {{1, 1, 0}}));
    const Picker picker;
    auto hit = picker.nearest(list, {0.5, 0.5}, 0.01);
    REQUIRE(hit);
    REQUIRE(hit->surface);
    CHECK(hit->surface->uv.x == Approx(0.5).margin(1e-9));
    // Just outside: the exact line misses, the aperture still touches the triangles.
    hit = picker.nearest(list, {0.805, 0.5}, 0.01);
    REQUIRE(hit);
    CHECK_FALSE(hit->surface);
    CHECK_FALSE(picker.nearest(list, {0.9, 0.5}, 0.01));

    // An exact hit anywhere (here a plane behind) beats a tessellation under the aperture.
    DrawMesh back;
    back.interior.edit().style = InteriorStyle::Solid;
    back.surface = std::make_shared<const geom::Surface>(
        1, 1, std::vector<double>{0, 0, 1, 1}, std::vector<double>{0, 0, 1, 1}, 2, 2,
        std::vector<glm::dvec3>{{0, 0, 0.1}, {0, 1, 0.1}, {1, 0, 0.1}, {1, 1, 0.1}});
    list.items.push_back(item(back, {{1, 2, 0}}));
    hit = picker.nearest(list, {0.805, 0.5}, 0.01);
    REQUIRE(hit);
    CHECK(hit->item == 1);
    REQUIRE(hit->surface);
    CHECK(hit->surface->point.z == Approx(0.1).margin(1e-12));
}

TEST_CASE("pick surface: a wireframe (EMPTY, iso-lines) is hit inside its patches with (u, v)", "[pick]") {
    // The plane z = 0.5 over [0.2, 0.8]^2, u along x and v along y, its front toward the viewer,
    // tessellated as two triangles with the iso-line u = 0.5.
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {{0.2f, 0.2f, 0.5f}, {0.8f, 0.2f, 0.5f}, {0.8f, 0.8f, 0.5f},
                       {0.2f, 0.8f, 0.5f}, {0.5f, 0.2f, 0.5f}, {0.5f, 0.8f, 0.5f}};
    mesh->triangles = {0, 1, 2, 0, 2, 3};
    mesh->trianglesPerFacet = 2;  // one grid cell: its diagonal is no edge
    mesh->isoLines = {{4, 5}};
    auto listOf = [&](InteriorStyle style, CullMode cull, bool exact) {
        DrawList list = unitList();
        DrawMesh m;
        m.mesh = mesh;
        m.interior.edit().style = style;
        m.interior.edit().cull = cull;
        if (exact)
            m.surface = std::make_shared<const geom::Surface>(
                1, 1, std::vector<double>{0, 0, 1, 1}, std::vector<double>{0, 0, 1, 1}, 2, 2,
                std::vector<glm::dvec3>{{0.2, 0.2, 0.5}, {0.2, 0.8, 0.5}, {0.8, 0.2, 0.5}, {0.8, 0.8, 0.5}});
        list.items.push_back(item(m, {{1, 1, 0}}));
        return list;
    };
    std::mt19937 rng(0x31e7);
    std::uniform_real_distribution<double> inside(0.25, 0.75), offLine(0.0005, 0.004);
    for (int round = 0; round < 50; ++round) {
        const Picker picker;
        // Inside a patch, away from the iso-line, and beside the iso-line within the aperture.
        glm::dvec2 p(inside(rng), inside(rng));
        if (std::abs(p.x - 0.5) < 0.02) p.x += 0.05;
        const glm::dvec2 q(0.5 + (round % 2 ? 1 : -1) * offLine(rng), inside(rng));
        for (const glm::dvec2 at : {p, q}) {
            const DrawList list = listOf(InteriorStyle::Empty, CullMode::None, true);
            const auto hit = picker.nearest(list, at, 0.005);
            REQUIRE(hit);
            REQUIRE(hit->surface);
            CHECK(hit->surface->uv.x == Approx((at.x - 0.2) / 0.6).margin(1e-9));
            CHECK(hit->surface->uv.y == Approx((at.y - 0.2) / 0.6).margin(1e-9));
            CHECK(hit->depth == Approx(0.5).margin(1e-6));
        }
        // A culled EMPTY side is not hit, nor an EMPTY mesh without its surface; a HOLLOW side
        // only on its lines, without (u, v).
        CHECK_FALSE(picker.nearest(listOf(InteriorStyle::Empty, CullMode::FrontFaces, true), p, 0.005));
        CHECK(picker.nearest(listOf(InteriorStyle::Empty, CullMode::BackFaces, true), p, 0.005));
        CHECK_FALSE(picker.nearest(listOf(InteriorStyle::Empty, CullMode::None, false), p, 0.005));
        CHECK_FALSE(picker.nearest(listOf(InteriorStyle::Hollow, CullMode::None, true), p, 0.005));
        const auto line = picker.nearest(listOf(InteriorStyle::Hollow, CullMode::None, true), q, 0.005);
        REQUIRE(line);
        CHECK_FALSE(line->surface);
    }
}

TEST_CASE("pick surface: a nearer wireframe's iso-line beside the point leaves the exact hit behind",
          "[pick]") {
    // Two wireframe planes (EMPTY, iso-lines): far, z = 0.5 over [0.2, 0.8]^2; near, z = 0.7 over
    // x in [0.2, e], its iso-line along its edge x = e. Picked just right of e, the line misses the
    // near plane: the far one is hit exactly, with (u, v), though the near iso-line lies in the
    // aperture; alone, the near plane is hit by its line, without (u, v).
    auto plane = [](double x1, double z, bool isoAtEdge) {
        auto mesh = std::make_shared<MeshData>();
        const float fx = float(x1), fz = float(z);
        mesh->positions = {{0.2f, 0.2f, fz}, {fx, 0.2f, fz}, {fx, 0.8f, fz}, {0.2f, 0.8f, fz}};
        mesh->triangles = {0, 1, 2, 0, 2, 3};
        mesh->trianglesPerFacet = 2;
        if (isoAtEdge) mesh->isoLines = {{1, 2}};
        DrawMesh m;
        m.mesh = mesh;
        m.interior.edit().style = InteriorStyle::Empty;
        m.surface = std::make_shared<const geom::Surface>(
            1, 1, std::vector<double>{0, 0, 1, 1}, std::vector<double>{0, 0, 1, 1}, 2, 2,
            std::vector<glm::dvec3>{{0.2, 0.2, z}, {0.2, 0.8, z}, {x1, 0.2, z}, {x1, 0.8, z}});
        return m;
    };
    std::mt19937 rng(0x5eed);
    std::uniform_real_distribution<double> edge(0.3, 0.7), along(0.25, 0.75), off(0.0005, 0.004);
    for (int round = 0; round < 50; ++round) {
        const double e = edge(rng);
        const glm::dvec2 at(e + off(rng), along(rng));
        DrawList both = unitList();
        both.items.push_back(item(plane(0.8, 0.5, false), {{1, 1, 0}}));
        both.items.push_back(item(plane(e, 0.7, true), {{2, 1, 0}}));
        const Picker picker;
        const auto hit = picker.nearest(both, at, 0.005);
        REQUIRE(hit);
        CHECK(hit->item == 0);
        REQUIRE(hit->surface);
        CHECK(hit->surface->uv.x == Approx((at.x - 0.2) / 0.6).margin(1e-9));
        CHECK(hit->depth == Approx(0.5).margin(1e-6));
        DrawList nearOnly = unitList();
        nearOnly.items.push_back(item(plane(e, 0.7, true), {{2, 1, 0}}));
        const auto line = Picker().nearest(nearOnly, at, 0.005);
        REQUIRE(line);
        CHECK_FALSE(line->surface);
        CHECK(line->depth == Approx(0.7).margin(1e-6));
    }
}

TEST_CASE("pick surface: under a perspective view the hit projects onto the pick point", "[pick]") {
    DrawList list = unitList();
    const glm::dmat4 proj = glm::perspective(glm::radians(50.0), 1.0, 0.5, 10.0);
    const glm::dmat4 toNpc = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5)) *
                             glm::scale(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, -0.5));
    list.views[0].mapping = toNpc * proj;
    list.views[0].orientation =
        glm::lookAt(glm::dvec3(0.5, -0.5, 2.0), glm::dvec3(0.5, 0.5, 0.5), glm::dvec3(0, 0, 1));
    const auto surface = heightField();
    list.items.push_back(surfaceItem(surface, {{1, 1, 1}}));
    const Picker picker;
    const glm::dmat4 m = list.views[0].mapping * list.views[0].orientation;
    int hits = 0;
    for (double x = 0.3; x <= 0.7; x += 0.1)
        for (double y = 0.3; y <= 0.7; y += 0.1) {
            const auto hit = picker.nearest(list, {x, y}, 0.001);
            if (!hit) continue;
            ++hits;
            const glm::dvec3 p = hit->surface->point;
            CHECK(glm::length(p - geom::evaluate(*surface, hit->surface->uv.x, hit->surface->uv.y)) < 1e-9);
            const glm::dvec4 h = m * glm::dvec4(p, 1.0);
            CHECK(h.x / h.w == Approx(x).margin(1e-9));
            CHECK(h.y / h.w == Approx(y).margin(1e-9));
            CHECK(hit->depth == Approx(h.z / h.w).margin(1e-12));
        }
    CHECK(hits > 10);
}

TEST_CASE("pick surface: the intersector cache lets go of surfaces the draw list dropped", "[pick]") {
    DrawList list = unitList();
    list.items.push_back(surfaceItem(heightField(), {{1, 1, 1}}));
    const Picker picker;
    CHECK(picker.nearest(list, {0.5, 0.5}, 0.001));
    CHECK(picker.cachedSurfaces() == 1);
    CHECK(picker.nearest(list, {0.4, 0.5}, 0.001));
    CHECK(picker.cachedSurfaces() == 1);  // reused
    list.items = {surfaceItem(heightField(), {{1, 1, 2}})};
    list.generation = 1;
    CHECK(picker.pick(list, {0.5, 0.5}, {0.001}).path.back().pickId == 2);
    CHECK(picker.cachedSurfaces() == 1);  // the old surface is gone, the new one cached
    picker.clearCache();
    CHECK(picker.cachedSurfaces() == 0);
}

}  // namespace test_pick_surface
