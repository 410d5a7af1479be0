#include "phigs/pick/Picker.h"

#include "geom/Evaluate.h"
#include "geom/EvenOdd.h"

#include "geom/SurfaceIntersector.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/render/MeshEdges.h"
#include "phigs/traverse/ViewClipRectangle.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace phigs {
namespace {

/// A point after projection: NPC, or not drawable (behind the eye of a perspective view).
struct Projected {
    glm::dvec3 npc{0.0};
    bool valid = false;
};

Projected project(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    if (!(h.w > 1e-300)) return {};
    return {glm::dvec3(h) / h.w, true};
}

/// Whether a world point lies inside the item's model clipping volume (every half space).
/// True where `toNpc` and its inverse `fromNpc` can carry the pick line back into the surface's
/// own coordinates: the inverse is finite and the pair well conditioned. A modelling transform
/// that flattens (a scale of 0, or of 1e-300) makes that line a plane or an overflow; such a
/// surface is picked by its tessellation, as drawn.
bool lineMapsBack(const glm::dmat4& toNpc, const glm::dmat4& fromNpc) {
    double to = 0.0, from = 0.0;  // row-sum norms
    for (int r = 0; r < 4; ++r) {
        double a = 0.0, b = 0.0;
        for (int c = 0; c < 4; ++c) {
            if (!std::isfinite(fromNpc[c][r])) return false;
            a += std::abs(toNpc[c][r]), b += std::abs(fromNpc[c][r]);
        }
        to = std::max(to, a), from = std::max(from, b);
    }
    return to * from <= 1e10;
}

/// Whether a pick at `npc` can hit anything: a finite position inside the workstation window
/// (which clips everything) and an aperture that is not NaN or negative.
bool pickReaches(const DrawList& list, glm::dvec2 npc, double aperture) {
    return std::isfinite(npc.x) && std::isfinite(npc.y) && aperture >= 0.0 &&
           !(npc.x < list.windowMin.x || npc.x > list.windowMax.x || npc.y < list.windowMin.y ||
             npc.y > list.windowMax.y);
}

bool insideModelClip(const DrawItem& item, const glm::dvec3& world) {
    for (const glm::dvec4& plane : item.modelClipPlanes())
        if (glm::dot(glm::dvec3(plane), world) + plane.w < 0.0) return false;
    return true;
}

glm::dvec3 toWorld(const DrawItem& item, const glm::dvec3& modelling) {
    const glm::dvec4 h = item.modelTransform().get() * glm::dvec4(modelling, 1.0);
    return glm::dvec3(h) / h.w;
}

/// Whether the infinite line origin + t direction meets the box [lo, hi] (slabs).
bool lineMeetsBox(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& lo,
                  const glm::dvec3& hi) {
    double t0 = -std::numeric_limits<double>::infinity(), t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (direction[a] == 0.0) {
            if (origin[a] < lo[a] || origin[a] > hi[a]) return false;
            continue;
        }
        double ta = (lo[a] - origin[a]) / direction[a], tb = (hi[a] - origin[a]) / direction[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return !std::isnan(t0) && !std::isnan(t1);
}

/// Whether every control point lies strictly on one side of a plane through the line: then the
/// line misses the net's convex hull and the surface in it (weights are positive).
bool lineMissesHull(const std::vector<glm::dvec3>& points, const glm::dvec3& origin,
                    const glm::dvec3& direction) {
    const glm::dvec3 d = glm::normalize(direction);
    const glm::dvec3 axis = std::abs(d.x) < 0.5 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 n1 = glm::normalize(glm::cross(d, axis)), n2 = glm::cross(d, n1);
    double lo1 = std::numeric_limits<double>::infinity(), hi1 = -lo1, lo2 = lo1, hi2 = -lo1, reach = 0.0;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 e = p - origin;
        const double a = glm::dot(n1, e), b = glm::dot(n2, e);
        lo1 = std::min(lo1, a);
        hi1 = std::max(hi1, a);
        lo2 = std::min(lo2, b);
        hi2 = std::max(hi2, b);
        reach = std::max(reach, std::abs(e.x) + std::abs(e.y) + std::abs(e.z));
    }
    // Rounding: a hit point a few ulps outside the hull must not be lost.
    const double tolerance = 1e-9 * reach;
    return lo1 > tolerance || hi1 < -tolerance || lo2 > tolerance || hi2 < -tolerance;
}

/// The aperture: a square of half-size `half` around `centre` in NPC x, y.
struct Aperture {
    glm::dvec2 centre{0.0};
    double half = 0.0;
    bool contains(glm::dvec2 p, double grow = 0.0) const {
        return std::abs(p.x - centre.x) <= half + grow && std::abs(p.y - centre.y) <= half + grow;
    }
};

/// Whether segment a-b meets the aperture square (Liang-Barsky); on a hit, the depth at the
/// point of the segment nearest the aperture centre.
std::optional<double> segmentHit(const Aperture& ap, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec2 d(b.x - a.x, b.y - a.y);
    double t0 = 0.0, t1 = 1.0;
    const double p[4] = {-d.x, d.x, -d.y, d.y};
    const double q[4] = {a.x - (ap.centre.x - ap.half), (ap.centre.x + ap.half) - a.x,
                         a.y - (ap.centre.y - ap.half), (ap.centre.y + ap.half) - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return std::nullopt;
        } else {
            const double r = q[i] / p[i];
            if (p[i] < 0.0)
                t0 = std::max(t0, r);
            else
                t1 = std::min(t1, r);
        }
    }
    if (t0 > t1) return std::nullopt;
    const double len2 = glm::dot(d, d);
    double t = len2 > 0 ? glm::dot(ap.centre - glm::dvec2(a), d) / len2 : 0.0;
    t = std::clamp(t, t0, t1);
    return a.z + t * (b.z - a.z);
}

