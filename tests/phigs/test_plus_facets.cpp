// Facet data of triangle strips and quadrilateral meshes, per-edge visibility of fill area sets
// with data, and level curves of NURBS surfaces: traversed into draw items (no GPU) and checked
// against the elements, with seeded random members. Surface meshes keep (u, v) per position
// exactly where something reads them, and share the stored surface.

#include "ErrorNumber.h"
#include "PostedScene.h"
#include "RandomElements.h"
#include "geom/Evaluate.h"
#include "phigs/Phigs.h"
#include "phigs/store/ArchiveFile.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace test_plus_facets {

using namespace phigs;
using phigs::test::errorOf;
using phigs::testing::randomInt;
using phigs::testing::randomPoints;

namespace {

using Scene = phigs::test::PostedScene;

template <class P>
std::vector<std::pair<const P*, const DrawItem*>> itemsOf(const DrawList& list) {
    std::vector<std::pair<const P*, const DrawItem*>> out;
    for (const DrawItem& item : list.items)
        if (auto p = primitiveIf<P>(item.primitive)) out.push_back({p, &item});
    return out;
}

Colour rgb(std::mt19937& rng) {
    return Colour::fromRgb(
        {randomInt(rng, 0, 8) / 8.0, randomInt(rng, 0, 8) / 8.0, randomInt(rng, 0, 8) / 8.0});
}
std::vector<Colour> rgbs(std::mt19937& rng, std::size_t n) {
    std::vector<Colour> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(rgb(rng));
    return out;
}
glm::vec3 unit(const glm::dvec3& n) {
    return glm::vec3(glm::normalize(n));
}
/// A mesh's normal against the unit direction given: packed, within 1e-4 radians.
bool nearDirection(const PackedNormal& a, const glm::vec3& b) {
    return glm::length(a.unpacked() - b) <= 1e-4f;
}

/// Random facet and vertex data (each list present or not) for `points` points and `facets` facets.
template <class Mesh>
void randomData(std::mt19937& rng, Mesh& e, std::size_t facets) {
    const std::size_t n = e.points.size();
    if (randomInt(rng, 0, 2) == 0) e.vertexColours = rgbs(rng, n);
    if (randomInt(rng, 0, 2) == 0) e.vertexNormals = randomPoints(rng, static_cast<int>(n));
    if (randomInt(rng, 0, 1)) e.facetColours = rgbs(rng, facets);
    if (randomInt(rng, 0, 1)) e.facetNormals = randomPoints(rng, static_cast<int>(facets));
}

/// The drawn mesh of a strip or mesh `e` whose facet f has points `cornersOf(f)`, `perFacet`
/// triangles each, follows the precedence rules: vertex data over facet data over none; flat
/// shaded (`flat`), a facet is one colour, so its vertex colours are not drawn.
template <class Mesh, class CornersOf>
void checkFacets(const MeshData& m, const Mesh& e, std::size_t facets, std::size_t perFacet, bool flat,
                 CornersOf cornersOf) {
    REQUIRE(m.triangles.size() == facets * perFacet * 3);
    const bool vertexColours = !e.vertexColours.empty() && !flat;
    const bool facetColours = !vertexColours && !e.facetColours.empty();
    const bool facetNormals = e.vertexNormals.empty() && !e.facetNormals.empty();
    CHECK(m.colours.size() == (!vertexColours && !facetColours ? 0 : m.positions.size()));
    CHECK(m.normals.size() == (e.vertexNormals.empty() && !facetNormals ? 0 : m.positions.size()));
    for (std::size_t t = 0; t < m.triangles.size() / 3; ++t) {
        const std::size_t f = t / perFacet;
        const std::vector<std::size_t> corners = cornersOf(f);
        std::array<glm::vec3, 3> p;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = m.triangles[3 * t + std::size_t(k)];
            p[std::size_t(k)] = m.positions[i];
            // the point of the element this corner stands for
            std::size_t source = corners.size();
            for (std::size_t c = 0; c < corners.size(); ++c)
                if (glm::vec3(e.points[corners[c]]) == m.positions[i]) source = c;
            REQUIRE(source < corners.size());
            const std::size_t v = corners[source];
            if (vertexColours)
                CHECK(m.colours[i] == glm::vec3(e.vertexColours[v].rgb));
            else if (facetColours)
                CHECK(m.colours[i] == glm::vec3(e.facetColours[f].rgb));
            if (!e.vertexNormals.empty())
                CHECK(nearDirection(m.normals[i], unit(e.vertexNormals[v])));
            else if (facetNormals)
                CHECK(nearDirection(m.normals[i], unit(e.facetNormals[f])));
        }
        if (facetNormals) {  // the facet normal gives the front: counter-clockwise seen from it
            const glm::dvec3 winding = glm::cross(glm::dvec3(p[1] - p[0]), glm::dvec3(p[2] - p[0]));
            CHECK(glm::dot(winding, e.facetNormals[f]) >=
                  -1e-9 * glm::length(winding) * glm::length(e.facetNormals[f]));
        }
    }
}

