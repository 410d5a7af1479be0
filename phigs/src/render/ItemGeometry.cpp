#include "phigs/render/ItemGeometry.h"

#include "phigs/core/ColourModels.h"
#include "phigs/core/TransformUtilities.h"
#include "phigs/render/LinePattern.h"
#include "phigs/render/MarkerShape.h"
#include "phigs/render/MeshEdges.h"
#include "phigs/render/StrokeFont.h"
#include "phigs/render/Triangulation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace phigs::render {
namespace {

/// The colour at `t` from `a` to `b` mixed in the rendering colour model, as the renderer
/// interpolates (clamped to [0, 1] first outside RGB, shaders/colour_models.glsl), so a vertex the
/// triangulation cuts on an edge carries the colour the edge has there.
glm::vec3 mixIn(ColourModel model, glm::vec3 a, glm::vec3 b, double t) {
    if (model == ColourModel::Rgb) return glm::mix(a, b, float(t));
    if (t == 0.0 || t == 1.0) return t == 0.0 ? a : b;
    const glm::dvec3 from = fromRgb(model, glm::clamp(glm::dvec3(a), 0.0, 1.0));
    const glm::dvec3 to = fromRgb(model, glm::clamp(glm::dvec3(b), 0.0, 1.0));
    return glm::vec3(toRgb(model, from * (1.0 - t) + to * t));
}

class Builder {
public:
    Builder(const DrawItem& item, const glm::dmat4& worldToPixels, double pixelsPerNpc)
        : model_(item.modelTransform().get()), toPixels_(worldToPixels), pixelsPerNpc_(pixelsPerNpc) {}

    ItemGeometry geometry;

    /// Line strips in world coordinates as a line list, with the screen distance for patterns.
    /// `colours` (when given, one per point of the one strip) colour the segments as DrawColouredPolyline
    /// says; the pattern distance runs on along each whole strip.
    void lineStrips(const std::vector<std::vector<glm::dvec3>>& strips, bool closed, PartRole role,
                    glm::vec3 colour, LineType type, float width, std::span<const glm::vec3> colours = {},
                    bool interpolated = false) {
        GeometryPart part = begin(true, role, colour);
        part.lineType = type;
        part.lineWidth = width;
        part.vertexColours = !colours.empty();
        const bool patterned = type != LineType::Solid;
        for (const auto& strip : strips) {
            const std::size_t n = strip.size();
            if (n < 2) continue;
            double distance = 0.0;
            const std::size_t segments = closed ? n : n - 1;
            for (std::size_t i = 0; i < segments; ++i) {
                const glm::dvec3 a = strip[i], b = strip[(i + 1) % n];
                double length = 0.0;
                if (patterned) {
                    const glm::dvec3 pa = projectPoint3(toPixels_, a), pb = projectPoint3(toPixels_, b);
                    length = glm::length(glm::dvec2(pb) - glm::dvec2(pa));
                }
                const glm::vec3 ca = i < colours.size() ? colours[i] : colour;
                const glm::vec3 cb = interpolated && (i + 1) % n < colours.size() ? colours[(i + 1) % n] : ca;
                push(a, {}, ca, {}, float(distance));
                push(b, {}, cb, {}, float(distance + length));
                distance += length;
            }
        }
        end(part);
    }

    void polyline(std::span<const glm::dvec3> points, const LineStyle& style,
                  std::span<const glm::vec3> colours = {}, bool interpolated = false) {
        std::vector<glm::dvec3> world;
        world.reserve(points.size());
        for (const auto& p : points) world.push_back(projectPoint3(model_, p));
        if (colours.size() != points.size()) colours = {};
        lineStrips({world}, false, PartRole::Line, style.colour, style.type, style.width, colours,
                   interpolated);
    }

    void polymarker(const DrawPolymarker& m) {
        const MarkerShape shape = markerShape(m.style->type, m.style->scale);
        const bool triangles = !shape.triangles.empty();
        GeometryPart part = begin(!triangles, PartRole::Marker, m.style->colour);
        const auto& offsets = triangles ? shape.triangles : shape.segments;
        for (const auto& p : m.points) {
            const glm::dvec3 w = projectPoint3(model_, p);
            for (const glm::vec2& o : offsets) push(w, {}, m.style->colour, o, 0.0f);
        }
        end(part);
    }

