// Consecutive opaque fills of one colour are written as one path (CairoPainter): the page must
// show what painting them one by one shows, whatever their orientation and overlaps.
#include "VectorRaster.h"
#include "phigs/hardcopy/VectorDescriber.h"
#include "phigs/hardcopy/VectorWorkstation.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

namespace test_vector_fill_runs {

using namespace phigs;
using namespace phigs::hardcopy;

namespace {

using Triangle = std::array<glm::dvec2, 3>;

/// Signed distance from p to a triangle in NPC: negative inside.
double signedDistance(const Triangle& t, glm::dvec2 p) {
    const double area = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x);
    double inside = -1e300, outside = 1e300;
    bool in = true;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 a = t[i], b = t[(i + 1) % 3], e = b - a;
        const double side =
            (area > 0 ? 1.0 : -1.0) * (e.x * (p.y - a.y) - e.y * (p.x - a.x)) / glm::length(e);
        in = in && side >= 0.0;
        inside = std::max(inside, -side);
        const double s = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
        outside = std::min(outside, glm::length(p - (a + s * e)));
    }
    return in ? inside : outside;
}

}  // namespace

TEST_CASE("vector hardcopy: runs of one colour show the union of their fills, in painting order",
          "[hardcopy]") {
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hardcopy";
    std::filesystem::create_directories(dir);
    constexpr std::uint32_t kSize = 200;
    const glm::vec3 first(0.9f, 0.2f, 0.1f), second(0.1f, 0.3f, 0.9f), background(0.0f);
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> at(0.1, 0.9);
        // Two runs of overlapping triangles, either way round; the second paints over the first.
        std::vector<std::pair<Triangle, glm::vec3>> triangles;
        DrawList list;
        list.views.push_back(DrawView{});
        list.background = background;
        for (int i = 0; i < 16; ++i) {
            Triangle t{glm::dvec2(at(random), at(random)), glm::dvec2(at(random), at(random)),
                       glm::dvec2(at(random), at(random))};
            const glm::vec3 colour = i < 10 ? first : second;
            triangles.emplace_back(t, colour);
            DrawFillArea fill;
            fill.contours = {{{t[0], 0.5}, {t[1], 0.5}, {t[2], 0.5}}};
            fill.interior.edit().style = InteriorStyle::Solid;
            fill.interior.edit().colour = colour;
            DrawItem item;
            item.primitive = std::move(fill);
            list.items.push_back(std::move(item));
        }
        const auto file = dir / ("fill_runs_" + std::to_string(seed) + ".pdf");
        {
            PageSetup page;
            page.paper = {double(kSize), double(kSize)};
            page.nominalPixel = 1.0;
            VectorWorkstation ws(file, VectorFormat::Pdf, page);
            ws.update(list);
        }
        const Image image = vector_test::rasterisePdf(file, kSize, kSize);
        // Pixels two pixels or more from every edge: the colour of the last triangle over them.
        const double margin = 2.0 / kSize;
        int checked = 0, overlapped = 0;
        for (std::uint32_t y = 0; y < kSize; ++y)
            for (std::uint32_t x = 0; x < kSize; ++x) {
                const glm::dvec2 p((x + 0.5) / kSize, 1.0 - (y + 0.5) / kSize);
                glm::vec3 expected = background;
                bool clear = true;
                int over = 0;
                for (const auto& [t, colour] : triangles) {
                    const double d = signedDistance(t, p);
                    clear = clear && std::abs(d) >= margin;
                    if (d < 0) expected = colour, ++over;
                }
                if (!clear) continue;
                ++checked;
                overlapped += over > 1;
                const std::uint8_t* pixel = image.pixel(x, y);
                INFO("seed " << seed << " pixel " << x << ", " << y);
                for (int c = 0; c < 3; ++c)
                    CHECK(std::abs(int(pixel[c]) - int(expected[c] * 255.0f + 0.5f)) <= 3);
            }
        CHECK(checked > int(kSize * kSize / 2));
        CHECK(overlapped > 100);
    }
}

