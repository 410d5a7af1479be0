#pragma once

#include "geom/CurveFile.h"
#include "geom/Evaluate.h"
#include "geom/curvemap/CurveMapper.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace curvemap_test {

inline std::vector<geom::Curve> loadCurves(const std::string& name) {
    // Appended in place: GCC 12 warns falsely (-Warray-bounds) on a chain of temporaries here.
    std::string path = PHIGS_TEST_DATA_DIR;
    path += "/curvemap/";
    path += name;
    const geom::CurveModel model = geom::readCurveFile(path);
    std::vector<geom::Curve> curves;
    for (const geom::CurvePart& part : model.parts) curves.push_back(geom::interpolatePart(part));
    return curves;
}

/// A closed polygon through the given corners as a curve with straight C0 sides.
inline geom::Curve polygonCurve(std::vector<glm::dvec3> corners) {
    corners.push_back(corners.front());
    geom::InterpolationData d;
    d.points = corners;
    d.continuities.assign(corners.size(), geom::Continuity::C0);
    d.tangents.assign(2 * corners.size(), glm::dvec3(0.0));
    d.closed = true;
    return geom::interpolateCubic(d);
}

inline double signedArea(const std::vector<glm::dvec2>& loop) {
    double a = 0.0;
    for (std::size_t i = 0; i + 1 < loop.size(); ++i)
        a += loop[i].x * loop[i + 1].y - loop[i + 1].x * loop[i].y;
    return 0.5 * a;
}

inline bool segmentsCross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                          const glm::dvec2& d) {
    auto orient = [](const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& r) {
        return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    };
    const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    return ((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0)) && o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0;
}

inline bool selfIntersects(const std::vector<glm::dvec2>& loop) {
    const std::size_t n = loop.size() - 1;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;
            if (segmentsCross(loop[i], loop[i + 1], loop[j], loop[j + 1])) return true;
        }
    return false;
}

/// Crossing-number inside test of a closed polygon, edges bucketed by y so a query reads few.
class PolygonInside {
public:
    explicit PolygonInside(std::vector<glm::dvec2> poly, int buckets = 128) : poly_(std::move(poly)) {
        lo_ = hi_ = poly_.front().y;
        for (const glm::dvec2& p : poly_) {
            lo_ = std::min(lo_, p.y);
            hi_ = std::max(hi_, p.y);
        }
        buckets_.resize(static_cast<std::size_t>(buckets));
        for (std::size_t i = 0, j = poly_.size() - 1; i < poly_.size(); j = i++) {
            const double a = std::min(poly_[i].y, poly_[j].y), b = std::max(poly_[i].y, poly_[j].y);
            for (std::size_t k = bucket(a); k <= bucket(b); ++k) buckets_[k].push_back({i, j});
        }
    }
    bool operator()(const glm::dvec2& p) const {
        if (p.y < lo_ || p.y > hi_) return false;
        bool inside = false;
        for (const auto& [i, j] : buckets_[bucket(p.y)]) {
            const glm::dvec2 &a = poly_[i], &b = poly_[j];
            if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
                inside = !inside;
        }
        return inside;
    }

private:
    std::size_t bucket(double y) const {
        const double f = (y - lo_) / (hi_ - lo_ + 1e-300) * static_cast<double>(buckets_.size());
        return std::min(buckets_.size() - 1, static_cast<std::size_t>(std::max(0.0, f)));
    }
    std::vector<glm::dvec2> poly_;
    double lo_, hi_;
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> buckets_;
};

/// Brute-force reference: the (u, w) area of the cells (a grid over the loops' box) whose
/// surface point projects into the plane curve and faces the curve plane.
inline double rasterArea(const geom::curvemap::CurveMapper& mapper, const geom::curvemap::MapResult& result,
                         const geom::Curve& curve, const std::vector<geom::curvemap::MappedLoop>& loops,
                         int cells = 200) {
    std::vector<glm::dvec2> plane;
    for (int i = 0; i <= 4000; ++i) {
        const double s = curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * i / 4000.0;
        const glm::dvec3 p = geom::evaluate(curve, s);
        plane.push_back({p.x, p.y});
    }
    const PolygonInside inside(plane);
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const auto& loop : loops)
        for (const glm::dvec2& uv : loop.uv) {
            lo = glm::min(lo, uv);
            hi = glm::max(hi, uv);
        }
    const glm::dvec2 margin = 0.02 * (hi - lo);
    lo -= margin;
    hi += margin;
    const geom::curvemap::SurfaceDomain& d = mapper.domain();
    const glm::dvec2 cell = (hi - lo) / double(cells);
    // Only the side of the surface that faces the curve plane at the reference point is seen.
    const double facing = glm::dot(result.frame.z, glm::cross(result.frame.tangentU, result.frame.tangentW));
    double area = 0.0;
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            const glm::dvec2 uv = lo + glm::dvec2(i + 0.5, j + 0.5) * cell;
            if (!d.closedU && (uv.x < d.u0 || uv.x > d.u1)) continue;
            if (!d.closedW && (uv.y < d.w0 || uv.y > d.w1)) continue;
            const glm::dvec2 w = d.wrap(uv);
            if (glm::dot(geom::normal(mapper.surface(), w.x, w.y), result.frame.z) * facing <= 0.0) continue;
            const glm::dvec3 local = result.frame.toCurve(geom::evaluate(mapper.surface(), w.x, w.y));
            if (inside({local.x, local.y})) area += cell.x * cell.y;
        }
    return area;
}

/// The checks every mapping must pass: points on the surface and on their projection lines,
/// boundary vertices on the boundary, loops closed, counter-clockwise and simple.
inline void checkMapping(const geom::curvemap::CurveMapper& mapper, const geom::curvemap::MapResult& result,
                         const std::vector<geom::Curve>& curves) {
    const geom::curvemap::SurfaceDomain& d = mapper.domain();
    REQUIRE(result.parts.size() == curves.size());
    for (std::size_t p = 0; p < curves.size(); ++p) {
        INFO("part " << p);
        for (const auto& loop : result.parts[p].loops) {
            REQUIRE(loop.uv.size() >= 4);
            REQUIRE(loop.points.size() == loop.uv.size());
            CHECK(loop.uv.front() == loop.uv.back());
            CHECK(signedArea(loop.uv) > 0.0);
            CHECK_FALSE(selfIntersects(loop.uv));
            for (std::size_t i = 0; i < loop.uv.size(); ++i) {
                const glm::dvec2 w = d.wrap(loop.uv[i]);
                CHECK(glm::length(geom::evaluate(mapper.surface(), w.x, w.y) - loop.points[i]) <= 1e-9);
                if (i > 0) {
                    CHECK(std::abs(loop.uv[i].x - loop.uv[i - 1].x) < 0.25 * d.periodU());
                    CHECK(std::abs(loop.uv[i].y - loop.uv[i - 1].y) < 0.25 * d.periodW());
                }
                if (std::isnan(loop.curveParameters[i])) {
                    const bool onEdge = (!d.closedU && (w.x == d.u0 || w.x == d.u1)) ||
                                        (!d.closedW && (w.y == d.w0 || w.y == d.w1));
                    CHECK(onEdge);
                    continue;
                }
                const glm::dvec3 from =
                    result.frame.toModel(geom::evaluate(curves[p], loop.curveParameters[i]));
                CHECK(glm::length(from - loop.projectedFrom[i]) <= 1e-9);
                const glm::dvec3 off = loop.points[i] - from;
                CHECK(glm::length(off - glm::dot(off, result.frame.z) * result.frame.z) <= 1e-9);
            }
        }
    }
}

}  // namespace curvemap_test