/// SET INTERIOR SHADING METHOD: NONE (flat) or COLOUR.
Element shadingMethod(bool flat) {
    return IndexAttribute{ElementType::InteriorShadingMethod,
                          int(flat ? ShadingMethod::None : ShadingMethod::Colour)};
}

const DrawMesh& onlyMesh(const DrawList& list) {
    const auto meshes = itemsOf<DrawMesh>(list);
    REQUIRE(meshes.size() == 1);
    return *meshes[0].first;
}

/// A random bicubic-ish surface over [0, 1] x [0, 1], gently curved, about 10 units across.
geom::Surface randomSheet(std::mt19937& rng) {
    const int degree = randomInt(rng, 1, 3), n = degree + 1 + randomInt(rng, 0, 2);
    std::vector<double> knots(static_cast<std::size_t>(degree + 1), 0.0);
    for (int i = 1; i < n - degree; ++i) knots.push_back(double(i) / (n - degree));
    knots.insert(knots.end(), static_cast<std::size_t>(degree + 1), 1.0);
    std::uniform_real_distribution<double> bump(-2.0, 2.0);
    std::vector<glm::dvec3> points;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) points.push_back({10.0 * i / (n - 1), 10.0 * j / (n - 1), bump(rng)});
    return geom::Surface(degree, degree, knots, knots, std::size_t(n), std::size_t(n), points);
}

}  // namespace

TEST_CASE("random triangle strips with facet data draw each facet's colour and normal", "[plus][traverse]") {
    std::mt19937 rng(4099);
    for (int round = 0; round < 60; ++round) {
        TriangleStripElement e{randomPoints(rng, randomInt(rng, 3, 12)), {}, {}};
        const std::size_t facets = e.points.size() - 2;
        randomData(rng, e, facets);
        Scene s;
        const bool flat = round % 2 == 0;
        const DrawMesh& mesh = onlyMesh(s.draw({shadingMethod(flat), e}));
        checkFacets(*mesh.mesh, e, facets, 1, flat, [](std::size_t f) {
            return std::vector<std::size_t>{f, f + 1, f + 2};
        });
    }
}

TEST_CASE("random quadrilateral meshes with facet data draw each facet's colour and normal",
          "[plus][traverse]") {
    std::mt19937 rng(6151);
    for (int round = 0; round < 60; ++round) {
        const int rows = randomInt(rng, 2, 5), columns = randomInt(rng, 2, 5);
        QuadrilateralMeshElement e{rows, columns, randomPoints(rng, rows * columns), {}, {}};
        const auto facets = static_cast<std::size_t>((rows - 1) * (columns - 1));
        randomData(rng, e, facets);
        Scene s;
        const bool flat = round % 2 == 0;
        const DrawMesh& mesh = onlyMesh(s.draw({shadingMethod(flat), e}));
        const auto width = static_cast<std::size_t>(columns);
        checkFacets(*mesh.mesh, e, facets, 2, flat, [&](std::size_t f) {
            const std::size_t r = f / (width - 1), c = f % (width - 1);
            return std::vector<std::size_t>{r * width + c, r * width + c + 1, (r + 1) * width + c,
                                            (r + 1) * width + c + 1};
        });
    }
}

