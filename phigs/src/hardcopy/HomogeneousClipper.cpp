#include "phigs/hardcopy/HomogeneousClipper.h"

#include "phigs/traverse/ViewClipRectangle.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace phigs::hardcopy {
namespace {

/// w stays above this, so the division that follows clipping is safe.
constexpr double kMinW = 1e-12;

double signedDistance(const HalfSpace& s, const ClipVertex& v) {
    return glm::dot(s.plane, v.h) - s.offset;
}

/// A place on a -> b as its fraction from a and the rest (1 - t), each computed directly.
struct Fraction {
    double t = 0.0;
    double rest = 1.0;
};

/// Where the segment meets a plane, from the signed distances of its ends (of opposite sides).
Fraction crossing(double da, double db) {
    return {da / (da - db), db / (db - da)};
}

/// The point at a fraction, built from the nearer end: a far vertex (1e20 and beyond) swamps
/// the other's coordinates in b - a, and 1 - t near 1 keeps none of the rest's digits.
ClipVertex at(const ClipVertex& a, const ClipVertex& b, Fraction f) {
    if (f.t <= f.rest)
        return {a.h + f.t * (b.h - a.h), a.distance + f.t * (b.distance - a.distance),
                a.along + f.t * (b.along - a.along)};
    return {b.h + f.rest * (a.h - b.h), b.distance + f.rest * (a.distance - b.distance),
            b.along + f.rest * (a.along - b.along)};
}

}  // namespace

std::vector<HalfSpace> viewVolume(const DrawView& view, const DrawList& list) {
    std::vector<HalfSpace> volume;
    volume.push_back({{0, 0, 0, 1}, kMinW});
    // NPC z in [lo, hi] as z - lo w >= 0 and hi w - z >= 0 (w > 0).
    double zLo = 0.0, zHi = 1.0;
    if (view.clipBack) zLo = std::max(zLo, view.clipMin.z);
    if (view.clipFront) zHi = std::min(zHi, view.clipMax.z);
    volume.push_back({{0, 0, 1, -zLo}, 0.0});
    volume.push_back({{0, 0, -1, zHi}, 0.0});
    const ViewClipRectangle kept(view, list.windowMin, list.windowMax);
    const glm::dvec2 lo = kept.min, hi = kept.max;
    volume.push_back({{1, 0, 0, -lo.x}, 0.0});
    volume.push_back({{-1, 0, 0, hi.x}, 0.0});
    volume.push_back({{0, 1, 0, -lo.y}, 0.0});
    volume.push_back({{0, -1, 0, hi.y}, 0.0});
    return volume;
}

std::vector<HalfSpace> modelVolume(const std::vector<glm::dvec4>& planes) {
    std::vector<HalfSpace> volume;
    for (const glm::dvec4& p : planes) volume.push_back({p, 0.0});
    return volume;
}

bool inside(const glm::dvec4& h, const std::vector<HalfSpace>& volume) {
    return std::all_of(volume.begin(), volume.end(),
                       [&](const HalfSpace& s) { return glm::dot(s.plane, h) - s.offset >= 0.0; });
}

std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> polygon, const std::vector<HalfSpace>& volume) {
    std::vector<ClipVertex> next;
    for (const HalfSpace& s : volume) {
        if (polygon.size() < 3) return {};
        next.clear();
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const ClipVertex& a = polygon[i];
            const ClipVertex& b = polygon[(i + 1) % polygon.size()];
            const double da = signedDistance(s, a), db = signedDistance(s, b);
            if (da >= 0.0) next.push_back(a);
            if ((da >= 0.0) != (db >= 0.0)) next.push_back(at(a, b, crossing(da, db)));
        }
        polygon.swap(next);
    }
    if (polygon.size() < 3) return {};
    return polygon;
}

std::vector<std::vector<ClipVertex>> clipPolyline(const std::vector<ClipVertex>& line,
                                                  const std::vector<HalfSpace>& volume) {
    std::vector<std::vector<ClipVertex>> runs;
    std::vector<ClipVertex> run;
    // Ordered by t where both are near a, by the rest elsewhere (t rounds to 1 near b, where
    // several planes' crossings by a far vertex's segment would tie).
    const auto byT = [](const Fraction& x, const Fraction& y) {
        return x.t <= x.rest && y.t <= y.rest ? x.t < y.t : x.rest > y.rest;
    };
    auto finish = [&] {
        if (run.size() >= 2) runs.push_back(run);
        run.clear();
    };
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        // The segment's part inside every half space: [t0, t1] of a + t (b - a).
        Fraction t0{0.0, 1.0}, t1{1.0, 0.0};
        for (const HalfSpace& s : volume) {
            const double da = signedDistance(s, line[i]), db = signedDistance(s, line[i + 1]);
            if (da < 0.0 && db < 0.0) t0 = {1.0, 0.0}, t1 = {0.0, 1.0};
            if (da < 0.0 && db >= 0.0) t0 = std::max(t0, crossing(da, db), byT);
            if (da >= 0.0 && db < 0.0) t1 = std::min(t1, crossing(da, db), byT);
        }
        if (t0.t > t1.t) {
            finish();
            continue;
        }
        const ClipVertex &a = line[i], &b = line[i + 1];
        if (t0.t > 0.0 || run.empty()) {
            finish();
            run.push_back(at(a, b, t0));
        }
        run.push_back(at(a, b, t1));
        if (t1.t < 1.0) finish();
    }
    finish();
    return runs;
}

}  // namespace phigs::hardcopy
