// The occlusion index of the vector hardcopy against its own definition: a facet is hidden whole
// when a triangle hides its centre and every edge, taken the margin inside, is hidden along all of
// its length by the triangles together. The index shortens its queries with the triangles that hid
// the facet before (hints carried from facet to facet, parts of an edge queried alone); the
// answers must be those of asking every triangle.
#include "phigs/hardcopy/OcclusionIndex.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>

namespace test_occlusion_index {

using namespace phigs::hardcopy;

namespace {

/// The definition, through the queries that take no hints: the centre not visible, and no visible
/// part on any edge moved the margin towards the centre (at most a tenth of the way).
bool hiddenByDefinition(const OcclusionIndex& index, const ProjectedFacet& facet, double margin) {
    PagePoint centre(0.0);
    std::size_t count = 0;
    for (const auto& c : facet.contours)
        for (const PagePoint& p : c) centre += p, ++count;
    centre /= double(count);
    if (index.visible(centre)) return false;
    auto inside = [&](const PagePoint& p) {
        const double distance = glm::length(glm::dvec2(centre - p));
        return distance > 0.0 ? p + (centre - p) * std::min(0.1, margin / distance) : p;
    };
    for (const auto& c : facet.contours)
        for (std::size_t i = 0; i < c.size(); ++i)
            if (!index.visibleParts(inside(c[i]), inside(c[(i + 1) % c.size()])).empty()) return false;
    return true;
}

/// A strip of triangles across the page at a depth, tilted a little: neighbours in order, as a
/// mesh gives them, so hints carry from one facet to the next.
void addStrip(std::vector<ProjectedFacet>& facets, std::mt19937& random, double depth) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double y0 = 10.0 + 80.0 * unit(random), height = 2.0 + 10.0 * unit(random);
    const double tilt = 0.002 * (unit(random) - 0.5), step = 1.0 + 4.0 * unit(random);
    auto at = [&](double x, double y) { return PagePoint(x, y, depth + tilt * (x - 50.0)); };
    for (double x = 5.0 * unit(random); x + step < 100.0; x += step) {
        ProjectedFacet lower, upper;
        lower.contours = {{at(x, y0), at(x + step, y0), at(x, y0 + height)}};
        upper.contours = {{at(x + step, y0), at(x + step, y0 + height), at(x, y0 + height)}};
        facets.push_back(std::move(lower));
        facets.push_back(std::move(upper));
    }
}

}  // namespace

