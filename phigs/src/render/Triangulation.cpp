#include "phigs/render/Triangulation.h"

#include <algorithm>
#include <cmath>

namespace phigs::render {
namespace {

struct Edge {
    glm::dvec2 a, b;  // a.y < b.y
    std::uint32_t from, to;
    bool flipped;  // a is the contour's `to` vertex
};

double xAt(const Edge& e, double y) {
    const double t = (y - e.a.y) / (e.b.y - e.a.y);
    return e.a.x + t * (e.b.x - e.a.x);
}

}  // namespace

Triangulation triangulateEvenOdd(const std::vector<std::vector<glm::dvec2>>& contours) {
    // A lone triangle is its own triangulation: no slab cut, so vertex data interpolate across it
    // from its corners alone (a cut vertex would carry a value mixed in one colour space).
    if (contours.size() == 1 && contours[0].size() == 3) {
        const auto& c = contours[0];
        const double area = (c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[1].y - c[0].y) * (c[2].x - c[0].x);
        Triangulation out;
        if (!(std::abs(area) > 0.0)) return out;  // also NaN: no triangle
        for (std::uint32_t i = 0; i < 3; ++i) out.vertices.push_back({c[i], i, i, 0.0});
        out.triangles =
            area > 0.0 ? std::vector<std::uint32_t>{0, 1, 2} : std::vector<std::uint32_t>{0, 2, 1};
        return out;
    }
    std::vector<Edge> edges;
    std::vector<double> ys;
    std::uint32_t base = 0;
    for (const auto& contour : contours) {
        const auto n = static_cast<std::uint32_t>(contour.size());
        if (n >= 3) {
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t j = (i + 1) % n;
                glm::dvec2 p = contour[i], q = contour[j];
                ys.push_back(p.y);
                if (p.y == q.y) continue;  // horizontal edges bound no slab
                const bool flipped = p.y > q.y;
                if (flipped) std::swap(p, q);
                edges.push_back({p, q, base + i, base + j, flipped});
            }
        }
        base += n;
    }
    // Crossings split slabs too, so that inside each slab the edges keep their left-right order.
    for (std::size_t i = 0; i < edges.size(); ++i)
        for (std::size_t k = i + 1; k < edges.size(); ++k) {
            const Edge &e = edges[i], &f = edges[k];
            const glm::dvec2 r = e.b - e.a, s = f.b - f.a;
            const double denom = r.x * s.y - r.y * s.x;
            if (std::abs(denom) < 1e-300) continue;
            const glm::dvec2 d = f.a - e.a;
            const double t = (d.x * s.y - d.y * s.x) / denom;
            const double u = (d.x * r.y - d.y * r.x) / denom;
            if (t > 0 && t < 1 && u > 0 && u < 1) ys.push_back(e.a.y + t * r.y);
        }
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());

    Triangulation out;
    auto vertexOn = [&](const Edge& e, double y) {
        const double t = (y - e.a.y) / (e.b.y - e.a.y);
        TriangulationVertex v;
        v.point = {xAt(e, y), y};
        v.from = e.from;
        v.to = e.to;
        v.t = e.flipped ? 1.0 - t : t;
        out.vertices.push_back(v);
        return static_cast<std::uint32_t>(out.vertices.size() - 1);
    };
    std::vector<const Edge*> spanning;
    for (std::size_t s = 0; s + 1 < ys.size(); ++s) {
        const double y0 = ys[s], y1 = ys[s + 1], mid = 0.5 * (y0 + y1);
        spanning.clear();
        for (const Edge& e : edges)
            if (e.a.y <= y0 && e.b.y >= y1) spanning.push_back(&e);
        std::sort(spanning.begin(), spanning.end(),
                  [&](const Edge* l, const Edge* r) { return xAt(*l, mid) < xAt(*r, mid); });
        for (std::size_t k = 0; k + 1 < spanning.size(); k += 2) {
            const Edge &left = *spanning[k], &right = *spanning[k + 1];
            const std::uint32_t bl = vertexOn(left, y0), br = vertexOn(right, y0);
            const std::uint32_t tr = vertexOn(right, y1), tl = vertexOn(left, y1);
            out.triangles.insert(out.triangles.end(), {bl, br, tr, bl, tr, tl});
        }
    }
    return out;
}

double triangulatedArea(const Triangulation& triangulation) {
    double area = 0.0;
    const auto& v = triangulation.vertices;
    for (std::size_t i = 0; i + 2 < triangulation.triangles.size(); i += 3) {
        const glm::dvec2 a = v[triangulation.triangles[i]].point, b = v[triangulation.triangles[i + 1]].point,
                         c = v[triangulation.triangles[i + 2]].point;
        area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    }
    return area;
}

}  // namespace phigs::render
