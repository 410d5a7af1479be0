// Trimming curves' visibility and approximation (PHIGS PLUS), over random trimmed surfaces of
// degrees 1 to 3 with loops of one or two curves of degrees 1 to 3: a visible curve becomes a
// polyline on the surface drawn with the edges, its approximation decides how finely it is
// followed (for the polyline and for the trimming), and visibility never changes what is kept.

#include "RandomElements.h"

#include "phigs/Phigs.h"
#include "phigs/render/ItemGeometry.h"

#include "geom/Evaluate.h"

#include <catch2/catch.hpp>

#include <algorithm>

namespace test_trim_display {

using namespace phigs;
using phigs::testing::randomInt;

namespace {

/// The parameters a trim curve is sampled at under criteria 1 (8 per span) or 2 (`perSpan`).
std::vector<double> sampleParameters(const std::vector<double>& knots, double start, double end,
                                     int perSpan) {
    std::vector<double> breaks{start};
    for (double k : knots)
        if (k > breaks.back() && k < end) breaks.push_back(k);
    breaks.push_back(end);
    std::vector<double> t;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
        for (int s = 0; s < perSpan; ++s)
            t.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * static_cast<double>(s) / perSpan);
    t.push_back(breaks.back());
    return t;
}

int perSpanOf(const TrimCurveDisplay& d) {
    return d.approximation == 2 ? std::clamp(static_cast<int>(std::lround(d.approximationValue)), 1, 256) : 8;
}

/// A curve of degree 1..3 in (u, v) from `from` to `to` with random inner points in [lo, hi]^2.
geom::Curve uvCurve(std::mt19937& rng, glm::dvec2 from, glm::dvec2 to, glm::dvec2 lo, glm::dvec2 hi) {
    const int degree = randomInt(rng, 1, 3), n = degree + 1 + randomInt(rng, 0, 3);
    std::vector<double> knots(static_cast<std::size_t>(degree + 1), 0.0);
    for (int i = 1; i < n - degree; ++i) knots.push_back(i);
    knots.insert(knots.end(), static_cast<std::size_t>(degree + 1), double(n - degree));
    std::uniform_real_distribution<double> a(0.0, 1.0);
    std::vector<glm::dvec3> points{{from, 0.0}};
    for (int i = 1; i + 1 < n; ++i) points.push_back({lo + (hi - lo) * glm::dvec2(a(rng), a(rng)), 0.0});
    points.push_back({to, 0.0});
    return geom::Curve(degree, knots, points);
}

TrimCurveDisplay randomDisplay(std::mt19937& rng) {
    TrimCurveDisplay d;
    d.visible = randomInt(rng, 0, 1) == 1;
    switch (randomInt(rng, 0, 2)) {
        case 0:
            break;  // workstation dependent
        case 1:
            d.approximation = 2, d.approximationValue = randomInt(rng, 1, 12);
            break;
        default:
            d.approximation = 6,
            d.approximationValue = std::uniform_real_distribution<double>(0.002, 0.3)(rng);
    }
    return d;
}

/// A random surface with one or two loops, each of one closed curve or two curves end to end.
NurbsSurfaceElement randomTrimmedSurface(std::mt19937& rng) {
    NurbsSurfaceElement e{phigs::testing::randomSurface(rng), {}};
    const geom::Surface& s = e.surface;
    const glm::dvec2 low(s.domainStartU(), s.domainStartV()), high(s.domainEndU(), s.domainEndV());
    const glm::dvec2 lo = low + 0.05 * (high - low), hi = high - 0.05 * (high - low);
    std::uniform_real_distribution<double> a(0.0, 1.0);
    for (int l = randomInt(rng, 1, 2); l > 0; --l) {
        const glm::dvec2 p = lo + (hi - lo) * glm::dvec2(a(rng), a(rng));
        const glm::dvec2 q = lo + (hi - lo) * glm::dvec2(a(rng), a(rng));
        if (randomInt(rng, 0, 1))
            e.trimLoops.push_back({uvCurve(rng, p, p, lo, hi)});
        else
            e.trimLoops.push_back({uvCurve(rng, p, q, lo, hi), uvCurve(rng, q, p, lo, hi)});
        for (std::size_t k = 0; k < e.trimLoops.back().size(); ++k)
            e.trimDisplay.push_back(randomDisplay(rng));
    }
    return e;
}

/// The mesh the workstation makes of `element` (workstation-dependent surface approximation).
std::shared_ptr<const MeshData> meshOf(const NurbsSurfaceElement& element) {
    Phigs phigs;
    phigs.open();
    phigs.store().openStructure(1);
    phigs.store().insert(element);
    phigs.store().closeStructure();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    ws.postStructure(1, 0);
    const DrawList& list = ws.display();
    REQUIRE(list.items.size() == 1);
    return primitiveAs<DrawMesh>(list.items[0].primitive).mesh;
}

bool insideEvenOdd(const std::vector<std::vector<glm::dvec2>>& loops, glm::dvec2 p) {
    bool inside = false;
    for (const auto& poly : loops)
        for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
            if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
                p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
                inside = !inside;
    return inside;
}

/// Triangles kept when every curve is sampled as `display` says (none chordal): the grid cells
/// (8 per span each way) whose centre the loops enclose, two triangles each.
std::size_t expectedTriangles(const NurbsSurfaceElement& e) {
    std::vector<std::vector<glm::dvec2>> loops;
    std::size_t k = 0;
    for (const TrimLoop& loop : e.trimLoops) {
        auto& polygon = loops.emplace_back();
        for (const geom::Curve& c : loop)
            for (double t :
                 sampleParameters(c.knots, c.domainStart(), c.domainEnd(), perSpanOf(e.displayOf(k++)))) {
                const glm::dvec3 p = geom::evaluate(c, t);
                polygon.push_back({p.x, p.y});
            }
    }
    const geom::Surface& s = e.surface;
    const auto us = sampleParameters(s.knotsU, s.domainStartU(), s.domainEndU(), 8);
    const auto vs = sampleParameters(s.knotsV, s.domainStartV(), s.domainEndV(), 8);
    std::size_t cells = 0;
    for (std::size_t i = 0; i + 1 < us.size(); ++i)
        for (std::size_t j = 0; j + 1 < vs.size(); ++j)
            cells += insideEvenOdd(loops, {(us[i] + us[i + 1]) / 2, (vs[j] + vs[j + 1]) / 2});
    return 2 * cells;
}

}  // namespace