/// Nearest (largest z) hit of a polyline's segments; closed adds the last-to-first segment.
std::optional<double> polylineHit(const Aperture& ap, const std::vector<Projected>& pts, bool closed) {
    std::optional<double> best;
    const std::size_t n = pts.size();
    if (n == 1 && pts[0].valid && ap.contains(glm::dvec2(pts[0].npc))) return pts[0].npc.z;
    const std::size_t segments = closed && n > 2 ? n : (n > 0 ? n - 1 : 0);
    for (std::size_t i = 0; i < segments; ++i) {
        const Projected& a = pts[i];
        const Projected& b = pts[(i + 1) % n];
        if (!a.valid || !b.valid) continue;
        if (const auto z = segmentHit(ap, a.npc, b.npc); z && (!best || *z > *best)) best = z;
    }
    return best;
}

/// Even-odd inside test of a point against a set of contours (projected to NPC x, y).
bool insideEvenOdd(glm::dvec2 p, const std::vector<std::vector<Projected>>& contours) {
    return geom::insideEvenOdd(p, contours, [](const Projected& q) { return glm::dvec2(q.npc); });
}

/// Depth at (x, y) of the plane through the contours (render::contoursNormal in NPC); nullopt when
/// the plane is seen edge on.
std::optional<double> planeDepth(glm::dvec2 p, const std::vector<std::vector<Projected>>& contours) {
    std::vector<std::vector<glm::dvec3>> npc;
    glm::dvec3 centroid(0.0);
    std::size_t count = 0;
    for (const auto& c : contours) {
        npc.emplace_back();
        for (const Projected& q : c) npc.back().push_back(q.npc), centroid += q.npc, ++count;
    }
    if (count == 0) return std::nullopt;
    centroid /= static_cast<double>(count);
    // As the renderers find the plane (where signed areas cancel too: a bow-tie, contours wound
    // against each other).
    const glm::dvec3 normal = render::contoursNormal(npc);
    const double len = glm::length(normal);
    if (!(len > 0) || std::abs(normal.z) < 1e-12 * len) return std::nullopt;
    return centroid.z - (normal.x * (p.x - centroid.x) + normal.y * (p.y - centroid.y)) / normal.z;
}

/// A planar region (fill area set, text box): the centre inside counts when `interior`, the
/// boundary under the aperture when `boundary`.
std::optional<double> regionHit(const Aperture& ap, const std::vector<std::vector<Projected>>& contours,
                                bool interior, bool boundary) {
    for (const auto& c : contours)
        for (const auto& p : c)
            if (!p.valid) return std::nullopt;
    std::optional<double> best;
    if (interior && insideEvenOdd(ap.centre, contours)) best = planeDepth(ap.centre, contours);
    if (boundary || interior) {
        for (const auto& c : contours)
            if (const auto z = polylineHit(ap, c, true); z && (!best || *z > *best)) best = z;
    }
    return best;
}

