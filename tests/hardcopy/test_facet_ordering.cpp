// orderBackToFront (hidden-surface removal by the painter's algorithm) on random classes of
// facets: whatever they are, the facet painted last at a page point is the nearest one there;
// facets whose depths do not interleave are painted whole, and facets free to come next keep the
// last one's colour.
#include "phigs/hardcopy/FacetOrdering.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <random>

namespace test_facet_ordering {

using namespace phigs::hardcopy;

namespace {

/// Facet k's colour: its index in the channels, so a painted piece names its facet.
glm::vec3 colourOf(std::size_t k) {
    return {float(k % 256) / 255.0f, float(k / 256) / 255.0f, 0.5f};
}

std::size_t facetOf(glm::vec3 colour) {
    return std::size_t(std::lround(colour.x * 255.0f)) + 256 * std::size_t(std::lround(colour.y * 255.0f));
}

ProjectedFacet triangle(const PagePoint& a, const PagePoint& b, const PagePoint& c, std::size_t k) {
    ProjectedFacet f;
    f.contours = {{a, b, c}};
    f.colour = colourOf(k);
    return f;
}

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

/// Even-odd containment of a page point in a facet's contours.
bool contains(const ProjectedFacet& f, glm::dvec2 p) {
    bool inside = false;
    for (const auto& c : f.contours)
        for (std::size_t i = 0; i < c.size(); ++i) {
            const glm::dvec2 a(c[i]), b(c[(i + 1) % c.size()]);
            if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
                inside = !inside;
        }
    return inside;
}

/// A triangle's depth over a page point inside it, and the point's distance from its edges.
void depthAndMargin(const ProjectedFacet& f, glm::dvec2 p, double& depth, double& margin) {
    const auto& c = f.contours[0];
    const glm::dvec2 a(c[0]), b(c[1]), d(c[2]);
    const double area = cross(b - a, d - a);
    const double wa = cross(b - p, d - p) / area, wb = cross(d - p, a - p) / area, wd = 1.0 - wa - wb;
    depth = wa * c[0].z + wb * c[1].z + wd * c[2].z;
    margin = 1e300;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 s(c[std::size_t(i)]), e(c[std::size_t((i + 1) % 3)]);
        const double t = std::clamp(glm::dot(p - s, e - s) / glm::dot(e - s, e - s), 0.0, 1.0);
        margin = std::min(margin, glm::length(p - (s + t * (e - s))));
    }
}

/// Checks, at random page points clear of edges and of places where two facets meet in depth,
/// that the facet painted last there is the nearest; returns how many points were checked.
int checkNearestShows(const std::vector<ProjectedFacet>& facets, const std::vector<ProjectedFacet>& painted,
                      std::mt19937& random) {
    std::uniform_real_distribution<double> page(0.0, 100.0);
    int checked = 0;
    for (int s = 0; s < 400; ++s) {
        const glm::dvec2 p(page(random), page(random));
        double best = -1e300, second = -1e300, clear = 1e300;
        std::size_t nearest = facets.size();
        for (std::size_t k = 0; k < facets.size(); ++k) {
            if (!contains(facets[k], p)) continue;
            double depth = 0.0, margin = 0.0;
            depthAndMargin(facets[k], p, depth, margin);
            clear = std::min(clear, margin);
            if (depth > best)
                second = best, best = depth, nearest = k;
            else
                second = std::max(second, depth);
        }
        if (nearest == facets.size() || clear < 1e-3 || best - second < 1e-6) continue;
        std::size_t shown = facets.size();
        for (const ProjectedFacet& f : painted)
            if (contains(f, p)) shown = facetOf(f.colour);
        INFO("page point " << p.x << ", " << p.y);
        CHECK(shown == nearest);
        ++checked;
    }
    return checked;
}

/// A random triangle over the page square, its corners' depths from `depth`.
template <class Depth>
ProjectedFacet randomTriangle(std::mt19937& random, std::size_t k, Depth depth) {
    std::uniform_real_distribution<double> centre(10.0, 90.0), size(5.0, 40.0), turn(0.0, 6.283185307);
    const glm::dvec2 c(centre(random), centre(random));
    const double r = size(random), a = turn(random);
    PagePoint corners[3];
    for (int i = 0; i < 3; ++i) {
        const double angle = a + 2.0943951 * i + 0.5 * (turn(random) / 6.283185307 - 0.5);
        corners[i] = {c.x + r * std::cos(angle), c.y + r * std::sin(angle), depth()};
    }
    return triangle(corners[0], corners[1], corners[2], k);
}

}  // namespace

