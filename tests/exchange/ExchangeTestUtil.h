#pragma once
// Shared by the exchange tests: models to write, comparisons to 1e-12, scratch files.

#include "acsynt/Model.h"
#include "geom/BezierExtraction.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/Surface.h"
#include "geom/exchange/CadModel.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

namespace exchange_test {

/// A fresh folder for one test's files under the tests' output directory.
inline std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "exchange" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline const acsynt::Model& transport() {
    static const acsynt::Model model = acsynt::loadModel(ACSYNT_DATA_DIR "/transport.acm");
    return model;
}

/// The components of an acsynt model as named surfaces in metres.
inline geom::exchange::CadModel cadModelOf(const acsynt::Model& m) {
    geom::exchange::CadModel cad;
    cad.name = m.name;
    for (const auto& c : m.components) cad.surfaces.push_back({c.name, c.surface, c.colour, {}});
    return cad;
}

/// A closed loop round (u, w) centre c with radii r, n vertices, counter-clockwise or not; its
/// points on the surface (w wrapped into the domain where the surface is periodic).
inline geom::exchange::SurfaceLoop ellipse(const geom::Surface& s, glm::dvec2 c, glm::dvec2 r, int n,
                                           bool counterClockwise) {
    geom::exchange::SurfaceLoop loop;
    for (int k = 0; k <= n; ++k) {
        const double a = (counterClockwise ? 1 : -1) * 2 * M_PI * (k % n) / n;
        loop.uv.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
        double w = loop.uv.back().y;
        w -= std::floor((w - s.domainStartV()) / (s.domainEndV() - s.domainStartV())) *
             (s.domainEndV() - s.domainStartV());
        loop.points.push_back(geom::evaluate(s, loop.uv.back().x, w));
    }
    return loop;
}

/// The transport with loops on the wing (an outer loop with a hole, and a second outer loop) and
/// on the fuselage across its seam (w below 0), and a reduced fuselage (unclamped, not periodic).
/// seamKept false reduces the fuselage's seam as two ends (as before ReductionOptions::keepSeams).
inline geom::exchange::CadModel loopModel(bool seamKept = true) {
    geom::exchange::CadModel m = cadModelOf(exchange_test::transport());
    const geom::Surface& wing = m.surfaces[1].surface;
    m.surfaces[1].curves.push_back(
        {"logo.crv",
         {ellipse(wing, {0.5, 0.3}, {0.2, 0.1}, 40, true), ellipse(wing, {0.5, 0.3}, {0.05, 0.03}, 17, false),
          ellipse(wing, {0.2, 0.7}, {0.05, 0.05}, 12, true)}});
    const geom::Surface& body = m.surfaces[0].surface;
    m.surfaces[0].curves.push_back({"seam.crv", {ellipse(body, {0.5, 0.0}, {0.1, 0.04}, 30, true)}});
    geom::ReductionOptions o;
    o.tolerance = 0.01;
    o.keepSeams = seamKept;
    m.surfaces.push_back({"fuselage_R1",
                          geom::reduceSurface(body, geom::ReductionDirection::Both, o).surface,
                          glm::dvec3(0.2, 0.4, 0.6),
                          {}});
    return m;
}

inline double largestGap(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return INFINITY;
    double gap = 0;
    for (std::size_t i = 0; i < a.size(); ++i) gap = std::max(gap, std::abs(a[i] - b[i]));
    return gap;
}

/// Same degrees, knots, weights and poles (each within `tolerance`), and the same points at a
/// 13 x 13 grid of parameters.
inline void requireSameSurface(const geom::Surface& a, const geom::Surface& b, double tolerance = 1e-12) {
    REQUIRE(a.degreeU == b.degreeU);
    REQUIRE(a.degreeV == b.degreeV);
    REQUIRE(a.countU == b.countU);
    REQUIRE(a.countV == b.countV);
    REQUIRE(a.rational() == b.rational());
    CHECK(largestGap(a.knotsU, b.knotsU) <= tolerance);
    CHECK(largestGap(a.knotsV, b.knotsV) <= tolerance);
    CHECK(largestGap(a.weights, b.weights) <= tolerance);
    double poles = 0, points = 0;
    for (std::size_t i = 0; i < a.points.size(); ++i)
        poles = std::max(poles, glm::length(a.points[i] - b.points[i]));
    for (int i = 0; i <= 12; ++i)
        for (int j = 0; j <= 12; ++j) {
            const double u = a.domainStartU() + (a.domainEndU() - a.domainStartU()) * i / 12.0;
            const double v = a.domainStartV() + (a.domainEndV() - a.domainStartV()) * j / 12.0;
            points = std::max(points, glm::length(geom::evaluate(a, u, v) - geom::evaluate(b, u, v)));
        }
    INFO("largest pole difference " << poles << ", point difference " << points);
    CHECK(poles <= tolerance);
    CHECK(points <= tolerance);
}

/// The same patches (Bézier pieces: parameter intervals, knots, poles, weights within
/// `tolerance`), whatever knots lie outside the domain (an unclamped surface comes back clamped).
inline void requireSamePatches(const geom::Surface& a, const geom::Surface& b, double tolerance = 1e-12) {
    const auto pa = geom::extractBezier(a), pb = geom::extractBezier(b);
    REQUIRE(pa.size() == pb.size());
    double gap = 0;
    for (std::size_t k = 0; k < pa.size(); ++k) {
        const geom::Surface &x = pa[k].surface, &y = pb[k].surface;
        REQUIRE(x.points.size() == y.points.size());
        gap = std::max({gap, std::abs(pa[k].u0 - pb[k].u0), std::abs(pa[k].u1 - pb[k].u1),
                        std::abs(pa[k].v0 - pb[k].v0), std::abs(pa[k].v1 - pb[k].v1),
                        largestGap(x.knotsU, y.knotsU), largestGap(x.knotsV, y.knotsV),
                        largestGap(x.weights, y.weights)});
        for (std::size_t i = 0; i < x.points.size(); ++i)
            gap = std::max(gap, glm::length(x.points[i] - y.points[i]));
    }
    INFO("largest difference in the patches " << gap);
    CHECK(gap <= tolerance);
}

inline void requireSameLoops(const std::vector<geom::exchange::SurfaceLoop>& a,
                             const std::vector<geom::exchange::SurfaceLoop>& b, double tolerance = 1e-12) {
    REQUIRE(a.size() == b.size());
    for (std::size_t l = 0; l < a.size(); ++l) {
        INFO("loop " << l);
        REQUIRE(a[l].points.size() == b[l].points.size());
        REQUIRE(a[l].uv.size() == b[l].uv.size());
        double points = 0, uv = 0;
        for (std::size_t k = 0; k < a[l].points.size(); ++k) {
            points = std::max(points, glm::length(a[l].points[k] - b[l].points[k]));
            uv = std::max(uv, glm::length(a[l].uv[k] - b[l].uv[k]));
        }
        INFO("largest point difference " << points << ", (u, v) difference " << uv);
        CHECK(points <= tolerance);
        CHECK(uv <= tolerance);
    }
}

}  // namespace exchange_test