TEST_CASE("visible trimming curves lie on the surface, followed as their approximation asks",
          "[traverse][plus][trim]") {
    int visibleCurves = 0, chordal = 0, checkedCells = 0;
    for (std::uint32_t seed = 1; seed <= 120; ++seed) {
        std::mt19937 rng(seed);
        const NurbsSurfaceElement element = randomTrimmedSurface(rng);
        INFO("seed " << seed);
        const auto mesh = meshOf(element);

        // Hidden, the same curves trim the same cells: the grid and its triangles are unchanged,
        // and the visible curves' points come after the grid's, in no triangle.
        NurbsSurfaceElement hidden = element;
        for (TrimCurveDisplay& d : hidden.trimDisplay) d.visible = false;
        const auto plain = meshOf(hidden);
        CHECK(plain->trimEdges.empty());
        CHECK(std::vector<std::uint32_t>(mesh->triangles) == std::vector<std::uint32_t>(plain->triangles));
        REQUIRE(mesh->positions.size() >= plain->positions.size());
        CHECK(std::equal(plain->positions.begin(), plain->positions.end(), mesh->positions.begin()));
        CHECK(mesh->normals.size() == mesh->positions.size());
        CHECK((mesh->uv.empty() || mesh->uv.size() == mesh->positions.size()));

        std::size_t k = 0, line = 0;
        bool anyChordal = false;
        const geom::Surface& s = element.surface;
        for (const TrimLoop& loop : element.trimLoops)
            for (const geom::Curve& c : loop) {
                const TrimCurveDisplay d = element.displayOf(k++);
                anyChordal = anyChordal || d.approximation == 6;
                if (!d.visible) continue;
                ++visibleCurves;
                REQUIRE(line < mesh->trimEdges.size());
                const auto& edge = mesh->trimEdges[line++];
                for (std::uint32_t i : edge) CHECK(i >= plain->positions.size());
                auto onSurface = [&](double t) {
                    const glm::dvec3 uv = geom::evaluate(c, t);
                    return glm::vec3(geom::evaluate(s, std::clamp(uv.x, s.domainStartU(), s.domainEndU()),
                                                    std::clamp(uv.y, s.domainStartV(), s.domainEndV())));
                };
                auto near = [](glm::vec3 a, glm::vec3 b) {
                    return glm::length(a - b) <= 1e-4f * (1 + glm::length(b));
                };
                if (d.approximation == 6) {
                    ++chordal;
                    CHECK(edge.size() >= 2);
                    CHECK(near(mesh->positions[edge.front()], onSurface(c.domainStart())));
                    CHECK(near(mesh->positions[edge.back()], onSurface(c.domainEnd())));
                    continue;
                }
                const auto t = sampleParameters(c.knots, c.domainStart(), c.domainEnd(), perSpanOf(d));
                REQUIRE(edge.size() == t.size());
                for (std::size_t i = 0; i < t.size(); ++i)
                    CHECK(near(mesh->positions[edge[i]], onSurface(t[i])));
            }
        CHECK(line == mesh->trimEdges.size());
        if (!anyChordal) {
            CHECK(mesh->triangles.size() / 3 == expectedTriangles(element));
            ++checkedCells;
        }

        // The raster draws them after the facets' edges, with the edge flag only.
        const render::MeshIndices indices = render::meshIndices(*mesh);
        std::size_t pairs = 0;
        for (const auto& e : mesh->trimEdges) pairs += e.size() - 1;
        CHECK(indices.trimEdgeCount == 2 * pairs);
        CHECK(indices.indices.size() == std::size_t{indices.triangleCount} + indices.isoLineCount +
                                            indices.edgeCount + indices.trimEdgeCount);
        CHECK(render::meshIndices(*plain).edgeCount == indices.edgeCount);
    }
    CHECK(visibleCurves > 60);
    CHECK(chordal > 15);
    CHECK(checkedCells > 20);
}

