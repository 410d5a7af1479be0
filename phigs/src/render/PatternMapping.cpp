#include "phigs/render/PatternMapping.h"

#include "phigs/core/TransformUtilities.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <variant>

namespace phigs::render {
namespace {

struct Plane {
    glm::dvec3 point{0.0}, normal{0.0};
};

/// Whether either side of an interior is drawn with the PATTERN style.
bool patterned(const InteriorStyleSet& in) {
    return in.styleOf(false) == InteriorStyle::Pattern || in.styleOf(true) == InteriorStyle::Pattern;
}

/// The plane of a fill area's contours in world coordinates (Newell's normal), if they span one.
std::optional<Plane> fillPlane(const DrawFillArea& fill, const glm::dmat4& model) {
    Plane plane;
    bool first = true;
    for (const auto& contour : fill.contours)
        for (std::size_t i = 0; i < contour.size(); ++i) {
            const glm::dvec3 a = projectPoint3(model, contour[i]),
                             b = projectPoint3(model, contour[(i + 1) % contour.size()]);
            if (first) plane.point = a, first = false;
            plane.normal +=
                glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        }
    if (glm::length(plane.normal) <= 0.0) return std::nullopt;
    plane.normal = glm::normalize(plane.normal);
    return plane;
}

/// The plane of a mesh in world coordinates when all its positions lie on one (to a millionth of
/// its size), else null.
std::optional<Plane> meshPlane(const MeshData& mesh, const glm::dmat4& model) {
    if (mesh.positions.empty()) return std::nullopt;
    std::vector<glm::dvec3> world;
    world.reserve(mesh.positions.size());
    glm::dvec3 low(1e300), high(-1e300);
    for (const glm::vec3& p : mesh.positions) {
        world.push_back(projectPoint3(model, glm::dvec3(p)));
        low = glm::min(low, world.back());
        high = glm::max(high, world.back());
    }
    Plane plane{world.front(), glm::dvec3(0.0)};
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3)
        plane.normal += glm::cross(world[mesh.triangles[t + 1]] - world[mesh.triangles[t]],
                                   world[mesh.triangles[t + 2]] - world[mesh.triangles[t]]);
    if (glm::length(plane.normal) <= 0.0) return std::nullopt;
    plane.normal = glm::normalize(plane.normal);
    const double tolerance = 1e-6 * glm::length(high - low);
    for (const glm::dvec3& p : world)
        if (std::abs(glm::dot(p - plane.point, plane.normal)) > tolerance) return std::nullopt;
    return plane;
}

}  // namespace

glm::dvec2 PatternMap::at(const glm::dvec3& world) const {
    return {glm::dot(glm::dvec3(u), world) + u.w, glm::dot(glm::dvec3(v), world) + v.w};
}

const DrawPattern* findPattern(const DrawList& list, int index) {
    auto it = list.patterns.find(index);
    if (it == list.patterns.end()) it = list.patterns.find(1);
    return it == list.patterns.end() ? nullptr : &it->second;
}

std::optional<PatternMap> patternMap(const PatternPlacement& placement, const glm::dmat4& model,
                                     const DrawPattern& pattern, const glm::dvec3& planePoint,
                                     const glm::dvec3& planeNormal) {
    const double lx = glm::length(placement.vectorX), ly = glm::length(placement.vectorY);
    if (lx <= 0.0 || ly <= 0.0 || glm::length(planeNormal) <= 0.0) return std::nullopt;
    // The pattern box's corner and edges in world coordinates.
    const glm::dvec3 origin = projectPoint3(model, placement.referencePoint);
    glm::dvec3 a =
        projectPoint3(model, placement.referencePoint + placement.vectorX * (placement.size.x / lx)) - origin;
    glm::dvec3 b =
        projectPoint3(model, placement.referencePoint + placement.vectorY * (placement.size.y / ly)) - origin;
    // Projected orthogonally onto the primitive's plane.
    const glm::dvec3 n = glm::normalize(planeNormal);
    const glm::dvec3 corner = origin - glm::dot(origin - planePoint, n) * n;
    a -= glm::dot(a, n) * n;
    b -= glm::dot(b, n) * n;
    // x - corner = s a + t b on the plane: (s, t) from the Gram matrix of a and b.
    const double aa = glm::dot(a, a), ab = glm::dot(a, b), bb = glm::dot(b, b);
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-12 * aa * bb) || !std::isfinite(det)) return std::nullopt;
    const glm::dvec3 rowS = (bb * a - ab * b) / det, rowT = (aa * b - ab * a) / det;
    PatternMap map;
    map.u = glm::dvec4(rowS, -glm::dot(rowS, corner)) * double(pattern.columns);
    map.v = glm::dvec4(rowT, -glm::dot(rowT, corner)) * double(pattern.rows);
    return map;
}

std::optional<PatternMap> itemPatternMap(const DrawItem& item, const DrawPattern& pattern) {
    const glm::dmat4& model = item.modelTransform().get();
    if (const auto* fill = primitiveIf<DrawFillArea>(item.primitive)) {
        if (!patterned(fill->interior)) return std::nullopt;
        const std::optional<Plane> plane = fillPlane(*fill, model);
        if (!plane) return std::nullopt;
        return patternMap(fill->interior->pattern, model, pattern, plane->point, plane->normal);
    }
    if (const auto* mesh = primitiveIf<DrawMesh>(item.primitive)) {
        if (!patterned(mesh->interior) || !mesh->mesh) return std::nullopt;
        if (const std::optional<Plane> plane = meshPlane(*mesh->mesh, model))
            return patternMap(mesh->interior->pattern, model, pattern, plane->point, plane->normal);
        // A curved surface: its points take the cell of their projection onto the pattern's plane.
        const PatternPlacement& p = mesh->interior->pattern;
        const glm::dvec3 origin = projectPoint3(model, p.referencePoint);
        const glm::dvec3 normal = glm::cross(projectPoint3(model, p.referencePoint + p.vectorX) - origin,
                                             projectPoint3(model, p.referencePoint + p.vectorY) - origin);
        return patternMap(p, model, pattern, origin, normal);
    }
    return std::nullopt;
}

glm::vec3 patternColour(const DrawPattern& pattern, const glm::dvec2& cell) {
    if (pattern.columns < 1 || pattern.rows < 1 || pattern.colours.empty()) return glm::vec3(1.0f);
    auto wrap = [](double x, int n) {
        const double f = std::floor(x);
        const double m = std::fmod(f, double(n));
        return int(m < 0.0 ? m + n : m);
    };
    const std::size_t index = std::size_t(wrap(cell.y, pattern.rows)) * std::size_t(pattern.columns) +
                              std::size_t(wrap(cell.x, pattern.columns));
    return pattern.colours[std::min(index, pattern.colours.size() - 1)];
}

}  // namespace phigs::render