    void fillArea(const DrawFillArea& f) {
        std::vector<std::vector<glm::dvec3>> contours;
        for (const auto& c : f.contours) {
            contours.emplace_back();
            for (const auto& p : c) contours.back().push_back(projectPoint3(model_, p));
        }
        const InteriorStyleSet& in = f.interior;
        outlines(f, contours);
        // The triangles go when either side fills (a distinguished back may fill under a HOLLOW or
        // EMPTY front), each side culled by its own style.
        if (in.fillsFrontFaces() || in.fillsBackFaces()) interior(f, contours);
        if (f.edges->visible)
            lineStrips(contours, true, PartRole::Edge, f.edges->colour, f.edges->type, f.edges->width);
    }

    void text(const DrawText& t) {
        const StrokeFont& font = StrokeFont::forIndex(t.style->font);
        const auto strips = layoutText(font, t.text, t.style);
        const glm::vec3 colour = t.style->colour;
        if (t.annotation) {
            const glm::dvec3 reference = projectPoint3(model_, t.position);
            const glm::dvec2 offset(t.annotationOffset);
            if (t.leadLine) {
                // From the reference point (no offset) to the annotation point, in NPC on the screen,
                // in the polyline attributes in force: its pattern runs over its length on screen.
                GeometryPart lead = begin(true, PartRole::Line, t.leadLine->colour);
                lead.offsetInNpc = true;
                lead.lineType = t.leadLine->type;
                lead.lineWidth = t.leadLine->width;
                const double length =
                    lead.lineType == LineType::Solid ? 0.0 : glm::length(offset) * pixelsPerNpc_;
                push(reference, {}, t.leadLine->colour, glm::vec2(0.0f), 0.0f);
                push(reference, {}, t.leadLine->colour, glm::vec2(offset), float(length));
                end(lead);
            }
            GeometryPart part = begin(true, PartRole::Text, colour);
            part.offsetInNpc = true;
            for (const auto& strip : strips)
                for (std::size_t i = 0; i + 1 < strip.size(); ++i) {
                    push(reference, {}, colour, glm::vec2(offset + strip[i]), 0.0f);
                    push(reference, {}, colour, glm::vec2(offset + strip[i + 1]), 0.0f);
                }
            end(part);
            return;
        }
        // The text plane's axes: direction1, and direction2 made orthogonal to it within the plane.
        glm::dvec3 x = t.direction1, y = t.direction2;
        if (glm::length(x) == 0.0) x = {1, 0, 0};
        x = glm::normalize(x);
        y -= x * glm::dot(x, y);
        y = glm::length(y) > 0.0 ? glm::normalize(y) : glm::dvec3(0, 1, 0);
        std::vector<std::vector<glm::dvec3>> world;
        for (const auto& strip : strips) {
            world.emplace_back();
            for (const auto& q : strip)
                world.back().push_back(projectPoint3(model_, t.position + x * q.x + y * q.y));
        }
        lineStrips(world, false, PartRole::Text, colour, LineType::Solid, 1.0f);
    }

private:
    GeometryPart begin(bool lines, PartRole role, glm::vec3 colour) {
        GeometryPart part;
        part.lines = lines;
        part.role = role;
        part.colour = colour;
        part.first = static_cast<std::uint32_t>(geometry.vertices.size());
        return part;
    }
    void end(GeometryPart part) {
        part.count = static_cast<std::uint32_t>(geometry.vertices.size()) - part.first;
        if (part.count) geometry.parts.push_back(part);
    }
    void push(const glm::dvec3& p, glm::vec3 normal, glm::vec3 colour, glm::vec2 offset, float pattern) {
        geometry.vertices.push_back({glm::vec3(p), normal, colour, offset, pattern});
    }

