#include "phigs/hardcopy/VectorDescriber.h"

#include "phigs/hardcopy/ItemProjector.h"
#include "phigs/hardcopy/OcclusionIndex.h"
#include "phigs/hardcopy/PaintBuilder.h"

#include <algorithm>
#include <cmath>

namespace phigs::hardcopy {
namespace {

/// How far inside its outline a facet is tested for being hidden whole, in nominal pixels: the
/// width of a seam stroke (PaintBuilder), so what a neighbour's seam would cover.
constexpr double kHiddenMargin = 0.25;

/// Whether a facet covers any area on the page (an edge-on one paints and hides nothing): its
/// points do not all lie on one line. (A sum of signed areas would not do: a bow-tie's lobes
/// cancel in it, though the even-odd rule fills them.)
bool coversArea(const ProjectedFacet& f) {
    const PagePoint* a = nullptr;
    const PagePoint* b = nullptr;
    double far = 0.0;
    for (const auto& c : f.contours)
        for (const PagePoint& p : c) {
            if (!a) a = &p;
            const double d = (p.x - a->x) * (p.x - a->x) + (p.y - a->y) * (p.y - a->y);
            if (d > far) far = d, b = &p;
        }
    if (!b) return false;
    for (const auto& c : f.contours)
        for (const PagePoint& p : c)
            if (std::abs((b->x - a->x) * (p.y - a->y) - (b->y - a->y) * (p.x - a->x)) > 1e-12) return true;
    return false;
}

/// Drops the facets hidden whole and gives back the visible runs of the scene's lines and its
/// visible markers, in order. The occlusion index lives only in here: it is gone before the facets
/// are ordered, the describe step's largest need for room.
std::vector<ProjectedPart> cullHidden(std::vector<ProjectedFacet>& facets, const ProjectedScene& scene,
                                      const PageMapping& mapping, DescribeStats& stats) {
    const OcclusionIndex occlusion(facets, mapping.nominalPixel);
    stats.occluders = occlusion.triangleCount();
    // Hidden-line surfaces need painting only where other facets could show through them; facets
    // hidden whole need no painting (most back faces, and the far sides of things).
    const bool paintCovers =
        std::any_of(facets.begin(), facets.end(), [](const ProjectedFacet& f) { return !f.coverOnly; });
    if (!paintCovers) facets.clear();
    const std::size_t before = facets.size();
    std::erase_if(facets, [&](const ProjectedFacet& f) {
        return occlusion.hidden(f, kHiddenMargin * mapping.nominalPixel);
    });
    stats.hiddenFacets = before - facets.size();
    std::vector<ProjectedPart> shown;
    // About one run a line or marker (a line hidden in places makes more): room for them at once.
    shown.reserve(scene.parts.size() + scene.parts.size() / 2);
    for (const ProjectedPart& part : scene.parts) {
        if (const auto* line = std::get_if<ProjectedLine>(&part))
            for (ProjectedLine& run : occlusion.visibleRuns(*line)) shown.push_back(std::move(run));
        if (const auto* marker = std::get_if<ProjectedMarker>(&part);
            marker && occlusion.visible(marker->position))
            shown.push_back(*marker);
    }
    return shown;
}

void describeHidden(ProjectedScene& scene, const PageMapping& mapping, PaintBuilder& paint,
                    DescribeStats& stats) {
    // The facets move out of the scene: only its lines and markers are read after this.
    std::vector<ProjectedFacet> facets;
    facets.reserve(
        std::size_t(std::count_if(scene.parts.begin(), scene.parts.end(), [](const ProjectedPart& p) {
            return std::holds_alternative<ProjectedFacet>(p);
        })));
    for (ProjectedPart& part : scene.parts)
        if (auto* f = std::get_if<ProjectedFacet>(&part); f && coversArea(*f))
            facets.push_back(std::move(*f));
    // The scene keeps its lines and markers, in order, and gives back the room of the facets it
    // held (most of its parts) before the occlusion index takes room of its own.
    std::erase_if(scene.parts,
                  [](const ProjectedPart& p) { return std::holds_alternative<ProjectedFacet>(p); });
    scene.parts.shrink_to_fit();
    std::vector<ProjectedPart> shown = cullHidden(facets, scene, mapping, stats);
    scene.parts = {};
    std::vector<ProjectedFacet> ordered =
        orderBackToFront(std::move(facets), mapping.pointsPerNpc, &stats.facets);
    // One operation a facet, line run or marker: room for them at once, not a doubling vector's
    // spare half.
    paint.reserve(ordered.size() + shown.size());
    // Each facet's points go once painted: the page holds them from then on.
    for (ProjectedFacet& f : ordered) paint(f), f.contours = {};
    ordered = {};
    for (const ProjectedPart& part : shown) std::visit(paint, part);
}

}  // namespace

VectorPicture describePicture(const DrawList& list, const PageSetup& page, const VectorOptions& options,
                              DescribeStats* stats) {
    const PageMapping mapping(list, page);
    ProjectedScene scene = projectScene(list, mapping, options);
    VectorPicture picture;
    picture.pageSize = mapping.pageSize;
    picture.paintBackground = page.background;
    picture.backgroundRect = mapping.display;
    picture.background = list.background;
    const DrawView identity;
    for (std::size_t v = 0; v < std::max<std::size_t>(1, list.views.size()); ++v)
        picture.clips.push_back(mapping.clipRect(list.views.empty() ? identity : list.views[v]));
    DescribeStats local;
    local.hidden = list.hiddenSurfaceRemoval || options.surfaces == SurfaceDrawing::HiddenLine;
    PaintBuilder paint(mapping, picture);
    if (local.hidden) {
        describeHidden(scene, mapping, paint, local);
    } else {
        // The raster's painter's order: traversal order, each item's parts in turn.
        for (const ProjectedPart& part : scene.parts) {
            const auto* facet = std::get_if<ProjectedFacet>(&part);
            if (!facet || coversArea(*facet)) std::visit(paint, part);
        }
    }
    if (stats) *stats = local;
    return picture;
}

}  // namespace phigs::hardcopy
