// unionOutline (the painter's runs of one colour as one outline): for random patches of a
// jittered triangle mesh, with overlapping triangles thrown in, the loops' non-zero winding
// covers exactly the union of the triangles, and shared edges are gone.
#include "phigs/hardcopy/UnionOutline.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <array>
#include <random>

namespace test_union_outline {

using namespace phigs::hardcopy;

namespace {

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

/// The winding number of closed loops round a point.
int winding(const std::vector<std::vector<glm::dvec2>>& loops, glm::dvec2 p) {
    int w = 0;
    for (const auto& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const glm::dvec2 a = loop[i], b = loop[(i + 1) % loop.size()];
            if (a.y <= p.y && b.y > p.y && cross(b - a, p - a) > 0) ++w;
            if (a.y > p.y && b.y <= p.y && cross(b - a, p - a) < 0) --w;
        }
    return w;
}

/// Distance from p to a segment.
double distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
    return glm::length(p - (a + t * (b - a)));
}

}  // namespace

TEST_CASE("union outline: loops cover the union of random mesh patches and overlaps", "[hardcopy]") {
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const int columns = 2 + int(random() % 8), rows = 2 + int(random() % 8);
        std::vector<glm::dvec2> grid;
        for (int r = 0; r <= rows; ++r)
            for (int c = 0; c <= columns; ++c)
                grid.emplace_back(c + 0.3 * (unit(random) - 0.5), r + 0.3 * (unit(random) - 0.5));
        auto at = [&](int c, int r) { return grid[std::size_t(r * (columns + 1) + c)]; };
        std::vector<std::array<glm::dvec2, 3>> triangles;
        const double keep = 0.3 + 0.7 * unit(random);
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < columns; ++c) {
                const glm::dvec2 a = at(c, r), b = at(c + 1, r), d = at(c + 1, r + 1), e = at(c, r + 1);
                // Either diagonal; counter-clockwise (x right, y up).
                const bool flip = random() % 2;
                const std::array<glm::dvec2, 3> one = flip ? std::array{a, b, e} : std::array{a, b, d};
                const std::array<glm::dvec2, 3> two = flip ? std::array{b, d, e} : std::array{a, d, e};
                if (unit(random) < keep) triangles.push_back(one);
                if (unit(random) < keep) triangles.push_back(two);
            }
        for (int k = 0; k < 3; ++k) {  // overlapping strays, counter-clockwise
            std::array<glm::dvec2, 3> t{glm::dvec2(unit(random) * columns, unit(random) * rows),
                                        glm::dvec2(unit(random) * columns, unit(random) * rows),
                                        glm::dvec2(unit(random) * columns, unit(random) * rows)};
            if (cross(t[1] - t[0], t[2] - t[0]) < 0) std::swap(t[1], t[2]);
            triangles.push_back(t);
        }
        std::vector<std::vector<glm::dvec2>> contours;
        for (const auto& t : triangles) contours.push_back({t[0], t[1], t[2]});
        std::vector<const std::vector<glm::dvec2>*> input;
        for (const auto& c : contours) input.push_back(&c);
        const auto loops = unionOutline(input);
        std::size_t points = 0;
        for (const auto& loop : loops) points += loop.size();
        INFO("seed " << seed << ": " << triangles.size() << " triangles, " << loops.size() << " loops");
        CHECK(points < 3 * triangles.size());
        int checked = 0;
        for (int s = 0; s < 2000; ++s) {
            const glm::dvec2 p(unit(random) * columns, unit(random) * rows);
            bool inside = false, near = false;
            for (const auto& t : triangles) {
                bool in = true;
                for (int i = 0; i < 3; ++i) {
                    in = in && cross(t[(i + 1) % 3] - t[i], p - t[i]) > 0;
                    near = near || distance(p, t[i], t[(i + 1) % 3]) < 1e-6;
                }
                inside = inside || in;
            }
            if (near) continue;
            ++checked;
            CHECK((winding(loops, p) != 0) == inside);
        }
        CHECK(checked > 1900);
    }
}

TEST_CASE("union outline: a whole mesh is one loop round its border", "[hardcopy]") {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int columns = 6, rows = 4;
    std::vector<glm::dvec2> grid;
    for (int r = 0; r <= rows; ++r)
        for (int c = 0; c <= columns; ++c) grid.emplace_back(c + 0.2 * unit(random), r + 0.2 * unit(random));
    auto at = [&](int c, int r) { return grid[std::size_t(r * (columns + 1) + c)]; };
    std::vector<std::vector<glm::dvec2>> contours;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            contours.push_back({at(c, r), at(c + 1, r), at(c + 1, r + 1)});
            contours.push_back({at(c, r), at(c + 1, r + 1), at(c, r + 1)});
        }
    std::vector<const std::vector<glm::dvec2>*> input;
    for (const auto& c : contours) input.push_back(&c);
    const auto loops = unionOutline(input);
    REQUIRE(loops.size() == 1);
    CHECK(loops[0].size() == std::size_t(2 * (columns + rows)));
}

}  // namespace test_union_outline