    /// Each HOLLOW side draws the boundary in its own colour when it shows (a culled side never): one
    /// part for both sides when they draw alike, else a part per side for the renderer to choose.
    void outlines(const DrawFillArea& f, const std::vector<std::vector<glm::dvec3>>& contours) {
        const InteriorStyleSet& in = f.interior;
        glm::vec3 colour;
        if (hollowOutline(in, 0, colour)) {
            lineStrips(contours, true, PartRole::Edge, colour, LineType::Solid, 1.0f);
            return;
        }
        const glm::dvec4 plane = fillAreaPlane(f, model_);
        for (const int side : {1, -1}) {
            if (!hollowOutline(in, side, colour)) continue;
            lineStrips(contours, true, PartRole::Edge, colour, LineType::Solid, 1.0f);
            geometry.parts.back().side = side;
            geometry.parts.back().sidePlane = plane;
        }
    }

    void interior(const DrawFillArea& f, const std::vector<std::vector<glm::dvec3>>& contours) {
        const glm::dvec3 normal(fillAreaPlane(f, model_));
        if (glm::length(normal) == 0.0) return;
        glm::dvec3 centre(0.0);
        std::vector<glm::dvec3> flat;
        for (const auto& c : contours)
            for (const glm::dvec3& p : c) centre += p, flat.push_back(p);
        centre /= double(flat.size());
        const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 u = glm::normalize(glm::cross(helper, normal)), v = glm::cross(normal, u);
        std::vector<std::vector<glm::dvec2>> plane;
        for (const auto& c : contours) {
            plane.emplace_back();
            for (const auto& p : c)
                plane.back().push_back({glm::dot(p - centre, u), glm::dot(p - centre, v)});
        }
        const Triangulation tri = triangulateEvenOdd(plane);

        std::vector<glm::vec3> colours;
        std::vector<glm::dvec3> normals;
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(model_)));
        // A given facet normal lights the facet where no vertex normals do, and where both sides
        // are flat shaded (which lights a facet once, with its facet normal); it need not be the
        // plane's normal: the plane is only turned to agree with it.
        const InteriorStyleSet& style = f.interior;
        const bool flatShaded =
            style.shadingOf(false) == ShadingMethod::None && style.shadingOf(true) == ShadingMethod::None;
        const bool given = (f.vertexNormals.empty() || flatShaded) && glm::length(f.facetNormal) > 0.0 &&
                           glm::length(normalMatrix * f.facetNormal) > 0.0;
        const bool haveColours = !f.vertexColours.empty();
        const bool haveNormals = !f.vertexNormals.empty() && !given;
        const glm::dvec3 lighting = given ? glm::normalize(normalMatrix * f.facetNormal) : normal;
        for (std::size_t c = 0; c < contours.size(); ++c)
            for (std::size_t i = 0; i < contours[c].size(); ++i) {
                if (haveColours)
                    colours.push_back(c < f.vertexColours.size() && i < f.vertexColours[c].size()
                                          ? f.vertexColours[c][i]
                                          : f.interior->colour);
                if (haveNormals)
                    normals.push_back(c < f.vertexNormals.size() && i < f.vertexNormals[c].size()
                                          ? glm::normalize(normalMatrix * f.vertexNormals[c][i])
                                          : normal);
            }
        GeometryPart part = begin(false, PartRole::Interior, f.interior->colour);
        part.vertexColours = haveColours;
        part.vertexNormals = true;
        part.facetNormals = given;
        for (std::uint32_t index : tri.triangles) {
            const TriangulationVertex& tv = tri.vertices[index];
            const double t = tv.t;
            const glm::dvec3 p = flat[tv.from] * (1.0 - t) + flat[tv.to] * t;
            const glm::vec3 colour =
                haveColours ? mixIn(f.interior->renderingModel, colours[tv.from], colours[tv.to], t)
                            : f.interior->colour;
            glm::dvec3 n = haveNormals ? normals[tv.from] * (1.0 - t) + normals[tv.to] * t : lighting;
            if (glm::length(n) > 0.0) n = glm::normalize(n);
            push(p, glm::vec3(n), colour, {}, 0.0f);
        }
        // The slab triangulation is counter-clockwise in the (u, v) plane, i.e. front facing along `normal`.
        end(part);
    }

    glm::dmat4 model_;
    glm::dmat4 toPixels_;
    double pixelsPerNpc_;
};

