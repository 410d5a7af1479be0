#include "phigs/render/Triangulation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

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
    // Bounded time and memory: a fill area tangled enough to need more steps than this (many
    // thousands of points crossing each other everywhere) is refused rather than drawn for minutes.
    constexpr double kMostSteps = 2e9;
    constexpr std::size_t kMostBoundaries = 4'000'000;
    double steps = 0.0;
    const auto count = [&](double more) {
        steps += more;
        if (steps > kMostSteps)
            throw std::length_error("even-odd fill of " + std::to_string(edges.size()) +
                                    " edges: too tangled to triangulate (its edges cross too often)");
    };
    // Crossings split slabs too, so that inside each slab the edges keep their left-right order.
    // Edges by their lower end: only those whose y ranges overlap can cross.
    std::sort(edges.begin(), edges.end(), [](const Edge& l, const Edge& r) { return l.a.y < r.a.y; });
    for (std::size_t i = 0; i < edges.size(); ++i) {
        std::size_t k = i + 1;
        for (; k < edges.size() && edges[k].a.y < edges[i].b.y; ++k) {
            const Edge &e = edges[i], &f = edges[k];
            const glm::dvec2 r = e.b - e.a, s = f.b - f.a;
            const double denom = r.x * s.y - r.y * s.x;
            if (std::abs(denom) < 1e-300) continue;
            const glm::dvec2 d = f.a - e.a;
            const double t = (d.x * s.y - d.y * s.x) / denom;
            const double u = (d.x * r.y - d.y * r.x) / denom;
            if (t > 0 && t < 1 && u > 0 && u < 1) {
                ys.push_back(e.a.y + t * r.y);
                if (ys.size() > kMostBoundaries) count(kMostSteps);  // each crossing is a slab
            }
        }
        count(double(k - i));
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
    // Each inside span of a slab is bounded by a pair of edges; a pair that goes on into the next
    // slab makes one trapezoid with it, so a simple polygon gives O(n) trapezoids, not one per
    // slab and span (O(n^2) for a polygon whose every vertex starts a slab).
    struct Open {
        const Edge* right;
        double bottom;
        bool seen;
    };
    std::map<const Edge*, Open> open;  // by left edge
    auto emit = [&](const Edge& left, const Edge& right, double bottom, double top) {
        const std::uint32_t bl = vertexOn(left, bottom), br = vertexOn(right, bottom);
        const std::uint32_t tr = vertexOn(right, top), tl = vertexOn(left, top);
        out.triangles.insert(out.triangles.end(), {bl, br, tr, bl, tr, tl});
    };
    auto closeUnseen = [&](double at) {
        for (auto it = open.begin(); it != open.end();) {
            if (it->second.seen) {
                it->second.seen = false;
                ++it;
                continue;
            }
            emit(*it->first, *it->second.right, it->second.bottom, at);
            it = open.erase(it);
        }
    };
    // The edges spanning a slab: those begun at or below it and not yet ended (every end is a
    // slab boundary), kept as the slabs go up.
    std::vector<const Edge*> spanning;
    std::vector<double> keys;
    std::size_t begun = 0;
    for (std::size_t s = 0; s + 1 < ys.size(); ++s) {
        const double y0 = ys[s], y1 = ys[s + 1], mid = 0.5 * (y0 + y1);
        std::erase_if(spanning, [&](const Edge* e) { return e->b.y <= y0; });
        for (; begun < edges.size() && edges[begun].a.y <= y0; ++begun)
            if (edges[begun].b.y > y0) spanning.push_back(&edges[begun]);
        // By x at mid-slab: the order changes little from one slab to the next (crossings and new
        // edges), so an insertion sort on the last order is about linear.
        keys.resize(spanning.size());
        for (std::size_t k = 0; k < spanning.size(); ++k) keys[k] = xAt(*spanning[k], mid);
        std::size_t moves = 0;
        for (std::size_t k = 1; k < spanning.size(); ++k)
            for (std::size_t m = k; m > 0 && keys[m] < keys[m - 1]; --m, ++moves) {
                std::swap(keys[m], keys[m - 1]);
                std::swap(spanning[m], spanning[m - 1]);
            }
        count(double(spanning.size() + moves));
        for (std::size_t k = 0; k + 1 < spanning.size(); k += 2) {
            const Edge *left = spanning[k], *right = spanning[k + 1];
            const auto it = open.find(left);
            if (it != open.end() && it->second.right == right) {
                it->second.seen = true;
                continue;
            }
            if (it != open.end()) {
                emit(*left, *it->second.right, it->second.bottom, y0);
                open.erase(it);
            }
            open.emplace(left, Open{right, y0, true});
        }
        closeUnseen(y0);
    }
    closeUnseen(ys.empty() ? 0.0 : ys.back());
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