TEST_CASE("a finer trim approximation follows a curved trimming loop more closely",
          "[traverse][plus][trim]") {
    // A quarter circle's worth of degree-2 curve closing a loop: one segment per span trims to its
    // chords, more segments to cells nearer the curve; chordal criteria tighten the same way.
    NurbsSurfaceElement e{
        geom::Surface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}}),
        {}};
    e.trimLoops = {{geom::Curve(2, {0, 0, 0, 1, 1, 1}, {{0.1, 0.1, 0}, {0.9, 0.1, 0}, {0.9, 0.9, 0}}),
                    geom::Curve(1, {0, 0, 1, 1}, {{0.9, 0.9, 0}, {0.1, 0.1, 0}})}};
    std::vector<std::size_t> points, triangles;
    for (const TrimCurveDisplay d : {TrimCurveDisplay{true, 2, 1}, TrimCurveDisplay{true, 2, 16},
                                     TrimCurveDisplay{true, 6, 0.05}, TrimCurveDisplay{true, 6, 0.0005}}) {
        e.trimDisplay = {d, TrimCurveDisplay{}};
        const auto mesh = meshOf(e);
        REQUIRE(mesh->trimEdges.size() == 1);
        points.push_back(mesh->trimEdges[0].size());
        triangles.push_back(mesh->triangles.size());
    }
    CHECK(points[0] == 2);
    CHECK(points[1] == 17);
    CHECK(points[2] < points[3]);
    CHECK(triangles[0] != triangles[1]);  // the chord cuts off cells the curve keeps
}

}  // namespace test_trim_display