TEST_CASE("facet data is checked against the facet count and survives the archive",
          "[plus][store][archive]") {
    TriangleStripElement strip{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {}, {}};
    strip.facetColours = {Colour::indexed(1)};
    CHECK(validateElement(strip) == "1 facet colours for 2 triangles");
    strip.facetColours = {Colour::indexed(1), Colour::indexed(4)};
    strip.facetNormals = {{0, 0, 1}};
    CHECK(validateElement(strip) == "1 facet normals for 2 triangles");
    std::mt19937 points(5);
    QuadrilateralMeshElement mesh{2, 3, randomPoints(points, 6), {}, {}};
    mesh.facetNormals = {{0, 0, 1}};
    CHECK(validateElement(mesh) == "1 facet normals for 2 quadrilaterals");
    FillAreaSetWithDataElement area;
    area.contours = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    area.edgeFlags = {{1, 0}};
    CHECK(validateElement(area) == "contour 0 has 2 edge flags for 3 edges");
    area.edgeFlags = {{1, 0, 3}};
    CHECK(validateElement(area) == "contour 0: edge flag 3 is neither 0 nor 1");
    SurfaceCharacteristicsAttribute level{4, 0, 0, 0};
    level.direction = glm::dvec3(0.0);
    CHECK(validateElement(level) == "level curve direction is zero");
    Scene s;
    s.store->openStructure(2);
    CHECK(errorOf([&] { s.store->insert(strip); }) == -202);
    level.direction = {0, 0, 1}, level.levels = {1.0, std::nan("")};
    CHECK(errorOf([&] { s.store->insert(level); }) == -202);
    CHECK(s.store->elementCount(2) == 0);

    std::mt19937 rng(3301);
    for (int round = 0; round < 30; ++round) {
        TriangleStripElement t{randomPoints(rng, randomInt(rng, 3, 7)), {}, {}};
        randomData(rng, t, t.points.size() - 2);
        FillAreaSetWithDataElement f;
        f.contours = {randomPoints(rng, 4), randomPoints(rng, 3)};
        f.edgeFlags = {{randomInt(rng, 0, 1), 1, 0, randomInt(rng, 0, 1)}, {1, randomInt(rng, 0, 1), 1}};
        SurfaceCharacteristicsAttribute c{randomInt(rng, 4, 5), 0, 0, 0};
        c.origin = phigs::testing::randomPoint(rng), c.direction = phigs::testing::randomPoint(rng);
        for (int k = randomInt(rng, 0, 5); k > 0; --k) c.levels.push_back(phigs::testing::randomReal(rng));
        const std::map<int, std::vector<Element>> contents{{1, {t, f, c}}};
        CHECK(ArchiveFile::decode(ArchiveFile::encode(contents), "facets", nullptr) == contents);
    }
}

TEST_CASE("fill area set with data: only the edges whose flag is on are drawn", "[plus][traverse]") {
    std::mt19937 rng(8377);
    for (int round = 0; round < 60; ++round) {
        FillAreaSetWithDataElement e;
        std::set<std::pair<std::array<double, 3>, std::array<double, 3>>> flagged;
        auto key = [](const glm::dvec3& p) { return std::array<double, 3>{p.x, p.y, p.z}; };
        for (int c = randomInt(rng, 1, 3); c > 0; --c) {
            const auto& contour = e.contours.emplace_back(randomPoints(rng, randomInt(rng, 3, 7)));
            auto& flags = e.edgeFlags.emplace_back();
            for (std::size_t k = 0; k < contour.size(); ++k) {
                flags.push_back(randomInt(rng, 0, 1));
                if (flags.back())
                    flagged.insert(std::minmax(key(contour[k]), key(contour[(k + 1) % contour.size()])));
            }
        }
        const bool edgeOn = randomInt(rng, 0, 3) != 0;
        const Colour edgeColour = rgb(rng);
        Scene s;
        const DrawList& list = s.draw({IndexAttribute{ElementType::EdgeFlag, edgeOn ? 1 : 0},
                                       ColourAttribute{ElementType::EdgeColour, edgeColour}, e});
        const auto fills = itemsOf<DrawFillArea>(list);
        REQUIRE(fills.size() == 1);
        CHECK_FALSE(fills[0].first->edges->visible);  // its edges come as polylines, or not at all
        std::set<std::pair<std::array<double, 3>, std::array<double, 3>>> drawn;
        for (const auto& [line, item] : itemsOf<DrawPolyline>(list)) {
            CHECK(line->style->colour == glm::vec3(edgeColour.rgb));
            for (std::size_t k = 0; k + 1 < line->points.size(); ++k)
                drawn.insert(std::minmax(key(line->points[k]), key(line->points[k + 1])));
        }
        CHECK(drawn == (edgeOn ? flagged : decltype(flagged){}));
    }
}

