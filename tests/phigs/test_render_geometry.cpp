// GPU-free pieces of the renderer: triangulation with holes, line patterns, marker shapes,
// stroke-font layout, describe-step geometry (vertex-coloured patterned lines and areas included)
// and cache keys.
#include "phigs/core/ColourModels.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/render/LinePattern.h"
#include "phigs/render/MarkerShape.h"
#include "phigs/render/MeshEdges.h"
#include "phigs/render/StrokeFont.h"
#include "phigs/render/Triangulation.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <stdexcept>

namespace test_render_geometry {

using namespace phigs;
using namespace phigs::render;

namespace {

std::vector<glm::dvec2> square(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

glm::dvec2 extentOf(const std::vector<std::vector<glm::dvec2>>& strips, glm::dvec2& lo) {
    lo = glm::dvec2(1e30);
    glm::dvec2 hi(-1e30);
    for (const auto& s : strips)
        for (const auto& p : s) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return hi;
}

}  // namespace

TEST_CASE("triangulation: convex, concave, holes and self-intersection by the even-odd rule",
          "[render][unit]") {
    CHECK(triangulatedArea(triangulateEvenOdd({square(0, 0, 2, 1)})) == Approx(2.0));
    // A "U": 3x3 square minus the 1x2 notch.
    const std::vector<glm::dvec2> u = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    CHECK(triangulatedArea(triangulateEvenOdd({u})) == Approx(7.0));
    // Holes subtract whatever their orientation.
    auto hole = square(1, 1, 2, 2);
    CHECK(triangulatedArea(triangulateEvenOdd({square(0, 0, 3, 3), hole})) == Approx(8.0));
    std::reverse(hole.begin(), hole.end());
    CHECK(triangulatedArea(triangulateEvenOdd({square(0, 0, 3, 3), hole})) == Approx(8.0));
    // A bow tie: two triangles of area 1 each.
    CHECK(triangulatedArea(triangulateEvenOdd({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}})) == Approx(2.0));
    // A clockwise outline still gives counter-clockwise triangles (positive area).
    auto cw = square(0, 0, 1, 1);
    std::reverse(cw.begin(), cw.end());
    CHECK(triangulatedArea(triangulateEvenOdd({cw})) == Approx(1.0));
    // Degenerate input: nothing, no crash.
    CHECK(triangulateEvenOdd({{{0, 0}, {1, 1}}}).triangles.empty());
    CHECK(triangulateEvenOdd({}).triangles.empty());
    // Every vertex lies on an input edge at its parameter.
    const Triangulation t = triangulateEvenOdd({u});
    for (const auto& v : t.vertices) {
        const glm::dvec2 p = u[v.from] * (1.0 - v.t) + u[v.to] * v.t;
        CHECK(p.x == Approx(v.point.x).margin(1e-12));
        CHECK(p.y == Approx(v.point.y).margin(1e-12));
    }
}

TEST_CASE("triangulation: simple polygons of many points give O(n) triangles covering their area",
          "[render][unit]") {
    // Random stars (concave, every vertex at its own height) up to 20,000 points: the area is the
    // polygon's, and the triangles stay linear in the points (one trapezoid per pair of edges for
    // as long as the pair bounds the inside, not one per slab).
    std::mt19937 random(18500);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const int n : {50, 400, 3000, 20000}) {
        std::vector<glm::dvec2> star;
        for (int i = 0; i < n; ++i) {
            const double angle = 2.0 * 3.141592653589793 * (i + 0.5 * unit(random)) / n;
            const double r = i % 2 ? 1.0 + unit(random) : 0.2 + 0.1 * unit(random);
            star.push_back({r * std::cos(angle), r * std::sin(angle)});
        }
        double area = 0.0;
        for (int i = 0; i < n; ++i)
            area += 0.5 * (star[i].x * star[(i + 1) % n].y - star[(i + 1) % n].x * star[i].y);
        const Triangulation t = triangulateEvenOdd({star});
        INFO(n << " points, " << t.triangles.size() / 3 << " triangles");
        CHECK(triangulatedArea(t) == Approx(std::abs(area)).epsilon(1e-9));
        CHECK(t.triangles.size() / 3 <= std::size_t(4 * n));
    }
}

