#include "acsynt/Model.h"
#include "acsynt/ModelFile.h"

#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace test_loft {

using namespace acsynt;

namespace {

const Model& transport() {
    static const Model m = loadModel(ACSYNT_DATA_DIR "/transport.acm");
    return m;
}

const Model& fighter() {
    static const Model m = loadModel(ACSYNT_DATA_DIR "/fighter.acm");
    return m;
}

}  // namespace

TEST_CASE("every lofted surface passes through every section point", "[acsynt][loft]") {
    for (const Model* m : {&transport(), &fighter()})
        for (const Component& c : m->components) {
            INFO(m->name << " / " << c.name);
            const SectionGrid& g = c.sections;
            REQUIRE(c.sectionParameters.size() == g.sectionCount);
            REQUIRE(c.pointParameters.size() == g.pointsPerSection + (c.closedW ? 1 : 0));
            for (std::size_t i = 0; i < g.sectionCount; ++i)
                for (std::size_t j = 0; j < g.pointsPerSection; ++j)
                    REQUIRE(
                        glm::distance(geom::evaluate(c.surface, c.sectionParameters[i], c.pointParameters[j]),
                                      g.at(i, j)) < 1e-9);
        }
}

TEST_CASE("closed components are periodic and C2 across the seam", "[acsynt][loft]") {
    int closed = 0;
    for (const Model* m : {&transport(), &fighter()})
        for (const Component& c : m->components) {
            const geom::Surface& s = c.surface;
            REQUIRE(s.degreeU == 3);
            REQUIRE(s.degreeV == 3);
            if (!c.closedW) {
                // Wings: open, the sharp trailing edge where the first and last w rows meet.
                for (double u : {0.0, 0.4, 1.0})
                    REQUIRE(glm::distance(geom::evaluate(s, u, s.domainStartV()),
                                          geom::evaluate(s, u, s.domainEndV())) < 1e-9);
                continue;
            }
            ++closed;
            INFO(c.name);
            REQUIRE(s.countV == c.sections.pointsPerSection + 3);
            for (std::size_t i = 0; i < s.countU; ++i)
                for (std::size_t j = 0; j < 3; ++j) REQUIRE(s.point(i, j) == s.point(i, s.countV - 3 + j));
            REQUIRE(s.domainStartV() == s.knotsV[3]);
            REQUIRE(s.domainEndV() == s.knotsV[s.countV]);
            for (double u : {0.05, 0.3, 0.5, 0.81, 0.97}) {
                const geom::SurfaceDerivatives a = geom::derivatives(s, u, s.domainStartV(), 2);
                const geom::SurfaceDerivatives b = geom::derivatives(s, u, s.domainEndV(), 2);
                for (int k = 0; k <= 2; ++k)
                    for (int l = 0; k + l <= 2; ++l) {
                        const double scale = 1.0 + glm::length(a.at(k, l));
                        REQUIRE(glm::distance(a.at(k, l), b.at(k, l)) < 1e-9 * scale);
                    }
                // And the seam is no crease: just inside on either side the derivatives agree closely.
                const double h = 1e-7;
                const auto left = geom::derivatives(s, u, s.domainEndV() - h, 2);
                const auto right = geom::derivatives(s, u, s.domainStartV() + h, 2);
                REQUIRE(glm::distance(left.at(0, 2), right.at(0, 2)) <
                        1e-3 * (1.0 + glm::length(left.at(0, 2))));
            }
        }
    REQUIRE(closed == 4);  // the transport's fuselage and two nacelles, the fighter's fuselage
}

TEST_CASE("closed sections face outward and wings have their upper surface up", "[acsynt][loft]") {
    for (const Model* m : {&transport(), &fighter()})
        for (const Component& c : m->components) {
            INFO(c.name);
            glm::dvec3 centre(0.0);
            for (const glm::dvec3& p : c.sections.points) centre += p;
            centre /= static_cast<double>(c.sections.points.size());
            int outward = 0, total = 0;
            for (const Patch& p : c.patches.patches) {
                const glm::dvec3 mid = p.middle;
                const geom::SurfaceDerivatives d =
                    geom::derivatives(c.surface, 0.5 * (p.u0 + p.u1), 0.5 * (p.w0 + p.w1), 1);
                const glm::dvec3 n = glm::cross(d.at(1, 0), d.at(0, 1));
                glm::dvec3 away = mid - centre;
                if (c.closedW) away.x = 0.0;  // bodies: away from the axis
                outward += glm::dot(n, away) > 0.0 ? 1 : 0;
                ++total;
            }
            REQUIRE(outward > total * 9 / 10);
        }
}

