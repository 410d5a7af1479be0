#include "phigs/hardcopy/ItemProjector.h"

#include "phigs/core/TransformUtilities.h"
#include "phigs/hardcopy/CurveRefinement.h"
#include "phigs/hardcopy/MeshProjector.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/render/StrokeFont.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace phigs::hardcopy {
namespace {

/// The raster's opacity of a facet: 1 - transparency of the side's reflectance.
float opacityOf(const InteriorStyleSet& interior, bool back) {
    const Reflectance& r =
        back && interior.distinguishBackFaces ? interior.backProperties : interior.properties;
    return 1.0f - std::clamp(r.transparency, 0.0f, 1.0f);
}

}  // namespace

std::vector<glm::dvec3> ItemProjector::toWorld(std::span<const glm::dvec3> points) const {
    std::vector<glm::dvec3> world;
    world.reserve(points.size());
    for (const glm::dvec3& p : points)
        world.push_back(projectPoint3(pipeline_.item().modelTransform().get(), p));
    return world;
}

void ItemProjector::operator()(const DrawPolyline& polyline) {
    pipeline_.line(toWorld(polyline.points), false, polyline.style->colour, polyline.style->type,
                   polyline.style->width);
}

void ItemProjector::operator()(const DrawColouredPolyline& polyline) {
    const DrawPolyline& line = polyline.line;
    pipeline_.line(toWorld(line.points), false, line.style->colour, line.style->type, line.style->width,
                   polyline.colours.values, polyline.colours.interpolated);
}

void ItemProjector::operator()(const DrawCurve& curve) {
    // Vector-fine: the exact curve again, to the page tolerance, rather than traversal's polyline.
    std::vector<glm::dvec3> points = curve.points;
    if (curve.curve)
        points = refineCurve(*curve.curve, curve.rangeStart, curve.rangeEnd,
                             pipeline_.worldToPage() * pipeline_.item().modelTransform().get(),
                             pipeline_.options().curveTolerance);
    pipeline_.line(toWorld(points), false, curve.style->colour, curve.style->type, curve.style->width);
}

void ItemProjector::operator()(const DrawPolymarker& markers) {
    for (const glm::dvec3& p : markers.points)
        pipeline_.marker(projectPoint3(pipeline_.item().modelTransform().get(), p), markers.style);
}

void ItemProjector::operator()(const DrawFillArea& fill) {
    std::vector<std::vector<glm::dvec3>> world;
    for (const auto& contour : fill.contours) world.push_back(toWorld(contour));
    const InteriorStyleSet& in = fill.interior;
    // Each HOLLOW side draws the boundary in its colour when it shows; each side fills by its own
    // style (ItemGeometry and the renderer do so).
    glm::vec3 outline;
    if (render::hollowOutline(in, 0, outline) ||
        render::hollowOutline(
            in, pipeline_.sideShown(render::fillAreaPlane(fill, pipeline_.item().modelTransform().get())),
            outline))
        for (const auto& contour : world) pipeline_.line(contour, true, outline, LineType::Solid, 1.0f);
    if (in.fillsFrontFaces() || in.fillsBackFaces()) {
        if (fill.vertexColours.empty() && fill.vertexNormals.empty())
            fillInterior(fill, world);
        else
            fillTriangles(fill);
    }
    if (fill.edges->visible)
        for (const auto& contour : world)
            pipeline_.line(contour, true, fill.edges->colour, fill.edges->type, fill.edges->width);
}

void ItemProjector::fillInterior(const DrawFillArea& fill,
                                 const std::vector<std::vector<glm::dvec3>>& world) {
    // One colour for the whole plane: the contours' normal as ItemGeometry finds it (where their
    // signed areas cancel too), turned as ItemGeometry turns it.
    glm::dvec3 normal = render::contoursNormal(world), centre(0.0), low(1e300), high(-1e300);
    std::vector<FacetVertex> vertices;
    for (const auto& c : world)
        for (const glm::dvec3& a : c) {
            centre += a, low = glm::min(low, a), high = glm::max(high, a);
            vertices.push_back({a, {}, fill.interior->colour});
        }
    if (vertices.size() < 3 || glm::length(normal) == 0.0) return;
    normal = glm::normalize(normal);
    // A given facet normal turns the plane and lights the facet (ItemGeometry does the same).
    glm::dvec3 lighting = normal;
    bool given = false;
    if (glm::length(fill.facetNormal) > 0.0) {
        const glm::dvec3 facet =
            glm::dvec3(glm::transpose(glm::inverse(pipeline_.item().modelTransform().get())) *
                       glm::dvec4(fill.facetNormal, 0.0));
        if (glm::dot(facet, normal) < 0.0) normal = -normal;
        given = glm::length(facet) > 0.0;
        lighting = given ? glm::normalize(facet) : normal;
    }
    centre /= double(vertices.size());
    for (FacetVertex& v : vertices) v.normal = lighting;
    // The side shown: the winding on screen of a triangle counter-clockwise about the normal.
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const double size = std::max(glm::length(high - low), 1e-300);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, normal)) * size, v = glm::cross(normal, u);
    const int facing = pipeline_.facing(centre, centre + u, centre + v);
    const InteriorStyleSet& in = fill.interior;
    if (FacetPaint::unfilled(in, facing)) return;
    FacetPaint paint;
    paint.paintFor(pipeline_.colouring(), in, vertices, true, facing, given);
    paint.opacity = opacityOf(in, facing < 0);
    pipeline_.facet(world, paint);
}