TEST_CASE("occlusion index: hidden facets are those the definition hides, whatever came before",
          "[hardcopy]") {
    std::size_t hidden = 0, shown = 0;
    for (std::uint32_t seed = 1; seed <= 12; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> depth(0.0, 1.0);
        std::vector<ProjectedFacet> facets;
        for (int strip = 0; strip < 14; ++strip) addStrip(facets, random, depth(random));
        // A few loose triangles of any shape and slope among them.
        std::uniform_real_distribution<double> coordinate(0.0, 100.0);
        for (int t = 0; t < 40; ++t) {
            ProjectedFacet loose;
            loose.contours = {{}};
            for (int k = 0; k < 3; ++k)
                loose.contours[0].push_back({coordinate(random), coordinate(random), depth(random)});
            facets.push_back(std::move(loose));
        }
        const double pixel = 0.5, margin = 0.25 * pixel;
        const OcclusionIndex index(facets, pixel);
        // In the facets' order, then shuffled: the hints carried differ, the answers may not.
        std::vector<std::size_t> order(facets.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        for (int pass = 0; pass < 2; ++pass) {
            if (pass == 1) std::shuffle(order.begin(), order.end(), random);
            for (std::size_t i : order) {
                const bool expected = hiddenByDefinition(index, facets[i], margin);
                REQUIRE(index.hidden(facets[i], margin) == expected);
                (expected ? hidden : shown)++;
            }
        }
    }
    // Both answers are common: the test says something about each.
    CHECK(hidden > 1000);
    CHECK(shown > 1000);
}

TEST_CASE("occlusion index: a facet seen through a hole in what hides its outline shows", "[hardcopy]") {
    // A square frame in front ([10, 90]^2 less [45, 55]^2, four trapezoids of two triangles) hides
    // a small facet behind its band, then a large one whose outline lies under the band and whose
    // centre lies behind the hole: the hints the small one leaves must not hide the large one.
    auto flat = [](std::vector<glm::dvec2> corners, double depth) {
        ProjectedFacet f;
        f.contours = {{}};
        for (glm::dvec2 c : corners) f.contours[0].push_back(PagePoint(c, depth));
        return f;
    };
    std::vector<ProjectedFacet> facets;
    const glm::dvec2 outer[4] = {{10, 10}, {90, 10}, {90, 90}, {10, 90}};
    const glm::dvec2 inner[4] = {{45, 45}, {55, 45}, {55, 55}, {45, 55}};
    for (int side = 0; side < 4; ++side) {
        const int next = (side + 1) % 4;
        facets.push_back(flat({outer[side], outer[next], inner[next]}, 0.9));
        facets.push_back(flat({outer[side], inner[next], inner[side]}, 0.9));
    }
    const ProjectedFacet small = flat({{20, 20}, {30, 20}, {20, 30}}, 0.2);
    const ProjectedFacet large = flat({{15, 70}, {85, 70}, {50, 10}}, 0.2);  // centre (50, 50)
    facets.push_back(small);
    facets.push_back(large);
    const double margin = 0.125;
    const OcclusionIndex index(facets, 0.5);
    CHECK(index.hidden(small, margin));
    CHECK_FALSE(index.hidden(large, margin));
    CHECK_FALSE(hiddenByDefinition(index, large, margin));
    CHECK(index.visibleParts({15, 70, 0.2}, {85, 70, 0.2}).empty());  // its outline is hidden
}

TEST_CASE("occlusion index: hidden facets keep the full query's answer where hiders nearly meet",
          "[hardcopy]") {
    // Two rectangles in front, each of two triangles, leave a slit 8e-9 points wide across the
    // bottom edge of a facet behind them: 8e-10 of the edge, inside the cover test's 1e-9 slack,
    // so the full query calls the edge hidden. The centre's hiders cover the edge's left half; the
    // rest is queried alone and must be judged on the whole edge's parameter as well.
    auto flat = [](std::vector<glm::dvec2> corners, double depth) {
        ProjectedFacet f;
        f.contours = {{}};
        for (glm::dvec2 c : corners) f.contours[0].push_back(PagePoint(c, depth));
        return f;
    };
    auto rectangle = [&](std::vector<ProjectedFacet>& out, glm::dvec2 lo, glm::dvec2 hi) {
        out.push_back(flat({lo, {hi.x, lo.y}, hi}, 1.0));
        out.push_back(flat({lo, hi, {lo.x, hi.y}}, 1.0));
    };
    std::vector<ProjectedFacet> facets;
    rectangle(facets, {-100, -100}, {5, 100});
    rectangle(facets, {5 + 8e-9, -100}, {100, 100});
    const ProjectedFacet behind = flat({{0, 0}, {10, 0}, {0, 10}}, 0.0);
    facets.push_back(behind);
    const OcclusionIndex index(facets, 1.0);
    REQUIRE(hiddenByDefinition(index, behind, 0.0));
    CHECK(index.hidden(behind, 0.0));
    // A facet with a point off the page is not known to be hidden (and is no trouble to test).
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(index.hidden(flat({{1, 1}, {2, 1}, {nan, 2}}, 0.0), 0.0));
    CHECK_FALSE(index.hidden(flat({{1, 1}, {2, 1}, {1e300, 2}}, 0.0), 0.0));
}

}  // namespace test_occlusion_index