namespace {

/// A draw list of one SOLID mesh in the identity view.
DrawList solidMesh(std::shared_ptr<const MeshData> mesh) {
    DrawList list;
    list.views.push_back(DrawView{});
    DrawMesh m;
    m.mesh = std::move(mesh);
    m.interior.edit().style = InteriorStyle::Solid;
    DrawItem item;
    item.primitive = std::move(m);
    list.items.push_back(std::move(item));
    return list;
}

/// Distance from p to a convex polygon, 0 inside.
double distanceOutside(const std::vector<glm::dvec2>& c, glm::dvec2 p) {
    double area = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i)
        area += c[i].x * c[(i + 1) % c.size()].y - c[(i + 1) % c.size()].x * c[i].y;
    bool in = true;
    double outside = 1e300;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const glm::dvec2 a = c[i], e = c[(i + 1) % c.size()] - a;
        in = in && (area > 0 ? 1.0 : -1.0) * (e.x * (p.y - a.y) - e.y * (p.x - a.x)) >= 0.0;
        const double s = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
        outside = std::min(outside, glm::length(p - (a + s * e)));
    }
    return in ? 0.0 : outside;
}

}  // namespace

TEST_CASE("vector hardcopy: a seamed facet covers what its fill and outline stroke cover", "[hardcopy]") {
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hardcopy";
    std::filesystem::create_directories(dir);
    constexpr std::uint32_t kSize = 200;
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> at(0.1, 0.9);
        std::uniform_real_distribution<float> channel(0.0f, 1.0f);
        // Mesh triangles of colours of their own (no runs), each facet seamed; overlapping.
        auto mesh = std::make_shared<MeshData>();
        for (std::uint32_t t = 0; t < 12; ++t) {
            std::array<glm::vec3, 3> p;
            for (auto& q : p) q = glm::vec3(at(random), at(random), 0.5);
            if (glm::cross(p[1] - p[0], p[2] - p[0]).z < 0.0f) std::swap(p[1], p[2]);
            const glm::vec3 colour(channel(random), channel(random), channel(random));
            for (const auto& q : p) mesh->positions.push_back(q), mesh->colours.push_back(colour);
            mesh->triangles.insert(mesh->triangles.end(), {3 * t, 3 * t + 1, 3 * t + 2});
        }
        const DrawList list = solidMesh(mesh);
        PageSetup page;
        page.paper = {double(kSize), double(kSize)};
        page.nominalPixel = 8.0;  // seams 4 points wide: far wider than the raster's pixels
        const VectorPicture picture = describePicture(list, page);
        const auto file = dir / ("seamed_facets_" + std::to_string(seed) + ".pdf");
        {
            VectorWorkstation ws(file, VectorFormat::Pdf, page);
            ws.update(list);
        }
        const Image image = vector_test::rasterisePdf(file, kSize, kSize);
        // Page points are pixels here. Each pixel away from every seam's outer edge and from every
        // corner (where the stroke's round join and a grown outline part) shows the last facet
        // within half a seam of it.
        int checked = 0, seamed = 0;
        for (std::uint32_t y = 0; y < kSize; ++y)
            for (std::uint32_t x = 0; x < kSize; ++x) {
                const glm::dvec2 p(x + 0.5, y + 0.5);
                glm::vec3 expected = list.background;
                bool clear = true, inSeam = false;
                for (const VectorOp& op : picture.ops) {
                    const auto* fill = std::get_if<VectorFill>(&op);
                    if (!fill) continue;
                    REQUIRE(fill->seamWidth > 0.0);
                    const auto& c = fill->contours.at(0);
                    const double half = 0.5 * fill->seamWidth, d = distanceOutside(c, p);
                    clear = clear && std::abs(d - half) >= 1.5;
                    for (const glm::dvec2& corner : c) clear = clear && glm::length(p - corner) >= 3.0 * half;
                    if (d < half) expected = fill->colour, inSeam = d > 0.0;
                }
                if (!clear) continue;
                ++checked;
                seamed += inSeam;
                const std::uint8_t* pixel = image.pixel(x, y);
                INFO("seed " << seed << " pixel " << x << ", " << y);
                for (int c = 0; c < 3; ++c)
                    CHECK(std::abs(int(pixel[c]) - int(expected[c] * 255.0f + 0.5f)) <= 3);
            }
        CHECK(checked > int(kSize * kSize / 2));
        CHECK(seamed > 100);
    }
}

