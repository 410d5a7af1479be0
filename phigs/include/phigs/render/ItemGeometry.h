#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace phigs::render {

/// The vertex every pipeline reads: world (or, for meshes, modelling) position, normal, colour, a
/// screen offset (markers in pixels, annotation text in NPC) and the distance along a patterned
/// line in pixels.
struct RenderVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec3 colour{0.0f};
    glm::vec2 offset{0.0f};
    float pattern = 0.0f;
};

/// What a run of vertices is for; it decides which attributes colour and style it.
enum class PartRole : int { Interior = 0, Edge = 1, Line = 2, Marker = 3, Text = 4, IsoLine = 5 };

/// A run of vertices drawn with one topology and one set of attributes.
struct GeometryPart {
    bool lines = false;  ///< line list, else triangle list
    std::uint32_t first = 0, count = 0;
    PartRole role = PartRole::Line;
    glm::vec3 colour{1.0f};
    LineType lineType = LineType::Solid;
    float lineWidth = 1.0f;
    bool vertexColours = false;  ///< the vertices carry colours (else `colour`)
    bool vertexNormals = false;  ///< the vertices carry normals (else facet normals)
    /// The vertices' normals are their facet's given normal: flat shading lights with it.
    bool facetNormals = false;
    bool offsetInNpc = false;  ///< offsets are NPC units (annotation text), else pixels
    /// `pattern` is a length in modelling units (mesh iso-lines), else pixels on screen.
    bool patternInModelUnits = false;
    /// The outline of a HOLLOW side of a fill area: +1 of its front, -1 of its back (drawn only
    /// when sideShown(sidePlane, view) says that side shows), 0 of whichever side shows. Of a mesh:
    /// its triangles' facet edges, each drawn while its triangle shows that side (meshSidedEdges).
    int side = 0;
    glm::dvec4 sidePlane{0.0};  ///< the fill area's world plane, positive on its front side
};

/// The CPU-side geometry of one non-mesh draw item (the "describe" step): world coordinates, the
/// modelling transform already applied in double precision.
struct ItemGeometry {
    std::vector<RenderVertex> vertices;
    std::vector<GeometryPart> parts;
};

/// Builds the geometry of a polyline, polymarker, fill area (set), text or curve item.
/// worldToPixels (the view and workstation transforms) measures patterned lines on screen, and
/// pixelsPerNpc (the workstation transform's scale) an annotation's patterned lead line, whose far
/// end is an offset in NPC. A DrawMesh item gives empty geometry (meshes are uploaded as they are,
/// see MeshGeometry).
ItemGeometry describeItem(const DrawItem& item, const glm::dmat4& worldToPixels, double pixelsPerNpc = 1.0);

/// Index lists of a mesh: triangles, then iso-lines and the facets' edges (render/MeshEdges.h: no
/// diagonals) as line-list pairs.
struct MeshIndices {
    std::vector<std::uint32_t> indices;
    std::uint32_t triangleCount = 0;  ///< index count of the triangles (first)
    std::uint32_t isoLineCount = 0;   ///< index count of the iso-line pairs (next)
    std::uint32_t edgeCount = 0;      ///< index count of the facets' edges, each once (next)
    std::uint32_t trimEdgeCount = 0;  ///< index count of the trim edges' pairs (last)
};
MeshIndices meshIndices(const MeshData& mesh);
/// The vertices of a mesh in modelling coordinates (missing normals or colours stay zero), then a
/// copy of each iso-line's vertices whose `pattern` is the length along that line.
std::vector<RenderVertex> meshVertices(const MeshData& mesh);

/// A fill area's world plane (unit normal, -normal . point), positive on its front: the side
/// Newell's normal of the world contours points to (even for concave outlines; where their signed
/// areas cancel, as in a bow-tie or contours wound against each other, the largest contour's or
/// the plane of the points spread farthest apart), turned to the given facet normal; zero when
/// the contours span no plane. The renderers wind its triangles counter-clockwise about it.
glm::dvec4 fillAreaPlane(const DrawFillArea& fill, const glm::dmat4& model);
/// The normal (not unit) of the plane closed contours lie on, as fillAreaPlane finds it (Newell's,
/// or where signed areas cancel the largest contour's or the points' spread); zero for none.
glm::dvec3 contoursNormal(const std::vector<std::vector<glm::dvec3>>& contours);
/// The side of a world plane (positive on its front) a view shows: +1 the front, -1 the back, 0
/// edge on. worldToNpc: the view's mapping times its orientation (the viewer is at NPC z = +inf).
int sideShown(const glm::dvec4& plane, const glm::dmat4& worldToNpc);

/// Whether a fill area's side draws its boundary (a HOLLOW style, not culled), and in which colour:
/// side +1 the front, -1 the back (its own colour with face distinguishing on), 0 seen edge on
/// (drawn only when both sides draw it alike). False leaves `colour` alone.
bool hollowOutline(const InteriorStyleSet& in, int side, glm::vec3& colour);

/// A content hash of a non-mesh item and the transforms its geometry depends on, to key caches.
std::uint64_t geometryKey(const DrawItem& item, const glm::dmat4& worldToPixels, double pixelsPerNpc = 1.0);

}  // namespace phigs::render