TEST_CASE("triangulation: contours crossing each other everywhere are refused in bounded time",
          "[render][unit]") {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<glm::dvec2> tangle;
    for (int i = 0; i < 20000; ++i) tangle.push_back({unit(random), unit(random)});
    CHECK_THROWS_AS(triangulateEvenOdd({tangle}), std::length_error);
}

TEST_CASE("triangulation: a lone triangle is its own triangle, counter-clockwise", "[render][unit]") {
    std::mt19937 rng(20261204);
    std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
    for (int round = 0; round < 50; ++round) {
        std::vector<glm::dvec2> c(3);
        for (auto& p : c) p = {coordinate(rng), coordinate(rng)};
        const double area =
            0.5 * ((c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[1].y - c[0].y) * (c[2].x - c[0].x));
        const Triangulation t = triangulateEvenOdd({c});
        REQUIRE(t.triangles.size() == 3);
        CHECK(triangulatedArea(t) == Approx(std::abs(area)));
        for (const std::uint32_t i : t.triangles) {
            CHECK(t.vertices[i].from == i);
            CHECK(t.vertices[i].t == 0.0);
            CHECK(t.vertices[i].point == c[i]);
        }
    }
    CHECK(triangulateEvenOdd({{{0, 0}, {1, 1}, {2, 2}}}).triangles.empty());  // no area
}

TEST_CASE("describe: vertices cut on an area's edges carry the colour mixed in its rendering colour model",
          "[render][unit][colour]") {
    std::mt19937 rng(20261205);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const ColourModel models[] = {ColourModel::Rgb, ColourModel::Cieluv, ColourModel::Hsv, ColourModel::Hls};
    int cut = 0;
    for (int round = 0; round < 40; ++round) {
        const ColourModel model = models[round % 4];
        // A convex quadrilateral, corners at distinct x and y: the slabs cut its edges.
        DrawFillArea fill;
        fill.contours = {
            {{0, 0, 0}, {1, 0.1 + 0.3 * unit(rng), 0}, {0.9, 1.2, 0}, {-0.1, 0.6 + 0.3 * unit(rng), 0}}};
        fill.vertexColours = {{}};
        for (int k = 0; k < 4; ++k)
            fill.vertexColours[0].push_back(glm::vec3(glm::dvec3(unit(rng), unit(rng), unit(rng))));
        fill.interior.edit().style = InteriorStyle::Solid;
        fill.interior.edit().renderingModel = model;
        DrawItem item;
        item.primitive = fill;
        const ItemGeometry g = describeItem(item, glm::dmat4(1.0));
        REQUIRE_FALSE(g.parts.empty());
        const auto& corners = fill.contours[0];
        for (std::uint32_t i = g.parts[0].first; i < g.parts[0].first + g.parts[0].count; ++i) {
            const glm::dvec3 p(g.vertices[i].position);
            for (std::size_t e = 0; e < 4; ++e) {
                const glm::dvec3 a = corners[e], b = corners[(e + 1) % 4];
                const double t = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
                if (!(t > 1e-6 && t < 1 - 1e-6) || glm::length(a + t * (b - a) - p) > 1e-6) continue;
                const glm::dvec3 ca(fill.vertexColours[0][e]), cb(fill.vertexColours[0][(e + 1) % 4]);
                const glm::dvec3 expected =
                    toRgb(model, (1 - t) * fromRgb(model, ca) + t * fromRgb(model, cb));
                CHECK(glm::length(glm::dvec3(g.vertices[i].colour) - expected) < 1e-4);
                ++cut;
            }
        }
    }
    CHECK(cut >= 40);  // every quadrilateral has cut vertices
}