TEST_CASE("the patch list matches its surface", "[acsynt][patch]") {
    for (const Model* m : {&transport(), &fighter()})
        for (const Component& c : m->components) {
            INFO(m->name << " / " << c.name);
            const geom::Surface& s = c.surface;
            const PatchList& list = c.patches;
            REQUIRE(list.countU == s.countU - 3);
            REQUIRE(list.countW == s.countV - 3);
            REQUIRE(list.size() == list.countU * list.countW);
            for (const Patch& p : list.patches) {
                REQUIRE(p.number == static_cast<int>(p.row * list.countW + p.column + 1));
                REQUIRE(p.spanU == p.row + 3);
                REQUIRE(p.spanW == p.column + 3);
                REQUIRE(p.u0 == s.knotsU[p.spanU]);
                REQUIRE(p.u1 == s.knotsU[p.spanU + 1]);
                REQUIRE(p.w0 == s.knotsV[p.spanW]);
                REQUIRE(p.w1 == s.knotsV[p.spanW + 1]);
                REQUIRE(p.knotsU[3] == p.u0);
                REQUIRE(p.knotsW[4] == p.w1);
                REQUIRE(p.hull[0] == s.point(p.spanU - 3, p.spanW - 3));
                REQUIRE(p.hull[15] == s.point(p.spanU, p.spanW));
                REQUIRE(glm::distance(p.corner, geom::evaluate(s, p.u0, p.w0)) < 1e-12);
                REQUIRE(glm::distance(p.u1w0, geom::evaluate(s, p.u1, p.w0)) < 1e-12);
                REQUIRE(glm::distance(p.u0w1, geom::evaluate(s, p.u0, p.w1)) < 1e-12);
                REQUIRE(glm::distance(p.middle, geom::evaluate(s, 0.5 * (p.u0 + p.u1), 0.5 * (p.w0 + p.w1))) <
                        1e-12);
                const geom::SurfaceDerivatives d = geom::derivatives(s, p.u0, p.w0, 1);
                REQUIRE(glm::distance(p.tangentU, d.at(1, 0)) < 1e-9 * (1.0 + glm::length(d.at(1, 0))));
                REQUIRE(glm::distance(p.tangentW, d.at(0, 1)) < 1e-9 * (1.0 + glm::length(d.at(0, 1))));
                REQUIRE(std::abs(glm::length(p.normal) - 1.0) < 1e-12);
                // Bezier corners are the surface corners.
                REQUIRE(glm::distance(p.bezier[0], p.corner) < 1e-12);
                REQUIRE(glm::distance(p.bezier[12], p.u1w0) < 1e-12);
                REQUIRE(glm::distance(p.bezier[3], p.u0w1) < 1e-12);
                const auto power = powerBasisCoefficients(p);
                for (double a : {0.0, 0.25, 0.6, 1.0})
                    for (double b : {0.0, 0.4, 0.9, 1.0}) {
                        const double u = p.u0 + a * (p.u1 - p.u0), w = p.w0 + b * (p.w1 - p.w0);
                        const glm::dvec3 expected = geom::evaluate(s, u, w);
                        REQUIRE(glm::distance(evaluatePatchHull(p, u, w), expected) < 1e-12);
                        REQUIRE(glm::distance(evaluateBezierPatch(p, u, w), expected) < 1e-12);
                        glm::dvec3 q(0.0);
                        for (int i = 3; i >= 0; --i) {
                            glm::dvec3 row(0.0);
                            for (int j = 3; j >= 0; --j)
                                row = row * b + power[static_cast<std::size_t>(i * 4 + j)];
                            q = q * a + row;
                        }
                        REQUIRE(glm::distance(q, expected) < 1e-9);
                    }
                const Patch* found = list.find(0.5 * (p.u0 + p.u1), 0.5 * (p.w0 + p.w1));
                REQUIRE(found == &p);
            }
            REQUIRE(list.find(s.domainEndU(), s.domainEndV()) == &list.patches.back());
            REQUIRE(list.find(s.domainStartU(), s.domainStartV()) == &list.patches.front());
            REQUIRE(list.find(s.domainEndU() + 0.1, s.domainStartV()) == nullptr);
        }
}

TEST_CASE("a patch list skips empty knot spans and refuses non-bicubic surfaces", "[acsynt][patch]") {
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j) points.push_back({i, j, 0.1 * i * j});
    // A double interior knot in u: 5 control points, spans [0, 0.5] and [0.5, 1] only.
    const geom::Surface s(3, 3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 5, 4, points);
    const PatchList list = buildPatches(s);
    REQUIRE(list.countU == 2);
    REQUIRE(list.countW == 1);
    const geom::Surface doubled(3, 3, {0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 6, 4, [] {
        std::vector<glm::dvec3> p;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 4; ++j) p.push_back({i, j, 0.1 * i * j});
        return p;
    }());
    const PatchList two = buildPatches(doubled);
    REQUIRE(two.countU == 2);
    REQUIRE(two.patches[1].spanU == 5);
    for (const Patch& p : two.patches)
        REQUIRE(glm::distance(evaluateBezierPatch(p, 0.7 * p.u0 + 0.3 * p.u1, 0.5),
                              geom::evaluate(doubled, 0.7 * p.u0 + 0.3 * p.u1, 0.5)) < 1e-12);
    const geom::Surface quadratic(2, 3, {0, 0, 0, 0.5, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4,
                                  std::vector<glm::dvec3>(points.begin(), points.begin() + 16));
    REQUIRE_THROWS_AS(buildPatches(quadratic), geom::GeometryError);
}

}  // namespace test_loft