/// A fill area under the aperture: the side the view shows by its own interior style (its back's
/// with face distinguishing on), a culled side not at all: the interior counts for SOLID, HATCH and
/// PATTERN, the boundary for a HOLLOW side (render::hollowOutline, as drawn) and for
/// visible edges (drawn whichever side shows).
std::optional<double> fillAreaHit(const Aperture& ap, const DrawItem& item, const DrawView& view,
                                  const DrawFillArea& f,
                                  const std::vector<std::vector<Projected>>& contours) {
    const InteriorStyleSet& in = *f.interior;
    const int side = render::sideShown(render::fillAreaPlane(f, item.modelTransform().get()),
                                       view.mapping * view.orientation);
    const bool culled =
        (side > 0 && in.cull == CullMode::FrontFaces) || (side < 0 && in.cull == CullMode::BackFaces);
    const InteriorStyle s = in.styleOf(side < 0);
    const bool interior = !culled && s != InteriorStyle::Hollow && s != InteriorStyle::Empty;
    glm::vec3 colour;
    const bool outline = render::hollowOutline(in, 0, colour) || render::hollowOutline(in, side, colour);
    return regionHit(ap, contours, interior, outline || f.edges->visible);
}

/// What a mesh shows each side of its triangles as, by side (0 back, 1 front; an edge-on triangle
/// counts as front, as the renderers draw it): filled (SOLID, HATCH, PATTERN, not culled), outlined
/// (a HOLLOW side, render::hollowOutline, as drawn) or neither; edges show either way. A NURBS
/// surface's EMPTY side counts as filled: PHIGS keeps an EMPTY interior detectable, and a wireframe
/// picks points inside a surface's patches, with their (u, v).
struct MeshSides {
    bool filled[2] = {false, false};
    bool outlined[2] = {false, false};

    MeshSides(const InteriorStyleSet& in, bool edges, bool surface) {
        filled[1] = in.fillsFrontFaces() ||
                    (surface && in.style == InteriorStyle::Empty && in.cull != CullMode::FrontFaces);
        filled[0] = in.fillsBackFaces() ||
                    (surface && in.styleOf(true) == InteriorStyle::Empty && in.cull != CullMode::BackFaces);
        glm::vec3 colour;
        const bool alike = render::hollowOutline(in, 0, colour);
        outlined[1] = edges || alike || render::hollowOutline(in, 1, colour);
        outlined[0] = edges || alike || render::hollowOutline(in, -1, colour);
    }
    bool anyOutline() const { return outlined[0] || outlined[1]; }
};

/// Nearest triangle of a mesh under the aperture, each by the side it shows (its NPC winding): a
/// filled side anywhere it overlaps the aperture, an outlined one by its facet edges (`facetEdges`,
/// render::meshFacetEdges), the others not at all; `filledToo` false leaves filled sides out.
std::optional<double> meshHit(const Aperture& ap, const std::vector<Projected>& pts,
                              const std::vector<std::uint32_t>& triangles, const MeshSides& sides,
                              const std::vector<std::uint8_t>& facetEdges, bool filledToo = true) {
    std::optional<double> best;
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const Projected& a = pts[triangles[t]];
        const Projected& b = pts[triangles[t + 1]];
        const Projected& c = pts[triangles[t + 2]];
        if (!a.valid || !b.valid || !c.valid) continue;
        // Most triangles lie clear of the aperture: reject them by their box.
        const double x0 = ap.centre.x - ap.half, x1 = ap.centre.x + ap.half;
        const double y0 = ap.centre.y - ap.half, y1 = ap.centre.y + ap.half;
        if (std::max({a.npc.x, b.npc.x, c.npc.x}) < x0 || std::min({a.npc.x, b.npc.x, c.npc.x}) > x1 ||
            std::max({a.npc.y, b.npc.y, c.npc.y}) < y0 || std::min({a.npc.y, b.npc.y, c.npc.y}) > y1)
            continue;
        // Barycentric coordinates of the centre; den is twice the signed area (> 0: the front).
        const glm::dvec2 v0(b.npc - a.npc), v1(c.npc - a.npc), v2(ap.centre - glm::dvec2(a.npc));
        const double den = v0.x * v1.y - v1.x * v0.y;
        const int side = den >= 0.0 ? 1 : 0;
        const bool filled = filledToo && sides.filled[side];
        if (!filled && !sides.outlined[side]) continue;
        std::optional<double> z;
        if (filled && den != 0.0) {
            const double s = (v2.x * v1.y - v1.x * v2.y) / den;
            const double r = (v0.x * v2.y - v2.x * v0.y) / den;
            if (s >= 0 && r >= 0 && s + r <= 1)
                z = a.npc.z + s * (b.npc.z - a.npc.z) + r * (c.npc.z - a.npc.z);
        }
        if (!z) {
            // A filled side overlapping the aperture meets it with an edge, diagonals too; an
            // outline is its facet edges only.
            const std::uint8_t edges = filled ? 7 : t / 3 < facetEdges.size() ? facetEdges[t / 3] : 7;
            const Projected* corner[3] = {&a, &b, &c};
            for (int e = 0; e < 3; ++e)
                if (edges >> e & 1)
                    if (const auto h = segmentHit(ap, corner[e]->npc, corner[(e + 1) % 3]->npc);
                        h && (!z || *h > *z))
                        z = h;
        }
        if (z && (!best || *z > *best)) best = z;
    }
    return best;
}