TEST_CASE("line patterns: solid, dashed, dotted and dash-dotted scale with the width", "[render][unit]") {
    for (float d : {0.0f, 5.0f, 17.0f, 100.0f}) CHECK(linePatternOn(LineType::Solid, 1, d));
    CHECK(linePatternOn(LineType::Dashed, 1, 1));
    CHECK_FALSE(linePatternOn(LineType::Dashed, 1, 14));
    CHECK(linePatternOn(LineType::Dashed, 1, 19));
    CHECK(linePatternOn(LineType::Dashed, 2, 14));  // twice as long at width 2
    CHECK(linePatternOn(LineType::Dotted, 1, 1));
    CHECK_FALSE(linePatternOn(LineType::Dotted, 1, 3));
    CHECK(linePatternOn(LineType::DashDotted, 1, 18));
    CHECK_FALSE(linePatternOn(LineType::DashDotted, 1, 15));
    CHECK(linePattern(LineType::DashDotted).period == Approx(24));
}

TEST_CASE("marker shapes: sizes follow the scale factor", "[render][unit]") {
    const MarkerShape plus = markerShape(MarkerType::Plus, 2.0f);
    REQUIRE(plus.segments.size() == 4);
    CHECK(std::abs(plus.segments[1].x) == Approx(7.0f));
    CHECK(markerShape(MarkerType::Asterisk, 1).segments.size() == 8);
    CHECK(markerShape(MarkerType::Cross, 1).segments.size() == 4);
    CHECK(markerShape(MarkerType::Circle, 1).segments.size() >= 24);
    CHECK(markerShape(MarkerType::Dot, 1).triangles.size() == 6);
}

TEST_CASE("stroke font: Hershey glyphs load and lay out with PHIGS text attributes", "[render][unit]") {
    const StrokeFont& font = StrokeFont::forIndex(1);
    CHECK(font.glyph('A').strokes.size() == 3);
    CHECK(&font.glyph('\x01') == &font.glyph('?'));
    TextStyle style;
    style.height = 1.0;
    glm::dvec2 lo;
    glm::dvec2 hi = extentOf(layoutText(font, "HH", style), lo);
    CHECK(hi.y == Approx(1.0).margin(1e-9));  // cap height
    CHECK(lo.y == Approx(0.0).margin(1e-9));  // baseline
    CHECK(lo.x > 0.0);
    const double width = hi.x;
    style.expansion = 2.0f;
    hi = extentOf(layoutText(font, "HH", style), lo);
    CHECK(hi.x == Approx(2 * width).epsilon(0.01));
    style.expansion = 1.0f;
    style.horizontal = HorizontalAlignment::Right;
    style.vertical = VerticalAlignment::Top;
    hi = extentOf(layoutText(font, "HH", style), lo);
    CHECK(hi.x < 0.0);
    CHECK(hi.y < 0.0);
    style.horizontal = HorizontalAlignment::Normal;
    style.vertical = VerticalAlignment::Normal;
    style.upVector = {-1, 0};  // text runs upward
    hi = extentOf(layoutText(font, "HH", style), lo);
    CHECK(hi.y == Approx(width).epsilon(0.01));
    CHECK(lo.x == Approx(-1.0).margin(1e-9));
    style.upVector = {0, 1};
    style.path = TextPath::Down;
    hi = extentOf(layoutText(font, "HH", style), lo);
    CHECK(hi.y <= 1e-9);  // top aligned by default, characters stacked downward
    CHECK(lo.y < -2.0);
}

TEST_CASE("stroke font: a malformed font file is refused naming the file and line", "[render][unit]") {
    const auto path = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "bad_font.jhf";
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << "12345  9MWRFRT RRYQZR[SZRY\n12345 99MW\n";
    REQUIRE_THROWS_WITH(StrokeFont::load(path), Catch::Contains("bad_font.jhf") && Catch::Contains("line"));
    REQUIRE_THROWS_WITH(StrokeFont::load("/nonexistent/font.jhf"), Catch::Contains("hershey-fonts-data"));
}

