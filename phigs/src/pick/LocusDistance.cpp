#include "phigs/pick/LocusDistance.h"

#include "phigs/core/TransformUtilities.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/render/Triangulation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace phigs {

namespace {

double side(const glm::dvec4& plane, const glm::dvec3& p) {
    return glm::dot(glm::dvec3(plane), p) + plane.w;
}

// Ericson, Real-Time Collision Detection (2005), 5.1.5: the closest point of triangle abc to p.
glm::dvec3 closestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

/// The smallest distance from a point to the parts of a locus the clipping planes keep.
class LocusMeasure {
public:
    LocusMeasure(const glm::dvec3& point, const ItemArray<glm::dvec4>* planes)
        : point_(point), planes_(planes) {}

    double best = std::numeric_limits<double>::infinity();

    void at(const glm::dvec3& p) {
        if (planes_)
            for (const glm::dvec4& plane : *planes_)
                if (side(plane, p) < 0) return;
        best = std::min(best, glm::length(p - point_));
    }

    void segment(const glm::dvec3& a, const glm::dvec3& b) {
        double t0 = 0.0, t1 = 1.0;
        if (planes_)
            for (const glm::dvec4& plane : *planes_) {
                const double da = side(plane, a), db = side(plane, b);
                if (da < 0 && db < 0) return;
                if (da < 0) t0 = std::max(t0, da / (da - db));
                if (db < 0) t1 = std::min(t1, da / (da - db));
            }
        if (t0 > t1) return;
        const glm::dvec3 d = b - a;
        const double dd = glm::dot(d, d);
        const double t = dd > 0 ? std::clamp(glm::dot(point_ - a, d) / dd, t0, t1) : t0;
        best = std::min(best, glm::length(a + d * t - point_));
    }

    void triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        std::vector<glm::dvec3> polygon{a, b, c};
        if (planes_)
            for (const glm::dvec4& plane : *planes_) polygon = clipped(polygon, plane);
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i) convex(polygon[0], polygon[i], polygon[i + 1]);
    }

private:
    // Sutherland-Hodgman against one half space.
    static std::vector<glm::dvec3> clipped(const std::vector<glm::dvec3>& in, const glm::dvec4& plane) {
        std::vector<glm::dvec3> out;
        for (std::size_t i = 0; i < in.size(); ++i) {
            const glm::dvec3 &p = in[i], &q = in[(i + 1) % in.size()];
            const double dp = side(plane, p), dq = side(plane, q);
            if (dp >= 0) out.push_back(p);
            if ((dp >= 0) != (dq >= 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
        }
        return out;
    }

    void convex(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        if (glm::length(glm::cross(b - a, c - a)) == 0.0) {  // degenerate: its edges are all of it
            const ItemArray<glm::dvec4>* planes = planes_;
            planes_ = nullptr;  // already clipped
            segment(a, b), segment(b, c), segment(c, a);
            planes_ = planes;
            return;
        }
        best = std::min(best, glm::length(closestOnTriangle(point_, a, b, c) - point_));
    }

    glm::dvec3 point_;
    const ItemArray<glm::dvec4>* planes_;
};

void strip(LocusMeasure& m, std::span<const glm::dvec3> points, const glm::dmat4& model, bool closed) {
    if (points.size() == 1) m.at(projectPoint3(model, points[0]));
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        m.segment(projectPoint3(model, points[i]), projectPoint3(model, points[i + 1]));
    if (closed && points.size() > 2)
        m.segment(projectPoint3(model, points.back()), projectPoint3(model, points.front()));
}

// The even-odd interior in the contours' plane (Newell's normal), and the boundary.
void fillArea(LocusMeasure& m, const DrawFillArea& f, const glm::dmat4& model) {
    std::vector<glm::dvec3> flat;
    glm::dvec3 normal(0.0);
    for (const auto& contour : f.contours) {
        for (std::size_t i = 0; i < contour.size(); ++i) {
            const glm::dvec3 p = projectPoint3(model, contour[i]),
                             q = projectPoint3(model, contour[(i + 1) % contour.size()]);
            normal +=
                glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
        }
        strip(m, contour, model, true);
    }
    if (glm::length(normal) == 0.0) return;
    normal = glm::normalize(normal);
    const glm::dvec3 u = glm::normalize(std::abs(normal.x) < 0.9 ? glm::cross(normal, glm::dvec3(1, 0, 0))
                                                                 : glm::cross(normal, glm::dvec3(0, 1, 0)));
    const glm::dvec3 v = glm::cross(normal, u);
    std::vector<std::vector<glm::dvec2>> plane;
    for (const auto& contour : f.contours) {
        plane.emplace_back();
        for (const auto& p : contour) {
            flat.push_back(projectPoint3(model, p));
            plane.back().push_back({glm::dot(flat.back(), u), glm::dot(flat.back(), v)});
        }
    }
    const render::Triangulation t = render::triangulateEvenOdd(plane);
    auto vertex = [&](std::uint32_t i) {
        const render::TriangulationVertex& tv = t.vertices[i];
        return flat[tv.from] * (1.0 - tv.t) + flat[tv.to] * tv.t;
    };
    for (std::size_t i = 0; i + 2 < t.triangles.size(); i += 3)
        m.triangle(vertex(t.triangles[i]), vertex(t.triangles[i + 1]), vertex(t.triangles[i + 2]));
}

void mesh(LocusMeasure& m, const DrawMesh& d, const glm::dmat4& model) {
    if (!d.mesh) return;
    const MeshData& data = *d.mesh;
    auto at = [&](std::uint32_t i) { return projectPoint3(model, glm::dvec3(data.positions[i])); };
    for (std::size_t i = 0; i + 2 < data.triangles.size(); i += 3)
        m.triangle(at(data.triangles[i]), at(data.triangles[i + 1]), at(data.triangles[i + 2]));
}

// Text strokes as the renderer lays them out (world coordinates).
void text(LocusMeasure& m, const DrawItem& item, const DrawText& t) {
    if (t.annotation) {
        m.at(projectPoint3(item.modelTransform().get(), t.position));
        return;
    }
    const render::ItemGeometry g = render::describeItem(item, glm::dmat4(1.0));
    for (const render::GeometryPart& part : g.parts)
        for (std::uint32_t i = part.first; i + 1 < part.first + part.count; i += 2)
            m.segment(glm::dvec3(g.vertices[i].position), glm::dvec3(g.vertices[i + 1].position));
}

}  // namespace

double locusDistance(const DrawItem& item, const glm::dvec3& point, bool clip) {
    LocusMeasure m(point, clip && !item.modelClipPlanes().empty() ? &item.modelClipPlanes() : nullptr);
    const glm::dmat4& model = item.modelTransform().get();
    visitPrimitive(
        [&](const auto& p) {
            using T = std::decay_t<decltype(p)>;
            if constexpr (kDrawsStrip<T>)
                strip(m, stripPoints(p), model, false);
            else if constexpr (std::is_same_v<T, DrawPolymarker>)
                for (const auto& q : p.points) m.at(projectPoint3(model, q));
            else if constexpr (std::is_same_v<T, DrawFillArea>)
                fillArea(m, p, model);
            else if constexpr (std::is_same_v<T, DrawMesh>)
                mesh(m, p, model);
            else if constexpr (std::is_same_v<T, DrawText>)
                text(m, item, p);
            else
                static_assert(kUnhandledPrimitive<T>);
        },
        item.primitive);
    return m.best;
}

}  // namespace phigs