bool insideClip(const DrawView& view, const glm::dvec3& npc) {
    const double eps = 1e-12;
    if (view.clipXY && (npc.x < view.clipMin.x - eps || npc.x > view.clipMax.x + eps ||
                        npc.y < view.clipMin.y - eps || npc.y > view.clipMax.y + eps))
        return false;
    if (view.clipBack && npc.z < view.clipMin.z - eps) return false;
    if (view.clipFront && npc.z > view.clipMax.z + eps) return false;
    return true;
}

/// Whether the box lo..hi (modelling coordinates) may meet the aperture once projected by `m`:
/// false only when all its corners project and their NPC box misses the aperture.
bool boxNearAperture(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dmat4& m, const Aperture& ap) {
    glm::dvec2 min(std::numeric_limits<double>::max()), max(std::numeric_limits<double>::lowest());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 c((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                           (corner & 4) ? hi.z : lo.z);
        const Projected q = project(m, c);
        if (!q.valid) return true;
        min = glm::min(min, glm::dvec2(q.npc));
        max = glm::max(max, glm::dvec2(q.npc));
    }
    return !(ap.centre.x + ap.half < min.x || ap.centre.x - ap.half > max.x ||
             ap.centre.y + ap.half < min.y || ap.centre.y - ap.half > max.y);
}

template <typename Points>
std::vector<Projected> projectAll(const glm::dmat4& m, const Points& points) {
    std::vector<Projected> out;
    out.reserve(points.size());
    for (const auto& p : points) out.push_back(project(m, glm::dvec3(p)));
    return out;
}

/// The four corners of a text string's box in its own plane: character boxes of height ×
/// height·expansion, spacing between them, placed by the path and alignment.
std::vector<glm::dvec2> textBox(const DrawText& text) {
    const TextStyle& s = text.style;
    const double h = s.height;
    const double w = h * s.expansion;
    const double n = static_cast<double>(std::max<std::size_t>(text.text.size(), 1));
    const bool horizontal = s.path == TextPath::Right || s.path == TextPath::Left;
    const double width = horizontal ? n * w + (n - 1) * s.spacing * h : w;
    const double height = horizontal ? h : n * h + (n - 1) * s.spacing * h;
    double x0 = 0, y0 = 0;
    HorizontalAlignment ha = s.horizontal;
    if (ha == HorizontalAlignment::Normal)
        ha = s.path == TextPath::Left
                 ? HorizontalAlignment::Right
                 : (horizontal ? HorizontalAlignment::Left : HorizontalAlignment::Centre);
    if (ha == HorizontalAlignment::Centre) x0 = -width / 2;
    if (ha == HorizontalAlignment::Right) x0 = -width;
    VerticalAlignment va = s.vertical;
    if (va == VerticalAlignment::Normal)
        va = s.path == TextPath::Down ? VerticalAlignment::Top : VerticalAlignment::Base;
    if (va == VerticalAlignment::Top || va == VerticalAlignment::Cap) y0 = -height;
    if (va == VerticalAlignment::Half) y0 = -height / 2;
    return {{x0, y0}, {x0 + width, y0}, {x0 + width, y0 + height}, {x0, y0 + height}};
}

}  // namespace