TEST_CASE("stroke font: a PHIGS_HERSHEY_DIR without the font is named as the cause", "[render][unit]") {
    // It was reported as a missing Debian package, which installing would not have fixed.
    const char* before = std::getenv("PHIGS_HERSHEY_DIR");
    const std::string kept = before ? before : "";
    ::setenv("PHIGS_HERSHEY_DIR", "/nonexistent/fonts", 1);
    REQUIRE_THROWS_WITH(StrokeFont::fileFor(2),
                        Catch::Contains("futuram.jhf") &&
                            Catch::Contains("not found in PHIGS_HERSHEY_DIR (/nonexistent/fonts)"));
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hershey";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "scripts.jhf") << "";
    ::setenv("PHIGS_HERSHEY_DIR", dir.c_str(), 1);
    CHECK(StrokeFont::fileFor(4) == dir / "scripts.jhf");
    if (before)
        ::setenv("PHIGS_HERSHEY_DIR", kept.c_str(), 1);
    else
        ::unsetenv("PHIGS_HERSHEY_DIR");
    CHECK(StrokeFont::fileFor(1) ==
          std::filesystem::path(before ? kept : "/usr/share/hershey-fonts") / "futural.jhf");
}

TEST_CASE("describe: fill area sets, markers and patterned lines become world geometry", "[render][unit]") {
    DrawItem item;
    DrawFillArea fill;
    fill.contours = {{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}},
                     {{0.5, 0.5, 0}, {1.5, 0.5, 0}, {1.5, 1.5, 0}, {0.5, 1.5, 0}}};
    fill.interior.edit().style = InteriorStyle::Solid;
    fill.edges.edit().visible = true;
    item.primitive = fill;
    item.context.edit().modelTransform.edit()[3] = glm::dvec4(10, 0, 0, 1);  // translate by 10 in x
    const ItemGeometry g = describeItem(item, glm::dmat4(1.0));
    REQUIRE(g.parts.size() == 2);
    CHECK_FALSE(g.parts[0].lines);
    CHECK(g.parts[1].lines);
    CHECK(g.parts[1].count == 16);  // 8 edges, 2 vertices each
    double area = 0.0;
    for (std::uint32_t i = g.parts[0].first; i + 2 < g.parts[0].first + g.parts[0].count; i += 3) {
        const glm::vec3 a = g.vertices[i].position, b = g.vertices[i + 1].position,
                        c = g.vertices[i + 2].position;
        area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
        CHECK(a.x >= 10.0f);
        CHECK(g.vertices[i].normal.z == Approx(1.0f));
    }
    CHECK(area == Approx(3.0));

    DrawPolyline dashed;
    dashed.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    dashed.style.edit().type = LineType::Dashed;
    item.primitive = dashed;
    item.context.edit().modelTransform = glm::dmat4(1.0);
    const glm::dmat4 toPixels = glm::dmat4(100.0);
    const ItemGeometry lines =
        describeItem(item, glm::dmat4(glm::dvec4(100, 0, 0, 0), glm::dvec4(0, 100, 0, 0),
                                      glm::dvec4(0, 0, 1, 0), glm::dvec4(0, 0, 0, 1)));
    REQUIRE(lines.vertices.size() == 4);
    CHECK(lines.vertices[3].pattern == Approx(200.0f));  // measured on screen: two 100-pixel segments
    // The cache key follows the content, and for patterned lines the view too.
    CHECK(geometryKey(item, glm::dmat4(1.0)) != geometryKey(item, toPixels));
    item.primitive = DrawPolyline{dashed.points, {}};
    CHECK(geometryKey(item, glm::dmat4(1.0)) == geometryKey(item, toPixels));
}