struct Hasher {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
    }
    template <class T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof v);
    }
    template <class T>
    void value(const ItemRef<T>& r) {
        value(r.get());
    }
    void value(const Reflectance& r) {
        value(r.ambient), value(r.diffuse), value(r.specular), value(r.specularColour);
        value(r.specularExponent), value(r.transparency);
    }
    void value(const InteriorStyleSet& s) {
        value(s.style), value(s.styleIndex), value(s.colour), value(s.backColour), value(s.shading);
        value(s.reflectance), value(s.properties), value(s.backProperties), value(s.cull);
        value(s.distinguishBackFaces), value(s.back.style), value(s.back.styleIndex);
        value(s.back.shading), value(s.back.reflectance);
    }
    void value(const EdgeStyle& e) { value(e.visible), value(e.colour), value(e.type), value(e.width); }
    void value(const TextStyle& t) {
        value(t.colour), value(t.font), value(t.expansion), value(t.spacing), value(t.height);
        value(t.upVector), value(t.path), value(t.horizontal), value(t.vertical);
    }
    template <class Values>
    void values(const Values& v) {
        using T = typename Values::value_type;
        value(v.size());
        if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
    }
};

}  // namespace

ItemGeometry describeItem(const DrawItem& item, const glm::dmat4& worldToPixels, double pixelsPerNpc) {
    Builder b(item, worldToPixels, pixelsPerNpc);
    visitPrimitive(
        [&](const auto& p) {
            using T = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<T, DrawColouredPolyline>)
                b.polyline(stripPoints(p), stripStyle(p), p.colours.values, p.colours.interpolated);
            else if constexpr (kDrawsStrip<T>)
                b.polyline(stripPoints(p), stripStyle(p));
            else if constexpr (std::is_same_v<T, DrawPolymarker>)
                b.polymarker(p);
            else if constexpr (std::is_same_v<T, DrawFillArea>)
                b.fillArea(p);
            else if constexpr (std::is_same_v<T, DrawText>)
                b.text(p);
            else if constexpr (!std::is_same_v<T, DrawMesh>)  // meshes are drawn from their own buffers
                static_assert(kUnhandledPrimitive<T>);
        },
        item.primitive);
    return std::move(b.geometry);
}