Picker::Picker() = default;
Picker::~Picker() = default;

void Picker::clearCache() const {
    intersectors_.clear();
    bounds_.clear();
    tree_.clear();
}

void Picker::prune(const DrawList& list) const {
    if (list.generation == generation_) return;
    generation_ = list.generation;
    std::erase_if(intersectors_, [](const auto& e) { return e.second.surface.use_count() == 1; });
    std::erase_if(bounds_, [](const auto& e) { return e.second.mesh.use_count() == 1; });
}

const Picker::CachedBounds& Picker::boundsOf(const std::shared_ptr<const MeshData>& mesh) const {
    auto it = bounds_.find(mesh.get());
    if (it != bounds_.end()) return it->second;
    CachedBounds b{mesh,
                   glm::dvec3(std::numeric_limits<double>::max()),
                   glm::dvec3(std::numeric_limits<double>::lowest()),
                   {}};
    for (const glm::vec3& p : mesh->positions) {
        b.min = glm::min(b.min, glm::dvec3(p));
        b.max = glm::max(b.max, glm::dvec3(p));
    }
    return bounds_.emplace(mesh.get(), std::move(b)).first->second;
}

const std::vector<std::uint8_t>& Picker::facetEdgesOf(const std::shared_ptr<const MeshData>& mesh) const {
    boundsOf(mesh);
    CachedBounds& b = bounds_.find(mesh.get())->second;
    if (b.facetEdges.size() != mesh->triangles.size() / 3) b.facetEdges = render::meshFacetEdges(*mesh);
    return b.facetEdges;
}

std::optional<PickHit> Picker::testSurface(const DrawItem& item, const DrawView& view,
                                           const std::shared_ptr<const geom::Surface>& surface,
                                           const MeshData* mesh, const InteriorStyleSet& interior,
                                           glm::dvec2 npc, const glm::dmat4& m, const glm::dmat4& inverse,
                                           const PickItemBounds* bounds) const {
    const MeshSides sides(interior, false, true);
    if (!sides.filled[0] && !sides.filled[1]) return std::nullopt;
    const glm::dvec4 front = inverse * glm::dvec4(npc, 1.0, 1.0);
    const glm::dvec4 back = inverse * glm::dvec4(npc, 0.0, 1.0);
    if (front.w == 0.0 || back.w == 0.0) return std::nullopt;
    const glm::dvec3 origin = glm::dvec3(front) / front.w;
    const glm::dvec3 direction = glm::dvec3(back) / back.w - origin;
    const double span = glm::dot(direction, direction);
    if (!std::isfinite(glm::dot(origin, origin)) || !std::isfinite(span) || !(span > 0.0))
        return std::nullopt;
    // The surface lies in its control net's box: a line that misses the box misses the surface.
    if (bounds && bounds->surfaceLo.x <= bounds->surfaceHi.x &&
        !lineMeetsBox(origin, direction, bounds->surfaceLo, bounds->surfaceHi))
        return std::nullopt;
    if (bounds && glm::dot(direction, direction) > 0.0 && lineMissesHull(surface->points, origin, direction))
        return std::nullopt;
    auto it = intersectors_.find(surface.get());
    if (it == intersectors_.end())
        it = intersectors_
                 .emplace(surface.get(),
                          CachedSurface{surface, std::make_unique<geom::SurfaceIntersector>(*surface)})
                 .first;
    const glm::dvec4 viewer = render::meshViewer(m);
    for (const geom::LineSurfaceHit& h : it->second.intersector->intersect(origin, direction)) {
        const Projected p = project(m, h.point);
        if (!p.valid || !insideClip(view, p.npc) || !insideModelClip(item, toWorld(item, h.point))) continue;
        // A hole trimmed away lets the line on through, as the picture shows what lies behind.
        if (mesh && !mesh->keeps(h.uv)) continue;
        // The side shown there (the tangent plane against the viewer, as the triangles are drawn;
        // edge on is the front): a HOLLOW or culled one lets the line on through to the next hit.
        const glm::dvec3 normal = geom::normal(*surface, h.uv.x, h.uv.y);
        const double s = glm::dot(normal, glm::dvec3(viewer)) - viewer.w * glm::dot(normal, h.point);
        if (!sides.filled[s >= 0.0 ? 1 : 0]) continue;
        SurfacePickDetail detail{h.point, normal, h.uv, h.piece};
        return PickHit{0, p.npc.z, detail};
    }
    return std::nullopt;
}