TEST_CASE("describe: fill areas whose signed areas cancel are filled on their own plane", "[render][unit]") {
    // A bow-tie, and two equal squares wound against each other: Newell's normal sums signed
    // areas to nothing (or to rounding noise, under a rotation), though the even-odd rule fills
    // both; each is placed on random planes and must fill its area there.
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> c(-1.0, 1.0), angle(0.0, 6.283185307179586);
    struct Shape {
        std::vector<std::vector<glm::dvec3>> contours;
        double area;
    };
    const std::vector<Shape> shapes{
        {{{{0, 0, 0}, {0.3, 0.3, 0}, {0.3, 0, 0}, {0, 0.3, 0}}}, 2 * 0.5 * 0.3 * 0.15},
        {{{{0, 0, 0}, {0.25, 0, 0}, {0.25, 0.25, 0}, {0, 0.25, 0}},
          {{0.5, 0, 0}, {0.5, 0.25, 0}, {0.75, 0.25, 0}, {0.75, 0, 0}}},
         2 * 0.25 * 0.25},
        {{{{0.1, 0.1, 0}, {0.7, 0.1, 0}, {0.7, 0.6, 0}, {0.1, 0.6, 0}}}, 0.3}};
    for (int trial = 0; trial < 40; ++trial) {
        const Shape& shape = shapes[static_cast<std::size_t>(trial) % shapes.size()];
        const glm::dvec3 axis = glm::normalize(glm::dvec3(c(rng), c(rng), c(rng)) + glm::dvec3(0, 0, 1e-3));
        const glm::dmat4 model = glm::translate(glm::dmat4(1.0), {c(rng), c(rng), c(rng)}) *
                                 glm::rotate(glm::dmat4(1.0), angle(rng), axis);
        DrawItem item;
        DrawFillArea fill;
        fill.contours = shape.contours;
        fill.interior.edit().style = InteriorStyle::Solid;
        item.primitive = fill;
        item.context.edit().modelTransform.edit() = model;
        INFO("trial " << trial);
        const glm::dvec3 planeNormal = glm::normalize(glm::dvec3(model * glm::dvec4(0, 0, 1, 0)));
        const glm::dvec4 plane = fillAreaPlane(fill, model);
        CHECK(std::abs(glm::dot(glm::dvec3(plane), planeNormal)) == Approx(1.0).margin(1e-9));
        const ItemGeometry g = describeItem(item, glm::dmat4(1.0));
        REQUIRE(g.parts.size() == 1);
        double area = 0.0;
        for (std::uint32_t i = g.parts[0].first; i + 2 < g.parts[0].first + g.parts[0].count; i += 3) {
            const glm::dvec3 a(g.vertices[i].position), b(g.vertices[i + 1].position),
                c3(g.vertices[i + 2].position);
            area += 0.5 * glm::length(glm::cross(b - a, c3 - a));
        }
        CHECK(area == Approx(shape.area).epsilon(1e-4));
    }
}

TEST_CASE("describe: a vertex-coloured patterned polyline keeps one pattern along its whole length",
          "[render][unit]") {
    std::mt19937 rng(5821);
    std::uniform_real_distribution<double> real(-1.0, 1.0);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int round = 0; round < 100; ++round) {
        DrawColouredPolyline line;
        std::vector<glm::dvec3> points;
        std::vector<glm::vec3> colours;
        const int n = 2 + int(rng() % 9);
        for (int i = 0; i < n; ++i) {
            points.push_back({real(rng), real(rng), real(rng)});
            colours.push_back({unit(rng), unit(rng), unit(rng)});
        }
        line.line.points = points;
        line.colours = VertexColours{colours, rng() % 2 == 0};
        line.line.style.edit().type = static_cast<LineType>(2 + rng() % 3);
        DrawItem item;
        item.primitive = line;
        const double scale = 50.0 + 200.0 * unit(rng);
        const glm::dmat4 toPixels(glm::dvec4(scale, 0, 0, 0), glm::dvec4(0, scale, 0, 0),
                                  glm::dvec4(0, 0, 1, 0), glm::dvec4(0, 0, 0, 1));
        const ItemGeometry g = describeItem(item, toPixels);
        REQUIRE(g.parts.size() == 1);  // one part: the pattern does not start again per segment
        CHECK(g.parts[0].vertexColours);
        REQUIRE(g.vertices.size() == std::size_t(2 * (n - 1)));
        double distance = 0.0;
        for (int i = 0; i + 1 < n; ++i) {
            const RenderVertex &a = g.vertices[std::size_t(2 * i)], &b = g.vertices[std::size_t(2 * i + 1)];
            CHECK(a.pattern == Approx(distance).margin(1e-3));
            distance += scale * glm::length(glm::dvec2(points[std::size_t(i + 1)] - points[std::size_t(i)]));
            CHECK(b.pattern == Approx(distance).epsilon(1e-5));
            CHECK(a.colour == colours[std::size_t(i)]);
            CHECK(b.colour == colours[std::size_t(line.colours.interpolated ? i + 1 : i)]);
        }
        // Colours and shading belong to the cache key.
        const std::uint64_t key = geometryKey(item, toPixels);
        editPrimitive<DrawColouredPolyline>(item.primitive).colours.interpolated = !line.colours.interpolated;
        CHECK(geometryKey(item, toPixels) != key);
    }
}