TEST_CASE("facet ordering: the nearest facet shows wherever random facets pierce and cycle", "[hardcopy]") {
    std::size_t splits = 0;
    for (std::uint32_t seed = 1; seed <= 30; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const std::size_t count = 2 + random() % 40;
        std::vector<ProjectedFacet> facets;
        for (std::size_t k = 0; k < count; ++k)
            facets.push_back(randomTriangle(random, k, [&] { return unit(random); }));
        FacetOrderStats stats;
        const std::vector<ProjectedFacet> painted = orderBackToFront(facets, 100.0, &stats);
        INFO("seed " << seed << ", " << count << " facets");
        CHECK(stats.input == count);
        CHECK(stats.output == painted.size());
        CHECK_FALSE(stats.fellBack);
        CHECK(checkNearestShows(facets, painted, random) > 0);
        splits += stats.splits;
    }
    CHECK(splits > 0);  // the class does hold facets no whole order fits
}

TEST_CASE("facet ordering: tilted facets whose depths do not interleave are painted whole", "[hardcopy]") {
    for (std::uint32_t seed = 1; seed <= 30; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const std::size_t count = 2 + random() % 40;
        // Facet k lies in a slab of depths of its own, in random order, each steeply tilted: its
        // plane runs through the slabs of the others, as a BSP tree's splitting planes would.
        std::vector<std::size_t> slab(count);
        for (std::size_t k = 0; k < count; ++k) slab[k] = k;
        std::shuffle(slab.begin(), slab.end(), random);
        std::vector<ProjectedFacet> facets;
        for (std::size_t k = 0; k < count; ++k)
            facets.push_back(randomTriangle(random, k, [&] { return double(slab[k]) + 0.9 * unit(random); }));
        FacetOrderStats stats;
        const std::vector<ProjectedFacet> painted = orderBackToFront(facets, 100.0, &stats);
        INFO("seed " << seed << ", " << count << " facets");
        CHECK(stats.splits == 0);
        CHECK(stats.clusters == 0);
        CHECK(painted.size() == count);
        checkNearestShows(facets, painted, random);
    }
}

TEST_CASE("facet ordering: facets free to come next keep the last one's colour", "[hardcopy]") {
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        // Two meshes of touching triangles in two colours, one wholly behind the other, each
        // triangle overlapping some of the other mesh's: one run of each colour fits.
        const int n = 2 + int(random() % 6);
        const double shift = 20.0 * unit(random), tilt = unit(random);
        std::vector<ProjectedFacet> facets;
        const glm::vec3 colours[2] = {{1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
        for (int mesh = 0; mesh < 2; ++mesh)
            for (int r = 0; r < n; ++r)
                for (int c = 0; c < n; ++c) {
                    const double x = 10.0 + 80.0 * c / n + mesh * shift,
                                 y = 10.0 + 80.0 * r / n + mesh * shift;
                    const double step = 80.0 / n;
                    auto at = [&](double px, double py) {
                        return PagePoint(px, py, (mesh == 0 ? 2.0 : 0.0) + tilt * px / 100.0);
                    };
                    for (int half = 0; half < 2; ++half) {
                        ProjectedFacet f =
                            half == 0 ? triangle(at(x, y), at(x + step, y), at(x, y + step), 0)
                                      : triangle(at(x + step, y), at(x + step, y + step), at(x, y + step), 0);
                        f.colour = colours[mesh];
                        facets.push_back(std::move(f));
                    }
                }
        // Interleaved in traversal order, so that only the ordering can make the runs.
        std::shuffle(facets.begin(), facets.end(), random);
        FacetOrderStats stats;
        const std::vector<ProjectedFacet> painted = orderBackToFront(facets, 100.0, &stats);
        INFO("seed " << seed);
        REQUIRE(painted.size() == facets.size());
        CHECK(stats.splits == 0);
        int changes = 0;
        for (std::size_t i = 1; i < painted.size(); ++i)
            changes += painted[i].colour != painted[i - 1].colour;
        CHECK(changes == 1);
        CHECK(painted.front().colour == colours[1]);  // the mesh behind first
    }
}

TEST_CASE("facet ordering: a pile of layers each over all the others is ordered in bounded room",
          "[hardcopy]") {
    // 1,600 large layers each overlap all the others: 1.3M pairs, past the pairs' budget, so one
    // BSP tree orders them; the layers keep to slabs of depth, so whatever it does is right.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<ProjectedFacet> facets;
    const std::size_t count = 1600;
    for (std::size_t k = 0; k < count; ++k) {
        const double z = double((k * 7919) % count), x = 5.0 * unit(random), y = 5.0 * unit(random);
        facets.push_back(triangle({x, y, z + 0.5 * unit(random)}, {x + 150.0, y + 10.0 * unit(random), z},
                                  {x + 10.0 * unit(random), y + 150.0, z + 0.5 * unit(random)}, k));
    }
    FacetOrderStats stats;
    const std::vector<ProjectedFacet> painted = orderBackToFront(facets, 100.0, &stats);
    CHECK(stats.clusters == 1);
    CHECK(stats.output == painted.size());
    CHECK(checkNearestShows(facets, painted, random) > 300);
}

}  // namespace test_facet_ordering