std::optional<PickHit> Picker::test(const DrawList& list, std::size_t index, glm::dvec2 npc, double aperture,
                                    const WorkstationMapping& mapping, SurfaceTest surfaceTest,
                                    const PickItemBounds* bounds) const {
    const DrawItem& item = list.items[index];
    if (!item.pickable()) return std::nullopt;
    const auto* drawMesh = primitiveIf<DrawMesh>(item.primitive);
    const bool exactSurface = drawMesh && drawMesh->surface;
    if (surfaceTest == SurfaceTest::Tessellation && !exactSurface) return std::nullopt;
    if (item.viewIndex() < 0 || static_cast<std::size_t>(item.viewIndex()) >= list.views.size())
        return std::nullopt;
    const DrawView& view = list.views[static_cast<std::size_t>(item.viewIndex())];
    if (view.clipXY && (npc.x < view.clipMin.x || npc.x > view.clipMax.x || npc.y < view.clipMin.y ||
                        npc.y > view.clipMax.y))
        return std::nullopt;
    const glm::dmat4 m =
        bounds ? bounds->toNpc : view.mapping * view.orientation * item.modelTransform().get();
    const Aperture ap{npc, aperture};

    std::optional<PickHit> hit;
    visitPrimitive(
        [&](const auto& p) {
            using T = std::decay_t<decltype(p)>;
            std::optional<double> z;
            if constexpr (kDrawsStrip<T>) {
                z = polylineHit(ap, projectAll(m, stripPoints(p)), false);
            } else if constexpr (std::is_same_v<T, DrawPolymarker>) {
                // The marker's own size widens the aperture (nominal 7 pixels times the scale).
                const double grow = mapping.npcLength(3.5 * p.style->scale);
                const ViewClipRectangle kept(view, list.windowMin, list.windowMax);
                // A marker is clipped by its position, as drawn: one outside the view's clip
                // limits or the workstation window is not hit where its glyph would reach in.
                for (const glm::dvec3& point : p.points) {
                    const Projected q = project(m, point);
                    if (q.valid && ap.contains(glm::dvec2(q.npc), grow) && (!z || q.npc.z > *z) &&
                        insideClip(view, q.npc) && kept.contains(glm::dvec2(q.npc)) &&
                        insideModelClip(item, toWorld(item, point)))
                        z = q.npc.z;
                }
            } else if constexpr (std::is_same_v<T, DrawFillArea>) {
                std::vector<std::vector<Projected>> contours;
                for (const auto& c : p.contours) contours.push_back(projectAll(m, c));
                z = fillAreaHit(ap, item, view, p, contours);
            } else if constexpr (std::is_same_v<T, DrawText>) {
                std::vector<std::vector<Projected>> box(1);
                const glm::dvec2 up =
                    glm::length(p.style->upVector) > 0 ? glm::normalize(p.style->upVector) : glm::dvec2(0, 1);
                const glm::dvec2 base(up.y, -up.x);
                if (p.annotation) {
                    // Kept or dropped whole by its reference point, as drawn (ISO 9592).
                    const Projected ref = project(m, p.position);
                    const ViewClipRectangle kept(view, list.windowMin, list.windowMax);
                    if (!ref.valid || !insideClip(view, ref.npc) || !kept.contains(glm::dvec2(ref.npc)) ||
                        !insideModelClip(item, toWorld(item, p.position)))
                        return;
                    for (const glm::dvec2& c : textBox(p)) {
                        const glm::dvec2 q = c.x * base + c.y * up;
                        box[0].push_back({ref.npc + p.annotationOffset + glm::dvec3(q, 0.0), ref.valid});
                    }
                } else {
                    const glm::dvec3 d1 = glm::normalize(p.direction1);
                    const glm::dvec3 d2 = glm::normalize(p.direction2 - glm::dot(p.direction2, d1) * d1);
                    for (const glm::dvec2& c : textBox(p)) {
                        const glm::dvec2 q = c.x * base + c.y * up;
                        box[0].push_back(project(m, p.position + q.x * d1 + q.y * d2));
                    }
                }
                z = regionHit(ap, box, true, true);
            } else if constexpr (std::is_same_v<T, DrawMesh>) {
                // Each triangle by the side it shows; a surface's filled sides exactly, its outlines
                // (HOLLOW sides, edges) and iso-lines by the tessellation. An exact hit keeps its
                // (u, v): a nearer outline or iso-line only brings the hit's depth forward.
                const MeshSides sides(*p.interior, p.edges->visible, p.surface != nullptr);
                const glm::dmat4 fromNpc = p.surface ? (bounds ? bounds->fromNpc : glm::inverse(m)) : m;
                const bool exact = p.surface && surfaceTest == SurfaceTest::Exact && lineMapsBack(m, fromNpc);
                const bool lines = sides.anyOutline() || (p.mesh && !p.mesh->isoLines.empty());
                if (exact) {
                    hit = testSurface(item, view, p.surface, p.mesh.get(), *p.interior, npc, m, fromNpc,
                                      bounds);
                    if (!lines) return;
                }
                if (p.mesh && !p.mesh->positions.empty()) {
                    // Reject by the projected box first: most meshes lie far from the aperture.
                    const CachedBounds& b = boundsOf(p.mesh);
                    if (!boxNearAperture(b.min, b.max, m, ap)) return;
                    const auto projected = projectAll(m, p.mesh->positions);
                    const std::vector<std::uint8_t> none;
                    if (!exact || sides.anyOutline())
                        z = meshHit(ap, projected, p.mesh->triangles, sides,
                                    sides.anyOutline() ? facetEdgesOf(p.mesh) : none, !exact);
                    // Iso-lines are the tessellation's: in the exact pass they only bring the
                    // surface's own exact hit forward, else a nearer iso-line of a patch beside
                    // would win over the exact hit under the centre, without (u, v).
                    for (const auto& line : p.mesh->isoLines) {
                        if (exact && !hit) break;
                        std::vector<Projected> pts;
                        for (std::uint32_t i : line) pts.push_back(projected[i]);
                        if (const auto e = polylineHit(ap, pts, false); e && (!z || *e > *z)) z = e;
                    }
                    if (exact && z && hit) {
                        hit->depth = std::max(hit->depth, *z);
                        return;
                    }
                }
            } else {
                static_assert(kUnhandledPrimitive<T>);
            }
            if (z) hit = PickHit{0, *z, std::nullopt};
        },
        item.primitive);
    if (!hit) return std::nullopt;
    hit->item = index;
    // Model clipping: the point under the aperture centre at the hit's depth must be kept
    // (markers, annotation text and surfaces were tested at their own points above).
    const auto* text = primitiveIf<DrawText>(item.primitive);
    if (!item.modelClipPlanes().empty() && !hit->surface &&
        !std::holds_alternative<DrawPolymarker>(item.primitive) && !(text && text->annotation)) {
        const glm::dvec4 h = glm::inverse(view.mapping * view.orientation) * glm::dvec4(npc, hit->depth, 1.0);
        if (h.w == 0.0 || !insideModelClip(item, glm::dvec3(h) / h.w)) return std::nullopt;
    }
    // Depth clipping: the part under the aperture must lie between the view's z planes.
    if ((view.clipBack && hit->depth < view.clipMin.z - 1e-12) ||
        (view.clipFront && hit->depth > view.clipMax.z + 1e-12))
        return std::nullopt;
    return hit;
}