TEST_CASE("mesh indices: triangles, iso-lines and unique edges, bad indices cannot overrun",
          "[render][unit]") {
    MeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.triangles = {0, 1, 2, 0, 2, 3};
    mesh.isoLines = {{0, 1, 2}};
    const MeshIndices m = meshIndices(mesh);
    CHECK(m.triangleCount == 6);
    CHECK(m.isoLineCount == 4);
    CHECK(m.edgeCount == 10);  // 5 unique edges
    // The iso-line runs through its own vertex copies (4, 5, 6), which carry the length along it.
    CHECK(std::vector<std::uint32_t>(m.indices.begin() + 6, m.indices.begin() + 10) ==
          std::vector<std::uint32_t>{4, 5, 5, 6});
    const auto vertices = meshVertices(mesh);
    REQUIRE(vertices.size() == 7);
    CHECK(vertices[5].position == glm::vec3(1, 0, 0));
    CHECK(vertices[4].pattern == 0.0f);
    CHECK(vertices[5].pattern == Approx(1.0f));
    CHECK(vertices[6].pattern == Approx(2.0f));
    mesh.triangles = {0, 1, 99};
    mesh.isoLines = {{0, 42}};
    for (std::uint32_t i : meshIndices(mesh).indices) CHECK(i < meshVertices(mesh).size());
}

TEST_CASE("mesh facet edges: no diagonal inside a facet, matched by index, sided copies", "[render][unit]") {
    // A 3 x 2 grid of quadrilaterals, two triangles each, the second quadrilateral with corners of
    // its own, which its two triangles share (as facet data makes them).
    MeshData mesh;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) mesh.positions.push_back({float(i), float(j), 0.0f});
    auto at = [](int i, int j) { return std::uint32_t(j * 4 + i); };
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i)
            mesh.triangles.insert(mesh.triangles.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                                         at(i + 1, j + 1), at(i, j + 1)});
    std::vector<std::uint32_t> triangles = mesh.triangles;
    std::map<std::uint32_t, std::uint32_t> own;
    for (int k = 6; k < 12; ++k) {
        const std::uint32_t i = triangles[std::size_t(k)];
        if (!own.count(i)) {
            own[i] = std::uint32_t(mesh.positions.size());
            mesh.positions.push_back(mesh.positions[i]);
        }
        triangles[std::size_t(k)] = own[i];
    }
    mesh.triangles = triangles;
    CHECK(meshFacetEdges(mesh) == std::vector<std::uint8_t>(12, 7));  // one triangle per facet
    mesh.trianglesPerFacet = 2;
    const std::vector<std::uint8_t> masks = meshFacetEdges(mesh);
    for (std::size_t t = 0; t < masks.size(); ++t) CHECK(int(masks[t]) == (t % 2 ? 6 : 3));
    // The facets as runs of their own: the first quadrilateral split into two facets.
    mesh.trianglesPerFacet = 1;
    mesh.facetEnds = {1, 2, 4, 6, 8, 10, 12};
    CHECK(int(meshFacetEdges(mesh)[0]) == 7);
    CHECK(int(meshFacetEdges(mesh)[2]) == 3);
    mesh.facetEnds.clear();
    mesh.trianglesPerFacet = 2;
    // Unique facet edges: 17 grid lines, the second quadrilateral's 3 it shares again (own corners).
    const MeshIndices m = meshIndices(mesh);
    CHECK(m.edgeCount == 2 * (3 * 3 + 4 * 2 + 3));
    const auto sided = meshSidedEdges(mesh);
    REQUIRE(sided.size() == 2 * 2 * 12);
    for (const RenderVertex& v : sided) {
        CHECK(v.normal == glm::vec3(0, 0, 1));  // each triangle's plane z = 0
        CHECK(v.pattern == 0.0f);
    }
    // Triangle 1 (0, 5, 4): its edges 5-4 and 4-0, not the diagonal 0-5.
    CHECK(sided[4].position == mesh.positions[5]);
    CHECK(sided[5].position == mesh.positions[4]);
    CHECK(sided[6].position == mesh.positions[4]);
    CHECK(sided[7].position == mesh.positions[0]);
    const auto vertices = meshVertices(mesh);
    for (std::uint32_t i : m.indices) CHECK(i < vertices.size());
}

