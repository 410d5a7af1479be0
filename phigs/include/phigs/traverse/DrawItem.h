#pragma once

// One primitive of a draw list with every attribute resolved (see DrawList.h).

#include "phigs/core/Attributes.h"
#include "phigs/traverse/DrawContext.h"
#include "phigs/traverse/DrawPath.h"
#include "phigs/traverse/DrawSource.h"
#include "phigs/traverse/ItemArray.h"
#include "phigs/traverse/ItemRef.h"
#include "phigs/traverse/PackedNormal.h"
#include "phigs/traverse/SharedIndexList.h"

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace phigs {

/// A polyline's vertex colours (one per point): segment i takes values[i], or with `interpolated`
/// goes linearly from values[i] to values[i + 1].
struct VertexColours {
    ItemArray<glm::vec3> values;
    bool interpolated = false;
};

/// A polyline: one connected strip of points in modelling coordinates in `style->colour`; its
/// line type runs on along the whole strip.
struct DrawPolyline {
    ItemArray<glm::dvec3> points;
    ItemRef<LineStyle> style;
};

/// A polyline coloured by its vertices (POLYLINE SET 3 WITH DATA with colours): `line` as
/// above, its colour taken from `colours` instead of the style.
struct DrawColouredPolyline {
    DrawPolyline line;
    VertexColours colours;
};

/// A set of markers at points in modelling coordinates.
struct DrawPolymarker {
    ItemArray<glm::dvec3> points;
    ItemRef<MarkerStyle> style;
};

/// A planar fill area set: one or more closed contours (the first is the outer boundary, the
/// others may be holes; the even-odd rule decides inside), optional per-vertex data.
struct DrawFillArea {
    std::vector<std::vector<glm::dvec3>> contours;
    std::vector<std::vector<glm::vec3>> vertexColours;   ///< empty, or one per vertex of each contour
    std::vector<std::vector<glm::dvec3>> vertexNormals;  ///< empty, or one per vertex of each contour
    glm::dvec3 facetNormal{0.0};                         ///< (0,0,0): derive from the contour
    ItemRef<InteriorStyleSet> interior;
    ItemRef<EdgeStyle> edges;
};

/// Text at a point on a plane given by two direction vectors (PHIGS TEXT 3), or annotation
/// text whose geometry lives in NPC at an offset from a reference point (ANNOTATION TEXT RELATIVE).
struct DrawText {
    std::string text;
    glm::dvec3 position{0.0};        ///< text point (annotation: the reference point, modelling coords)
    glm::dvec3 direction1{1, 0, 0};  ///< text plane x axis
    glm::dvec3 direction2{0, 1, 0};  ///< text plane y axis
    bool annotation = false;
    glm::dvec3 annotationOffset{0.0};  ///< NPC offset of the text from the reference point
    ItemRef<TextStyle> style;
    /// Annotation style LEAD LINE: the line from the reference point to the annotation point, in
    /// the polyline colour and width in force (drawn solid); absent for UNCONNECTED (and any
    /// other style).
    std::optional<LineStyle> leadLine;
};

/// A triangle mesh: what NURBS surfaces, triangle strips, quadrilateral meshes and fill area sets
/// with data become. Shared and immutable: the same pointer comes back while its element and
/// structure are unchanged, so a renderer may key its GPU buffers on it.
struct MeshData {
    std::vector<glm::vec3> positions;   ///< modelling coordinates
    std::vector<PackedNormal> normals;  ///< one per position (unit), or empty (facet normals)
    /// The normals are each facet's given normal, alike at its vertices: flat shading lights the
    /// facet with it rather than with the plane of its triangles.
    bool normalsPerFacet = false;
    std::vector<glm::vec3> colours;  ///< one per position, or empty (interior colour)
    std::vector<glm::vec2> uv;       ///< surface parameters per position, or empty
    SharedIndexList triangles;       ///< three indices per triangle, counter-clockwise = front
    std::vector<std::vector<std::uint32_t>>
        isoLines;  ///< polylines through positions (iso-parametric curves)
    /// Polylines through positions drawn as edges while the edge flag is on (a NURBS surface's
    /// visible trimming curves); their positions belong to no triangle.
    std::vector<std::vector<std::uint32_t>> trimEdges;
    /// The primitive's facets (a strip's triangle, a quadrilateral, a surface's grid cell) as runs
    /// of consecutive triangles: an edge two triangles of one facet share (a diagonal) is no edge
    /// of the primitive. facetEnds: each facet's end (one past its last triangle), ascending;
    /// empty: facets of trianglesPerFacet triangles each.
    std::uint32_t trianglesPerFacet = 1;
    std::vector<std::uint32_t> facetEnds;
    /// A NURBS surface's trimming loops as polygons in (u, v), or empty (untrimmed): what the
    /// even-odd rule puts inside them is kept.
    std::vector<std::vector<glm::dvec2>> trimLoops;

    /// Whether trimming keeps the surface at (u, v): inside its loops, or untrimmed.
    bool keeps(glm::dvec2 uv) const;
};

/// A mesh with its attributes; `surface` is set for NURBS surfaces so picking can intersect the
/// exact surface instead of the triangles.
struct DrawMesh {
    std::shared_ptr<const MeshData> mesh;
    std::shared_ptr<const geom::Surface> surface;  ///< the exact surface, or null
    ItemRef<InteriorStyleSet> interior;
    ItemRef<EdgeStyle> edges;
    ItemRef<LineStyle> isoLineStyle;
};

/// A B-spline curve already tessellated into a polyline; `curve` keeps the exact form and the
/// range the part drawn (a vector target tessellates it again to its own tolerance).
struct DrawCurve {
    ItemArray<glm::dvec3> points;
    std::shared_ptr<const geom::Curve> curve;
    ItemRef<LineStyle> style;
    double rangeStart = 0.0, rangeEnd = 0.0;  ///< equal: the whole domain
};

/// The closed family of primitives a draw list holds. Fill areas, text, meshes, curves and coloured
/// polylines, larger and fewer than polylines, are held out of line (a view of their draw segment's
/// record, or a copy of their own) so that every item stays 56 bytes; read through visitPrimitive and
/// primitiveIf, which hand them out as themselves.
using DrawPrimitive = std::variant<DrawPolyline, DrawPolymarker, ItemRef<DrawFillArea>, ItemRef<DrawText>,
                                   ItemRef<DrawMesh>, ItemRef<DrawCurve>, ItemRef<DrawColouredPolyline>>;

namespace detail {
/// A primitive as the variant holds it: T itself, or ItemRef<T> for the out-of-line ones.
template <class T>
struct HeldPrimitive {
    using type = T;
    static const T& read(const T& held) { return held; }
    static T& edit(T& held) { return held; }
};
template <class T>
struct HeldPrimitive<ItemRef<T>> {
    using type = T;
    static const T& read(const ItemRef<T>& held) { return held.get(); }
    static T& edit(ItemRef<T>& held) { return held.edit(); }
};
template <class T>
inline constexpr bool kHeldOutOfLine =
    std::is_same_v<T, DrawFillArea> || std::is_same_v<T, DrawText> || std::is_same_v<T, DrawMesh> ||
    std::is_same_v<T, DrawCurve> || std::is_same_v<T, DrawColouredPolyline>;
template <class T>
using HeldAs = std::conditional_t<kHeldOutOfLine<T>, ItemRef<T>, T>;
}  // namespace detail

/// Whether a T draws as one strip of points: a polyline, coloured or not, or a curve's polyline.
template <class T>
inline constexpr bool kDrawsStrip = std::is_same_v<T, DrawPolyline> ||
                                    std::is_same_v<T, DrawColouredPolyline> || std::is_same_v<T, DrawCurve>;
/// The points of a strip (see kDrawsStrip).
inline const ItemArray<glm::dvec3>& stripPoints(const DrawPolyline& p) {
    return p.points;
}
inline const ItemArray<glm::dvec3>& stripPoints(const DrawColouredPolyline& p) {
    return p.line.points;
}
inline const ItemArray<glm::dvec3>& stripPoints(const DrawCurve& p) {
    return p.points;
}
/// The line style of a strip (see kDrawsStrip).
inline const ItemRef<LineStyle>& stripStyle(const DrawPolyline& p) {
    return p.style;
}
inline const ItemRef<LineStyle>& stripStyle(const DrawColouredPolyline& p) {
    return p.line.style;
}
inline const ItemRef<LineStyle>& stripStyle(const DrawCurve& p) {
    return p.style;
}

/// False for every T: a visitor's last `else static_assert(kUnhandledPrimitive<T>)` fails to
/// compile when a new kind of primitive is not answered.
template <class T>
inline constexpr bool kUnhandledPrimitive = false;

/// Calls f with the primitive as its own type (DrawPolyline, ..., DrawFillArea, DrawText, ...).
template <class F>
decltype(auto) visitPrimitive(F&& f, const DrawPrimitive& primitive) {
    return std::visit(
        [&](const auto& held) -> decltype(auto) {
            return f(detail::HeldPrimitive<std::decay_t<decltype(held)>>::read(held));
        },
        primitive);
}
/// The primitive as a T, or null when it is another kind.
template <class T>
const T* primitiveIf(const DrawPrimitive& primitive) {
    const auto* held = std::get_if<detail::HeldAs<T>>(&primitive);
    return held ? &detail::HeldPrimitive<detail::HeldAs<T>>::read(*held) : nullptr;
}
/// The primitive as a T; std::bad_variant_access when it is another kind.
template <class T>
const T& primitiveAs(const DrawPrimitive& primitive) {
    return detail::HeldPrimitive<detail::HeldAs<T>>::read(std::get<detail::HeldAs<T>>(primitive));
}
/// The primitive as a T to change in place (an out-of-line one viewed becomes a copy of its own).
template <class T>
T& editPrimitive(DrawPrimitive& primitive) {
    return detail::HeldPrimitive<detail::HeldAs<T>>::edit(std::get<detail::HeldAs<T>>(primitive));
}
template <class T>
bool holdsPrimitive(const DrawPrimitive& primitive) {
    return std::holds_alternative<detail::HeldAs<T>>(primitive);
}

/// One primitive with everything a consumer needs to draw or pick it. The context (placement,
/// view, lights, depth cue, highlighting, pickability, clipping) and the styles are views of
/// records shared by many items (one context per run of items of a segment in one state, one
/// interned record per distinct style); `context.edit()` gives an item a context of its own.
struct DrawItem {
    DrawPrimitive primitive;
    ItemRef<DrawContext> context;
    DrawSource source;

    /// Composite modelling transform (global * local), to world.
    const ItemRef<glm::dmat4>& modelTransform() const { return context->modelTransform; }
    std::int32_t viewIndex() const { return context->viewIndex; }  ///< index into DrawList::views
    /// Index into DrawList::lightSets, -1: no lights.
    std::int32_t lightSet() const { return context->lightSet; }
    std::int32_t depthCue() const { return context->depthCue; }  ///< into DrawList::depthCues, -1: none
    bool highlighted() const { return context->highlighted; }
    /// False when the pick filter or detectability excludes it.
    bool pickable() const { return context->pickable; }
    /// Model clipping volume in world coordinates (see DrawContext); empty when off.
    const ItemArray<glm::dvec4>& modelClipPlanes() const { return context->modelClipPlanes; }
};

}  // namespace phigs
