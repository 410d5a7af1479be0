#pragma once

#include "phigs/hardcopy/ItemPipeline.h"
#include "phigs/hardcopy/ProjectedScene.h"

#include <span>
#include <vector>

namespace phigs::hardcopy {

/// Puts one draw item's primitive on the page through its ItemPipeline, part by part in the
/// raster's order (interior, then edges; lines; markers; stroke text from the same Hershey
/// layout). One overload per payload of DrawPrimitive and no catch-all, so a new payload does
/// not compile until it is handled here.
class ItemProjector {
public:
    explicit ItemProjector(ItemPipeline& pipeline) : pipeline_(pipeline) {}

    void operator()(const DrawPolyline& polyline);
    void operator()(const DrawColouredPolyline& polyline);
    void operator()(const DrawCurve& curve);
    void operator()(const DrawPolymarker& markers);
    void operator()(const DrawFillArea& fill);
    void operator()(const DrawText& text);
    void operator()(const DrawMesh& mesh);

private:
    std::vector<glm::dvec3> toWorld(std::span<const glm::dvec3> points) const;
    void fillInterior(const DrawFillArea& fill, const std::vector<std::vector<glm::dvec3>>& world);
    void fillTriangles(const DrawFillArea& fill);

    ItemPipeline& pipeline_;
};

/// Every item of a draw list on the page, in traversal order.
ProjectedScene projectScene(const DrawList& list, const PageMapping& mapping, const VectorOptions& options);

}  // namespace phigs::hardcopy