void ItemProjector::fillTriangles(const DrawFillArea& fill) {
    // Vertex colours or normals: the raster's own triangles, each coloured at its vertices' mean.
    const render::ItemGeometry geometry = render::describeItem(pipeline_.item(), pipeline_.worldToPage());
    const InteriorStyleSet& in = fill.interior;
    for (const render::GeometryPart& part : geometry.parts) {
        if (part.lines || part.role != render::PartRole::Interior) continue;
        for (std::uint32_t t = part.first; t + 2 < part.first + part.count; t += 3) {
            std::vector<FacetVertex> vertices;
            std::vector<glm::dvec3> triangle;
            for (std::uint32_t k = t; k < t + 3; ++k) {
                const render::RenderVertex& r = geometry.vertices[k];
                triangle.push_back(glm::dvec3(r.position));
                vertices.push_back({glm::dvec3(r.position), glm::dvec3(r.normal),
                                    part.vertexColours ? r.colour : in.colour});
            }
            const int facing = pipeline_.facing(triangle[0], triangle[1], triangle[2]);
            if (FacetPaint::unfilled(in, facing)) continue;
            FacetPaint paint;
            paint.paintFor(pipeline_.colouring(), in, vertices, true, facing, part.facetNormals);
            paint.opacity = opacityOf(in, facing < 0);
            paint.seam = true;
            pipeline_.facet({triangle}, paint);
        }
    }
}

void ItemProjector::operator()(const DrawText& text) {
    const auto strips =
        render::layoutText(render::StrokeFont::forIndex(text.style->font), text.text, text.style);
    const glm::vec3 colour = text.style->colour;
    const glm::dmat4& model = pipeline_.item().modelTransform().get();
    if (text.annotation) {
        // Laid out in NPC at the projected reference point plus the offset, at its depth; a
        // clipped reference point draws nothing (ISO 9592).
        const glm::dvec3 reference = projectPoint3(model, text.position);
        const std::optional<glm::dvec4> h = pipeline_.keptPoint(reference);
        if (!h) return;
        const glm::dvec3 from = glm::dvec3(*h) / h->w;
        const glm::dvec3 at = from + glm::dvec3(glm::dvec2(text.annotationOffset), 0.0);
        if (text.leadLine)  // in the polyline attributes in force, its pattern over its length on the page
            pipeline_.npcLine(
                {{glm::dvec4(from, 1.0), 0.0}, {glm::dvec4(at, 1.0), pipeline_.npcPixels(from, at)}},
                text.leadLine->colour, text.leadLine->type, text.leadLine->width);
        for (const auto& strip : strips) {
            std::vector<ClipVertex> npc;
            for (const glm::dvec2& q : strip)
                npc.push_back({glm::dvec4(at.x + q.x, at.y + q.y, at.z, 1.0), 0.0});
            pipeline_.npcLine(npc, colour, LineType::Solid, 1.0f);
        }
        return;
    }
    // The text plane's axes: direction1, and direction2 made orthogonal to it within the plane.
    glm::dvec3 x = text.direction1, y = text.direction2;
    if (glm::length(x) == 0.0) x = {1, 0, 0};
    x = glm::normalize(x);
    y -= x * glm::dot(x, y);
    y = glm::length(y) > 0.0 ? glm::normalize(y) : glm::dvec3(0, 1, 0);
    for (const auto& strip : strips) {
        std::vector<glm::dvec3> world;
        for (const glm::dvec2& q : strip)
            world.push_back(projectPoint3(model, text.position + x * q.x + y * q.y));
        pipeline_.line(world, false, colour, LineType::Solid, 1.0f);
    }
}

void ItemProjector::operator()(const DrawMesh& mesh) {
    if (mesh.mesh) MeshProjector(pipeline_, mesh).project();
}

ProjectedScene projectScene(const DrawList& list, const PageMapping& mapping, const VectorOptions& options) {
    ProjectedScene scene;
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const DrawItem& item = list.items[i];
        const int views = std::max<int>(1, int(list.views.size()));
        if (item.viewIndex() < 0 || item.viewIndex() >= views)
            throw std::invalid_argument("vector hardcopy: draw item " + std::to_string(i) + " uses view " +
                                        std::to_string(item.viewIndex()) + " but the list has " +
                                        std::to_string(list.views.size()));
        ItemPipeline pipeline(list, item, mapping, options, scene);
        ItemProjector projector(pipeline);
        visitPrimitive(projector, item.primitive);
    }
    return scene;
}

}  // namespace phigs::hardcopy
