#include "LevelCurves.h"

#include "geom/Evaluate.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace phigs::detail {

namespace {

/// One plane's cut through a mesh: a point per crossed edge, a segment per crossed triangle.
class PlaneCut {
public:
    PlaneCut(MeshData& mesh, const glm::dvec4& plane, const geom::Surface* surface)
        : mesh_(mesh), plane_(plane), surface_(surface) {}

    void run() {
        const std::size_t count = mesh_.positions.size();
        side_.resize(count);
        value_.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            value_[i] = glm::dot(glm::dvec3(plane_), glm::dvec3(mesh_.positions[i])) + plane_.w;
            side_[i] = value_[i] >= 0.0;
        }
        const std::vector<std::uint32_t> triangles = mesh_.triangles;  // positions grow below
        for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) cutTriangle(&triangles[t], count);
        chain();
    }

private:
    void cutTriangle(const std::uint32_t* corner, std::size_t count) {
        std::uint32_t ends[2];
        int found = 0;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = corner[k], b = corner[(k + 1) % 3];
            if (a >= count || b >= count) return;
            if (side_[a] != side_[b] && found < 2) ends[found++] = crossing(a, b);
        }
        if (found == 2 && ends[0] != ends[1]) segments_.push_back({ends[0], ends[1]});
    }

    /// The position where edge (a, b) crosses the plane, made once per edge.
    std::uint32_t crossing(std::uint32_t a, std::uint32_t b) {
        if (a > b) std::swap(a, b);
        auto [it, fresh] = points_.try_emplace({a, b}, 0);
        if (!fresh) return it->second;
        const double t = value_[a] / (value_[a] - value_[b]);
        const auto f = static_cast<float>(t);
        auto mix = [&](auto& list) {
            if (!list.empty()) list.push_back(glm::mix(list[a], list[b], f));
        };
        glm::dvec3 p = glm::mix(glm::dvec3(mesh_.positions[a]), glm::dvec3(mesh_.positions[b]), t);
        mix(mesh_.colours);
        mix(mesh_.uv);
        glm::dvec3 n = mesh_.normals.empty() ? glm::dvec3(0.0)
                                             : glm::mix(glm::dvec3(mesh_.normals[a].unpacked()),
                                                        glm::dvec3(mesh_.normals[b].unpacked()), t);
        if (surface_ && !mesh_.uv.empty()) onSurface(mesh_.uv[a], mesh_.uv[b], mesh_.uv.back(), p, n);
        if (!mesh_.normals.empty())
            mesh_.normals.push_back(glm::vec3(glm::length(n) > 0.0 ? glm::normalize(n) : n));
        mesh_.positions.push_back(glm::vec3(p));
        it->second = static_cast<std::uint32_t>(mesh_.positions.size() - 1);
        return it->second;
    }

    /// The root of the plane function on the exact surface along the (u, v) segment from
    /// `a` to `b` (Illinois regula falsi: the ends bracket it); keeps `p` and `n` when the
    /// surface's values at the ends do not change sign.
    void onSurface(glm::vec2 a, glm::vec2 b, glm::vec2& uvOut, glm::dvec3& p, glm::dvec3& n) const {
        const geom::Surface& s = *surface_;
        const glm::dvec3 normal(plane_);
        auto at = [&](double t) {
            const glm::dvec2 uv = glm::mix(glm::dvec2(a), glm::dvec2(b), t);
            return glm::dvec2(std::clamp(uv.x, s.domainStartU(), s.domainEndU()),
                              std::clamp(uv.y, s.domainStartV(), s.domainEndV()));
        };
        auto value = [&](double t) {
            const glm::dvec2 uv = at(t);
            return glm::dot(normal, geom::evaluate(s, uv.x, uv.y)) + plane_.w;
        };
        double t0 = 0.0, t1 = 1.0, f0 = value(t0), f1 = value(t1);
        if (!(f0 < 0.0 && f1 >= 0.0) && !(f0 >= 0.0 && f1 < 0.0)) return;
        const double tolerance = 1e-13 * (1.0 + glm::length(p));
        double t = t0;
        int side = 0;
        for (int step = 0; step < 60; ++step) {
            t = (t0 * f1 - t1 * f0) / (f1 - f0);
            const double f = value(t);
            if (std::abs(f) <= tolerance) break;
            if ((f < 0.0) == (f1 < 0.0)) {
                t1 = t, f1 = f;
                if (side == -1) f0 /= 2;
                side = -1;
            } else {
                t0 = t, f0 = f;
                if (side == 1) f1 /= 2;
                side = 1;
            }
        }
        const glm::dvec2 uv = at(t);
        p = geom::evaluate(s, uv.x, uv.y);
        n = geom::normal(s, uv.x, uv.y);
        uvOut = glm::vec2(uv);
    }

    /// Joins the segments into polylines: open chains from their ends first, then closed loops.
    void chain() {
        std::map<std::uint32_t, std::vector<std::size_t>> at;
        for (std::size_t k = 0; k < segments_.size(); ++k)
            at[segments_[k].first].push_back(k), at[segments_[k].second].push_back(k);
        std::vector<bool> used(segments_.size(), false);
        auto walk = [&](std::uint32_t start) {
            std::vector<std::uint32_t> line{start};
            for (std::uint32_t here = start;;) {
                std::size_t next = segments_.size();
                for (std::size_t k : at[here])
                    if (!used[k]) {
                        next = k;
                        break;
                    }
                if (next == segments_.size()) break;
                used[next] = true;
                here = segments_[next].first == here ? segments_[next].second : segments_[next].first;
                line.push_back(here);
            }
            if (line.size() >= 2) mesh_.isoLines.push_back(std::move(line));
        };
        for (const auto& [point, list] : at)
            if (list.size() == 1 && !used[list.front()]) walk(point);
        for (std::size_t k = 0; k < segments_.size(); ++k)
            if (!used[k]) walk(segments_[k].first);
    }

    MeshData& mesh_;
    glm::dvec4 plane_;
    const geom::Surface* surface_;
    std::vector<bool> side_;
    std::vector<double> value_;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> points_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> segments_;
};

}  // namespace

std::vector<glm::dvec4> levelPlanes(const SurfaceCharacteristicsAttribute& c,
                                    const glm::dmat4& modelToWorld) {
    std::vector<glm::dvec4> planes;
    if (c.style != 4 && c.style != 5) return planes;
    for (double t : c.levels) {
        const glm::dvec3 through = c.origin + t * c.direction;
        glm::dvec4 plane(c.direction, -glm::dot(c.direction, through));
        if (c.style == 5) plane = glm::transpose(modelToWorld) * plane;  // f(M x) = (M^T plane) . x
        const double length = glm::length(glm::dvec3(plane));
        if (length > 0.0 && std::isfinite(length) && std::isfinite(plane.w)) planes.push_back(plane / length);
    }
    return planes;
}

void addLevelCurves(MeshData& mesh, const std::vector<glm::dvec4>& planes, const geom::Surface* surface) {
    for (const glm::dvec4& plane : planes) PlaneCut(mesh, plane, surface).run();
}

}  // namespace phigs::detail
