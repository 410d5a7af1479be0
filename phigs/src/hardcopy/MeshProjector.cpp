#include "phigs/hardcopy/MeshProjector.h"

#include "phigs/hardcopy/MeshOutline.h"

#include <glm/matrix.hpp>

#include <algorithm>

namespace phigs::hardcopy {

MeshProjector::MeshProjector(ItemPipeline& pipeline, const DrawMesh& mesh)
    : pipeline_(pipeline), mesh_(mesh), data_(*mesh.mesh) {
    const glm::dmat4& model = pipeline_.item().modelTransform().get();
    world_.reserve(data_.positions.size());
    std::vector<glm::dvec4> npc;
    npc.reserve(data_.positions.size());
    outside_.reserve(data_.positions.size());
    std::uint32_t shared = ~std::uint32_t(0);
    for (const glm::vec3& p : data_.positions) {
        const glm::dvec4 q = model * glm::dvec4(glm::dvec3(p), 1.0);
        world_.push_back(glm::dvec3(q) / (q.w != 0.0 ? q.w : 1.0));
        npc.push_back(pipeline_.toNpc(world_.back()));
        outside_.push_back(pipeline_.outsideView(npc.back()));
        shared &= outside_.back();
    }
    // Everything the mesh draws (facets, edges, iso-lines, outlines) joins its vertices.
    allOutside_ = shared != 0 && !world_.empty();
    if (allOutside_) return;
    const std::size_t count = world_.size();
    facing_.reserve(data_.triangles.size() / 3);
    for (std::size_t t = 0; t + 2 < data_.triangles.size(); t += 3) {
        const std::uint32_t a = data_.triangles[t], b = data_.triangles[t + 1], c = data_.triangles[t + 2];
        facing_.push_back(
            a < count && b < count && c < count ? ItemPipeline::facingNpc(npc[a], npc[b], npc[c]) : 0);
    }
}

void MeshProjector::project() {
    if (allOutside_) return;
    const InteriorStyleSet& in = mesh_.interior;
    if (pipeline_.options().surfaces == SurfaceDrawing::HiddenLine && in.style != InteriorStyle::Empty) {
        facets(true);
        outline();
        isoLines();
    } else {
        // Each side by its own style, as the raster draws it: a HOLLOW one outlines the facets
        // showing it, a filled one fills them.
        hollowEdges();
        if (in.fillsFrontFaces() || in.fillsBackFaces()) facets(false);
        isoLines();
    }
    // Mesh edges (with the visible trimming curves) are solid, as the raster draws them.
    if (mesh_.edges->visible) {
        edgeLines(chainEdges(facetEdges(data_)), mesh_.edges->colour, LineType::Solid, mesh_.edges->width);
        edgeLines(data_.trimEdges, mesh_.edges->colour, LineType::Solid, mesh_.edges->width);
    }
}

void MeshProjector::hollowEdges() {
    const InteriorStyleSet& in = mesh_.interior;
    glm::vec3 colour;
    if (render::hollowOutline(in, 0, colour)) {
        edgeLines(chainEdges(facetEdges(data_)), colour, LineType::Solid, 1.0f);
        return;
    }
    for (const int side : {1, -1})
        if (render::hollowOutline(in, side, colour))
            edgeLines(chainEdges(facetEdges(data_, facing_, side)), colour, LineType::Solid, 1.0f);
}

void MeshProjector::facets(bool coverOnly) {
    const InteriorStyleSet& in = mesh_.interior;
    const std::size_t count = world_.size();
    const bool normals = data_.normals.size() == count && count > 0;
    const bool colours = data_.colours.size() == count && count > 0;
    const glm::dmat3 normalMatrix =
        glm::transpose(glm::inverse(glm::dmat3(pipeline_.item().modelTransform().get())));
    std::vector<FacetVertex> vertices(3);
    std::vector<std::vector<glm::dvec3>> triangle{std::vector<glm::dvec3>(3)};  // one allocation for all
    for (std::size_t t = 0; t < facing_.size(); ++t) {
        const std::uint32_t* index = &data_.triangles[3 * t];
        if (index[0] >= count || index[1] >= count || index[2] >= count) continue;
        // Outside the view whole: clipping would leave nothing, so it is neither lit nor clipped.
        if ((outside_[index[0]] & outside_[index[1]] & outside_[index[2]]) != 0) continue;
        const int facing = facing_[t];
        // A hidden-line surface hides with both sides; a shaded one is culled as the raster culls.
        if (!coverOnly && FacetPaint::unfilled(in, facing)) continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = index[k];
            vertices[std::size_t(k)] = {
                world_[i], normals ? normalMatrix * glm::dvec3(data_.normals[i].unpacked()) : glm::dvec3(0.0),
                colours ? data_.colours[i] : in.colour};
        }
        FacetPaint paint;
        paint.coverOnly = coverOnly;
        paint.seam = true;
        if (!coverOnly) {
            const bool back = facing < 0;
            paint.paintFor(pipeline_.colouring(), in, vertices, normals, facing,
                           normals && data_.normalsPerFacet);
            const Reflectance& r = back && in.distinguishBackFaces ? in.backProperties : in.properties;
            paint.opacity = 1.0f - std::clamp(r.transparency, 0.0f, 1.0f);
        }
        for (int k = 0; k < 3; ++k) triangle[0][std::size_t(k)] = vertices[std::size_t(k)].position;
        pipeline_.facet(triangle, paint);
    }
}

void MeshProjector::edgeLines(const std::vector<std::vector<std::uint32_t>>& chains, glm::vec3 colour,
                              LineType type, float width) {
    std::vector<glm::dvec3> points;
    for (const auto& chain : chains) {
        points.clear();
        for (std::uint32_t i : chain)
            if (i < world_.size()) points.push_back(world_[i]);
        pipeline_.line(points, false, colour, type, width);
    }
}

void MeshProjector::isoLines() {
    const LineStyle& style = mesh_.isoLineStyle;
    edgeLines(data_.isoLines, style.colour, style.type, style.width);
}

void MeshProjector::outline() {
    std::vector<MeshEdge> edges = patchBoundaryEdges(data_, mesh_.surface.get());
    const std::vector<MeshEdge> silhouette = silhouetteEdges(data_, facing_);
    edges.insert(edges.end(), silhouette.begin(), silhouette.end());
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    edgeLines(chainEdges(edges), mesh_.interior->colour, LineType::Solid, 1.0f);
}

}  // namespace phigs::hardcopy