std::vector<PickHit> Picker::hits(const DrawList& list, glm::dvec2 npc, double aperture) const {
    return hits(list, WorkstationMapping(list), npc, aperture);
}

std::vector<PickHit> Picker::hits(const DrawList& list, const WorkstationMapping& mapping, glm::dvec2 npc,
                                  double aperture) const {
    std::vector<PickHit> out;
    if (!pickReaches(list, npc, aperture)) return out;
    if (accelerated_) tree_.update(list);  // first: it lets go of surfaces the list dropped
    prune(list);
    if (accelerated_) {
        candidates_.clear();
        tree_.query(npc, aperture, candidates_);
        for (std::size_t i : candidates_)
            if (auto h = test(list, i, npc, aperture, mapping, SurfaceTest::Exact, &tree_.item(i)))
                out.push_back(std::move(*h));
        if (out.empty())
            for (std::size_t i : candidates_)
                if (auto h = test(list, i, npc, aperture, mapping, SurfaceTest::Tessellation, &tree_.item(i)))
                    out.push_back(std::move(*h));
    } else {
        for (std::size_t i = 0; i < list.items.size(); ++i)
            if (auto h = test(list, i, npc, aperture, mapping, SurfaceTest::Exact))
                out.push_back(std::move(*h));
        if (out.empty())
            for (std::size_t i = 0; i < list.items.size(); ++i)
                if (auto h = test(list, i, npc, aperture, mapping, SurfaceTest::Tessellation))
                    out.push_back(std::move(*h));
    }
    std::stable_sort(out.begin(), out.end(), [](const PickHit& a, const PickHit& b) {
        if (a.depth != b.depth) return a.depth > b.depth;
        return a.item > b.item;
    });
    return out;
}