TEST_CASE("mesh facet edges: a pole cell keeps its edge from the pole, whose corners coincide",
          "[render][unit]") {
    // A surface grid cell at a pole: corners 0 and 1 lie at one point, distinct vertices. Its
    // diagonal 0-3 goes; 1-3, at the same place but a grid line, stays.
    MeshData mesh;
    mesh.positions = {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.triangles = {0, 1, 3, 0, 3, 2};
    mesh.trianglesPerFacet = 2;
    CHECK(meshFacetEdges(mesh) == std::vector<std::uint8_t>{3, 6});
    CHECK(meshIndices(mesh).edgeCount == 2 * 4);
}

TEST_CASE("mesh viewer: an edge-on or degenerate triangle shows its front", "[render][unit]") {
    // Seen along z, the triangles in the plane x = 0 are edge on; a degenerate one has no plane.
    const glm::dvec4 viewer = meshViewer(glm::dmat4(1.0));
    CHECK(triangleSide({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, viewer) == 1);
    CHECK(triangleSide({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, viewer) == 1);
    CHECK(triangleSide({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, viewer) == 1);
    CHECK(triangleSide({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, viewer) == -1);
}

TEST_CASE("mesh viewer: the triangle side it sees is the NPC winding, mirrors included", "[render][unit]") {
    std::mt19937 rng(0x7e11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0, fronts = 0;
    for (int round = 0; round < 2000; ++round) {
        glm::dmat4 view(1.0);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) view[c][r] = unit(rng);
        if (round % 2) view[2][3] = -0.3 + 0.1 * unit(rng);  // a perspective divide (w = 1 - 0.3 z)
        glm::dmat4 model =
            glm::rotate(glm::dmat4(1.0), 3.0 * unit(rng), glm::dvec3(unit(rng), unit(rng), 1.0));
        if (round % 3 == 0) model = glm::scale(model, glm::dvec3(-1.0, 1.0, 1.0));
        const glm::dmat4 toNpc = view * model;
        const glm::dvec3 a(unit(rng), unit(rng), unit(rng)), b(unit(rng), unit(rng), unit(rng)),
            c(unit(rng), unit(rng), unit(rng));
        glm::dvec2 q[3];
        bool valid = true;
        const glm::dvec3 corners[3] = {a, b, c};
        for (int k = 0; k < 3; ++k) {
            const glm::dvec4 h = toNpc * glm::dvec4(corners[k], 1.0);
            valid = valid && h.w > 0.0;
            q[k] = glm::dvec2(h) / h.w;
        }
        const double winding = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
        if (!valid || std::abs(winding) < 1e-6) continue;
        ++checked;
        fronts += winding > 0;
        CHECK(triangleSide(a, b, c, meshViewer(toNpc)) == (winding > 0 ? 1 : -1));
    }
    CHECK(checked > 1000);
    CHECK(fronts > checked / 4);
    CHECK(fronts < 3 * checked / 4);
}

}  // namespace test_render_geometry