TEST_CASE("level curves lie on the surface and on their planes, in modelling and world coordinates",
          "[plus][traverse][surface]") {
    std::mt19937 rng(9547);
    for (int round = 0; round < 30; ++round) {
        const geom::Surface surface = randomSheet(rng);
        SurfaceCharacteristicsAttribute c{randomInt(rng, 4, 5), 0, 0, 0};
        std::uniform_real_distribution<double> real(-1.0, 1.0);
        c.origin = {5 + 3 * real(rng), 5 + 3 * real(rng), real(rng)};
        c.direction = {real(rng), real(rng), real(rng)};
        if (glm::length(c.direction) < 0.1) c.direction = {0, 0.6, 0.8};
        for (int k = randomInt(rng, 1, 4); k > 0; --k)
            c.levels.push_back(4 * real(rng) / glm::length(c.direction));
        glm::dmat4 model = glm::rotate(glm::translate(glm::dmat4(1.0), {real(rng), real(rng), real(rng)}),
                                       3 * real(rng), glm::normalize(glm::dvec3(real(rng), real(rng), 1.5)));
        const bool chordal = randomInt(rng, 0, 1) == 1;
        Scene s;
        const DrawList& list =
            s.draw({TransformElement{ElementType::LocalModellingTransformation3, model, Composition::Replace},
                    ApproximationAttribute{ElementType::SurfaceApproximationCriteria, chordal ? 6 : 2,
                                           chordal ? 0.05 : 6, 6},
                    c, NurbsSurfaceElement{surface, {}}});
        const auto meshes = itemsOf<DrawMesh>(list);
        REQUIRE(meshes.size() == 1);
        const MeshData& m = *meshes[0].first->mesh;
        const glm::dmat4& toWorld = *meshes[0].second->modelTransform();
        // Each plane that cuts the surface (its values on a fine grid change sign) has a curve.
        std::size_t expected = 0;
        for (double t : c.levels) {
            const glm::dvec3 q = c.origin + t * c.direction;
            double low = 1e300, high = -1e300;
            for (int i = 0; i <= 40; ++i)
                for (int j = 0; j <= 40; ++j) {
                    glm::dvec3 p = geom::evaluate(surface, i / 40.0, j / 40.0);
                    if (c.style == 5) p = glm::dvec3(toWorld * glm::dvec4(p, 1.0));
                    const double f = glm::dot(p - q, glm::normalize(c.direction));
                    low = std::min(low, f), high = std::max(high, f);
                }
            if (low < -0.05 && high > 0.05) ++expected;
        }
        CHECK(m.isoLines.size() >= expected);
        std::size_t points = 0;
        for (const auto& line : m.isoLines) {
            CHECK(line.size() >= 2);
            for (std::uint32_t i : line) {
                REQUIRE(i < m.positions.size());
                ++points;
                glm::dvec3 p(m.positions[i]);
                // on the surface: the point its (u, v) gives
                const glm::dvec3 exact = geom::evaluate(surface, m.uv[i].x, m.uv[i].y);
                CHECK(glm::distance(p, exact) < 1e-3);
                if (c.style == 5) p = glm::dvec3(toWorld * glm::dvec4(p, 1.0));
                double best = 1e300;  // on one of the planes
                for (double t : c.levels)
                    best = std::min(best, std::abs(glm::dot(p - (c.origin + t * c.direction),
                                                            glm::normalize(c.direction))));
                CHECK(best < 1e-4);
            }
        }
        if (expected > 0) CHECK(points > 0);
    }
}

TEST_CASE("surface meshes keep (u, v) where read and share the stored surface", "[plus][traverse][surface]") {
    // (u, v) is read by level curves (styles 4, 5) and by patch edges along knot lines inside
    // the domain; a one-span surface drawn otherwise has no reader and keeps none.
    std::mt19937 rng(4411);
    for (int round = 0; round < 60; ++round) {
        const geom::Surface surface = randomSheet(rng);
        const int style = randomInt(rng, 1, 5);
        SurfaceCharacteristicsAttribute c{style, 0, 2, 2};
        if (style >= 4) c.levels = {0.5}, c.origin = {5, 5, 0}, c.direction = {1, 1, 0};
        const bool chordal = style != 3 && randomInt(rng, 0, 1) == 1;
        Scene s;
        const DrawList& list = s.draw({ApproximationAttribute{ElementType::SurfaceApproximationCriteria,
                                                              chordal ? 6 : 2, chordal ? 0.05 : 4, 4},
                                       c, NurbsSurfaceElement{surface, {}}});
        const auto meshes = itemsOf<DrawMesh>(list);
        REQUIRE(meshes.size() == 1);
        const DrawMesh& d = *meshes[0].first;
        const MeshData& m = *d.mesh;
        const bool oneSpan = surface.knotsU.size() == std::size_t(2 * (surface.degreeU + 1)) &&
                             surface.knotsV.size() == std::size_t(2 * (surface.degreeV + 1));
        INFO("round " << round << ", style " << style << ", one span " << oneSpan);
        CHECK(m.uv.empty() == (oneSpan && style < 4));
        if (!m.uv.empty()) {
            REQUIRE(m.uv.size() == m.positions.size());
            for (std::size_t i = 0; i < m.positions.size(); ++i)
                REQUIRE(glm::distance(glm::dvec3(m.positions[i]),
                                      geom::evaluate(surface, m.uv[i].x, m.uv[i].y)) < 1e-3);
        }
        // The draw item's exact surface is the stored one, not a copy.
        const auto* stored = s.store->structure(1).elements.get<NurbsSurfaceElement>(2);
        REQUIRE(stored);
        CHECK(d.surface.get() == &stored->surface);
    }
}

}  // namespace test_plus_facets