namespace {

/// Newell's normal of a closed contour: twice its area, projected, along its plane's normal.
glm::dvec3 newellNormal(const std::vector<glm::dvec3>& points) {
    glm::dvec3 normal(0.0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3& a = points[i];
        const glm::dvec3& b = points[(i + 1) % points.size()];
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return normal;
}

/// The normal of the plane through three of the points spread farthest apart (a, the point
/// farthest from a, the point farthest from the line through both); zero for collinear points.
glm::dvec3 spreadNormal(const std::vector<glm::dvec3>& points) {
    const glm::dvec3 a = points.front();
    glm::dvec3 b = a;
    for (const glm::dvec3& q : points)
        if (glm::distance(q, a) > glm::distance(b, a)) b = q;
    glm::dvec3 normal(0.0);
    for (const glm::dvec3& q : points) {
        const glm::dvec3 n = glm::cross(b - a, q - a);
        if (glm::length(n) > glm::length(normal)) normal = n;
    }
    return normal;
}

}  // namespace

glm::dvec3 contoursNormal(const std::vector<std::vector<glm::dvec3>>& contours) {
    glm::dvec3 normal(0.0), largest(0.0), lo(std::numeric_limits<double>::infinity()), hi(-lo);
    std::size_t count = 0;
    for (const auto& contour : contours) {
        const glm::dvec3 n = newellNormal(contour);
        normal += n;
        if (glm::length(n) > glm::length(largest)) largest = n;
        for (const glm::dvec3& q : contour) lo = glm::min(lo, q), hi = glm::max(hi, q);
        count += contour.size();
    }
    if (count < 3) return glm::dvec3(0.0);
    // Newell's normal is a sum of signed areas: contours wound against each other, or the lobes
    // of a bow-tie, cancel in it (to nothing, or to rounding noise pointing anywhere), though the
    // even-odd rule fills them. There the largest contour's normal, else the plane through the
    // points spread farthest apart, takes its place (turned the way what is left of Newell's
    // points, which for a thin sliver is the true winding).
    const double size = glm::dot(hi - lo, hi - lo), enough = 1e-6 * size;
    if (!(glm::length(normal) > enough)) {
        const glm::dvec3 noise = normal;
        if (glm::length(largest) > enough) {
            normal = largest;
        } else {
            std::vector<glm::dvec3> all;
            all.reserve(count);
            for (const auto& contour : contours) all.insert(all.end(), contour.begin(), contour.end());
            normal = spreadNormal(all);
        }
        if (glm::dot(normal, noise) < 0.0) normal = -normal;
    }
    return glm::length(normal) > 1e-12 * size ? normal : glm::dvec3(0.0);
}

glm::dvec4 fillAreaPlane(const DrawFillArea& fill, const glm::dmat4& model) {
    std::vector<std::vector<glm::dvec3>> world;
    glm::dvec3 centre(0.0);
    std::size_t count = 0;
    for (const auto& contour : fill.contours) {
        world.emplace_back();
        for (const glm::dvec3& q : contour) world.back().push_back(projectPoint3(model, q));
        for (const glm::dvec3& q : world.back()) centre += q, ++count;
    }
    glm::dvec3 normal = contoursNormal(world);
    if (!(glm::length(normal) > 0.0)) return glm::dvec4(0.0);
    normal = glm::normalize(normal);
    if (glm::length(fill.facetNormal) > 0.0) {
        const glm::dvec3 given =
            glm::dvec3(glm::transpose(glm::inverse(model)) * glm::dvec4(fill.facetNormal, 0.0));
        if (glm::dot(given, normal) < 0.0) normal = -normal;
    }
    return glm::dvec4(normal, -glm::dot(normal, centre / double(count)));
}

bool hollowOutline(const InteriorStyleSet& in, int side, glm::vec3& colour) {
    const bool front = in.style == InteriorStyle::Hollow && in.cull != CullMode::FrontFaces;
    const bool back = in.styleOf(true) == InteriorStyle::Hollow && in.cull != CullMode::BackFaces;
    const bool alike = front && back && (!in.distinguishBackFaces || in.backColour == in.colour);
    if (!(side > 0 ? front : side < 0 ? back : alike)) return false;
    colour = side < 0 && in.distinguishBackFaces ? in.backColour : in.colour;
    return true;
}

int sideShown(const glm::dvec4& plane, const glm::dmat4& worldToNpc) {
    // The viewer in world coordinates: NPC's point at infinity toward +z brought back (a direction
    // for a parallel view, the eye point with w > 0 for a perspective one).
    const glm::dvec4 viewer = glm::inverse(worldToNpc) * glm::dvec4(0, 0, 1, 0);
    // A point with w < 0 is the same point with every coordinate negated.
    const double s = glm::dot(plane, viewer) * (viewer.w < 0.0 ? -1.0 : 1.0);
    return s > 0.0 ? 1 : s < 0.0 ? -1 : 0;
}

std::uint64_t geometryKey(const DrawItem& item, const glm::dmat4& worldToPixels, double pixelsPerNpc) {
    Hasher h;
    h.value(item.primitive.index());
    h.value(item.modelTransform().get());
    visitPrimitive(
        [&](const auto& p) {
            using T = std::decay_t<decltype(p)>;
            if constexpr (kDrawsStrip<T>) {
                h.values(stripPoints(p));
                h.value(stripStyle(p));
                if constexpr (std::is_same_v<T, DrawColouredPolyline>)
                    h.values(p.colours.values), h.value(p.colours.interpolated);
                if (stripStyle(p)->type != LineType::Solid) h.value(worldToPixels);
            } else if constexpr (std::is_same_v<T, DrawPolymarker>) {
                h.values(p.points);
                h.value(p.style);
            } else if constexpr (std::is_same_v<T, DrawFillArea>) {
                for (const auto& c : p.contours) h.values(c);
                for (const auto& c : p.vertexColours) h.values(c);
                for (const auto& c : p.vertexNormals) h.values(c);
                h.value(p.facetNormal);
                h.value(p.interior);
                h.value(p.edges);
                if (p.edges->visible && p.edges->type != LineType::Solid) h.value(worldToPixels);
            } else if constexpr (std::is_same_v<T, DrawText>) {
                h.bytes(p.text.data(), p.text.size());
                h.value(p.position);
                h.value(p.direction1);
                h.value(p.direction2);
                h.value(p.annotation);
                h.value(p.annotationOffset);
                h.value(p.style);
                h.value(p.leadLine.has_value());
                if (p.leadLine)
                    h.value(p.leadLine->colour), h.value(p.leadLine->type), h.value(p.leadLine->width);
                if (p.leadLine && p.leadLine->type != LineType::Solid) h.value(pixelsPerNpc);
            } else if constexpr (!std::is_same_v<T, DrawMesh>) {  // meshes: keyed by their own buffers
                static_assert(kUnhandledPrimitive<T>);
            }
        },
        item.primitive);
    return h.h;
}

MeshIndices meshIndices(const MeshData& mesh) {
    MeshIndices out;
    out.indices = mesh.triangles;
    out.triangleCount = static_cast<std::uint32_t>(mesh.triangles.size() / 3 * 3);
    out.indices.resize(out.triangleCount);
    // Iso-lines run through their own copies of the vertices (see meshVertices), which carry the
    // distance along the line for line types.
    auto copy = static_cast<std::uint32_t>(mesh.positions.size());
    for (const auto& line : mesh.isoLines) {
        for (std::size_t i = 0; i + 1 < line.size(); ++i)
            out.indices.insert(out.indices.end(), {copy + std::uint32_t(i), copy + std::uint32_t(i + 1)});
        copy += static_cast<std::uint32_t>(line.size());
    }
    out.isoLineCount = static_cast<std::uint32_t>(out.indices.size()) - out.triangleCount;
    const std::vector<std::uint8_t> masks = meshFacetEdges(mesh);
    std::unordered_set<std::uint64_t> seen;
    for (std::size_t t = 0; t < masks.size(); ++t)
        for (int e = 0; e < 3; ++e) {
            std::uint32_t a = mesh.triangles[3 * t + e], b = mesh.triangles[3 * t + (e + 1) % 3];
            if (a > b) std::swap(a, b);
            if ((masks[t] >> e & 1) && seen.insert((std::uint64_t(a) << 32) | b).second)
                out.indices.insert(out.indices.end(), {a, b});
        }
    out.edgeCount = static_cast<std::uint32_t>(out.indices.size()) - out.triangleCount - out.isoLineCount;
    for (const auto& line : mesh.trimEdges)
        for (std::size_t i = 0; i + 1 < line.size(); ++i)
            out.indices.insert(out.indices.end(), {line[i], line[i + 1]});
    out.trimEdgeCount =
        static_cast<std::uint32_t>(out.indices.size()) - out.triangleCount - out.isoLineCount - out.edgeCount;
    const auto limit = copy;
    for (std::uint32_t& i : out.indices)
        if (i >= limit) i = 0;  // a bad index must not read past the vertex buffer
    return out;
}

std::vector<RenderVertex> meshVertices(const MeshData& mesh) {
    std::vector<RenderVertex> v(mesh.positions.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        v[i].position = mesh.positions[i];
        if (i < mesh.normals.size()) v[i].normal = mesh.normals[i].unpacked();
        if (i < mesh.colours.size()) v[i].colour = mesh.colours[i];
    }
    const std::size_t count = v.size();
    // The iso-lines' own vertices, in meshIndices' order: `pattern` is the length along the line in
    // modelling coordinates; the fragment shader turns it into pixels by its screen derivative, so
    // the mesh buffer need not change with the view.
    for (const auto& line : mesh.isoLines) {
        float length = 0.0f;
        for (std::size_t i = 0; i < line.size(); ++i) {
            RenderVertex r = line[i] < count ? v[line[i]] : RenderVertex{};
            if (i > 0 && line[i] < count && line[i - 1] < count)
                length += glm::distance(v[line[i]].position, v[line[i - 1]].position);
            r.pattern = length;
            v.push_back(r);
        }
    }
    return v;
}

}  // namespace phigs::render