TEST_CASE("vector hardcopy: a star in a run of one colour keeps its even-odd hole", "[hardcopy]") {
    // A pentagram turns one way only, through 4 pi: it is not convex, and its centre is outside
    // under the even-odd rule however many fills of its colour come before or after it.
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hardcopy";
    std::filesystem::create_directories(dir);
    constexpr std::uint32_t kSize = 200;
    const glm::vec3 colour(0.2f, 0.8f, 0.3f);
    const glm::dvec2 centre(0.5, 0.5);
    DrawList list;
    list.views.push_back(DrawView{});
    auto addFill = [&](std::vector<glm::dvec3> contour) {
        DrawFillArea fill;
        fill.contours = {std::move(contour)};
        fill.interior.edit().style = InteriorStyle::Solid;
        fill.interior.edit().colour = colour;
        DrawItem item;
        item.primitive = std::move(fill);
        list.items.push_back(std::move(item));
    };
    addFill({{0.02, 0.02, 0.5}, {0.12, 0.02, 0.5}, {0.12, 0.12, 0.5}});
    std::vector<glm::dvec3> star;
    for (int i = 0; i < 5; ++i) {
        const double a = 2.0 * std::numbers::pi * (2 * i) / 5.0 + std::numbers::pi / 2.0;
        star.emplace_back(centre.x + 0.4 * std::cos(a), centre.y + 0.4 * std::sin(a), 0.5);
    }
    addFill(star);
    addFill({{0.88, 0.02, 0.5}, {0.98, 0.02, 0.5}, {0.98, 0.12, 0.5}});
    const auto file = dir / "fill_runs_star.pdf";
    {
        PageSetup page;
        page.paper = {double(kSize), double(kSize)};
        page.nominalPixel = 1.0;
        VectorWorkstation ws(file, VectorFormat::Pdf, page);
        ws.update(list);
    }
    const Image image = vector_test::rasterisePdf(file, kSize, kSize);
    auto at = [&](glm::dvec2 p) {
        return image.pixel(std::uint32_t(p.x * kSize), std::uint32_t((1.0 - p.y) * kSize));
    };
    const std::uint8_t* hole = at(centre);
    for (int c = 0; c < 3; ++c) CHECK(int(hole[c]) <= 3);
    // A star point is filled.
    const std::uint8_t* tip = at(centre + glm::dvec2(0.0, 0.33));
    CHECK(std::abs(int(tip[1]) - int(colour.y * 255.0f + 0.5f)) <= 3);
}

TEST_CASE("vector hardcopy: the seam of a run's outline runs along every side, the closing one too",
          "[hardcopy]") {
    // Two mesh triangles of one colour make a square, painted as a run: one outline with a seam
    // stroke. A fill closes its outline itself, a stroke only when told. Just outside the middle of
    // each side (whichever the outline closes on), within half a seam, the square's colour shows; a
    // little farther, the background.
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hardcopy";
    std::filesystem::create_directories(dir);
    constexpr std::uint32_t kSize = 200;
    const glm::vec3 colour(0.8f, 0.3f, 0.1f);
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {{0.3f, 0.3f, 0.5f}, {0.7f, 0.3f, 0.5f}, {0.7f, 0.7f, 0.5f}, {0.3f, 0.7f, 0.5f}};
    mesh->colours.assign(4, colour);
    mesh->triangles = {0, 1, 2, 0, 2, 3};
    const DrawList list = solidMesh(mesh);
    PageSetup page;
    page.paper = {double(kSize), double(kSize)};
    page.nominalPixel = 8.0;  // seams 4 points wide
    // A run: two seamed fills of the colour, one after the other.
    const VectorPicture picture = describePicture(list, page);
    REQUIRE(picture.ops.size() == 2);
    for (const VectorOp& op : picture.ops) {
        const auto* fill = std::get_if<VectorFill>(&op);
        REQUIRE(fill);
        CHECK(fill->colour == colour);
        CHECK(fill->seamWidth > 0.0);
    }
    const auto file = dir / "seamed_square.pdf";
    {
        VectorWorkstation ws(file, VectorFormat::Pdf, page);
        ws.update(list);
    }
    const Image image = vector_test::rasterisePdf(file, kSize, kSize);
    // The square covers page points 60..140 each way; pixel (x, y) covers [x, x + 1) points.
    const int middle = 100;
    const std::array<std::array<int, 2>, 4> seam{{{middle, 58}, {141, middle}, {middle, 141}, {58, middle}}};
    const std::array<std::array<int, 2>, 4> beyond{
        {{middle, 55}, {144, middle}, {middle, 144}, {55, middle}}};
    for (int side = 0; side < 4; ++side) {
        INFO("side " << side);
        const std::uint8_t* in = image.pixel(std::uint32_t(seam[side][0]), std::uint32_t(seam[side][1]));
        const std::uint8_t* out = image.pixel(std::uint32_t(beyond[side][0]), std::uint32_t(beyond[side][1]));
        for (int c = 0; c < 3; ++c) {
            CHECK(std::abs(int(in[c]) - int(colour[c] * 255.0f + 0.5f)) <= 3);
            CHECK(int(out[c]) <= 3);  // the black background
        }
    }
}

}  // namespace test_vector_fill_runs