std::optional<PickHit> Picker::nearest(const DrawList& list, glm::dvec2 npc, double aperture) const {
    return nearest(list, WorkstationMapping(list), npc, aperture);
}

std::optional<PickHit> Picker::nearest(const DrawList& list, const WorkstationMapping& mapping,
                                       glm::dvec2 npc, double aperture) const {
    if (accelerated_) return nearestAccelerated(list, mapping, npc, aperture);
    auto all = hits(list, mapping, npc, aperture);
    if (all.empty()) return std::nullopt;
    return all.front();
}

std::optional<PickHit> Picker::nearestAccelerated(const DrawList& list, const WorkstationMapping& mapping,
                                                  glm::dvec2 npc, double aperture) const {
    if (!pickReaches(list, npc, aperture)) return std::nullopt;
    tree_.update(list);  // first: it lets go of surfaces the list dropped
    prune(list);
    candidates_.clear();
    tree_.query(npc, aperture, candidates_);
    // Nearest box first (NPC z grows toward the eye); a hit lies in its item's box, so once the
    // best hit is nearer than a box's front no later candidate can win. Ties go to the item
    // drawn later, as in hits().
    std::sort(candidates_.begin(), candidates_.end(), [&](std::size_t a, std::size_t b) {
        const double za = tree_.item(a).hi.z, zb = tree_.item(b).hi.z;
        return za != zb ? za > zb : a > b;
    });
    std::optional<PickHit> best;
    for (SurfaceTest pass : {SurfaceTest::Exact, SurfaceTest::Tessellation}) {
        for (std::size_t i : candidates_) {
            const PickItemBounds& bounds = tree_.item(i);
            if (best && bounds.hi.z < best->depth) break;
            auto h = test(list, i, npc, aperture, mapping, pass, &bounds);
            if (h && (!best || h->depth > best->depth || (h->depth == best->depth && h->item > best->item)))
                best = std::move(h);
        }
        // Tessellations count only when nothing at all was hit exactly.
        if (best) break;
    }
    return best;
}

PickMeasure Picker::pick(const DrawList& list, glm::dvec2 npc, const PickOptions& options) const {
    PickMeasure measure;
    const auto hit = nearest(list, npc, options.aperture);
    if (!hit) return measure;
    measure.status = InputStatus::Ok;
    measure.path = pickPath(list.items[hit->item].source, options.order, options.depth);
    measure.surface = hit->surface;
    return measure;
}

std::vector<PickPathItem> pickPath(const DrawSource& source, PathOrder order, int depth) {
    std::vector<PickPathItem> path;
    for (const DrawPathLevel& l : source.path()) path.push_back({l.structureId, l.elementNumber, l.pickId});
    if (order == PathOrder::BottomFirst) std::reverse(path.begin(), path.end());
    if (depth > 0 && static_cast<std::size_t>(depth) < path.size())
        path.resize(static_cast<std::size_t>(depth));
    return path;
}

std::vector<std::size_t> echoItems(const DrawList& list, const PickHit& hit, bool wholeStructure) {
    std::vector<std::size_t> out;
    if (hit.item >= list.items.size()) return out;
    const auto& path = list.items[hit.item].source.path();
    if (path.empty()) return {hit.item};
    // The structure instance: the levels above the primitive, and the structure it sits in.
    const std::size_t prefix = path.size() - 1;
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const auto& other = list.items[i].source.path();
        const bool same = wholeStructure
                              ? other.size() == path.size() &&
                                    std::equal(path.begin(), path.begin() + prefix, other.begin()) &&
                                    other.back().structureId == path.back().structureId
                              : other == path;
        if (same) out.push_back(i);
    }
    return out;
}

}  // namespace phigs
