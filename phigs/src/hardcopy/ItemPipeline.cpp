#include "phigs/hardcopy/ItemPipeline.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace phigs::hardcopy {
namespace {

const DrawView& viewOf(const DrawList& list, const DrawItem& item) {
    static const DrawView identity;
    return list.views.empty() ? identity : list.views[std::size_t(item.viewIndex())];
}

}  // namespace

void FacetPaint::styleFor(const InteriorStyleSet& in, int facing) {
    const bool back = facing < 0;
    const InteriorStyle style = in.styleOf(back);
    hatch = style == InteriorStyle::Hatch;
    hatchIndex = in.styleIndexOf(back);
    pattern = style == InteriorStyle::Pattern;
    backPattern = back && in.distinguishBackFaces;
    model = in.renderingModel;
}

void FacetPaint::paintFor(const ItemColouring& colouring, const InteriorStyleSet& in,
                          const std::vector<FacetVertex>& vertices, bool vertexNormals, int facing,
                          bool facetNormals) {
    colour = colouring.facet(in, vertices, vertexNormals, facing < 0, facetNormals);
    styleFor(in, facing);
    if (pattern) cells = colouring.patternLighting(in, vertices, vertexNormals, facing < 0, facetNormals);
}

bool FacetPaint::unfilled(const InteriorStyleSet& in, int facing) {
    return facing < 0 ? !in.fillsBackFaces() : facing > 0 && !in.fillsFrontFaces();
}

ItemPipeline::ItemPipeline(const DrawList& list, const DrawItem& item, const PageMapping& mapping,
                           const VectorOptions& options, ProjectedScene& out)
    : list_(list),
      item_(item),
      mapping_(mapping),
      options_(options),
      out_(out),
      worldToNpc_(viewOf(list, item).mapping * viewOf(list, item).orientation),
      view_(viewVolume(viewOf(list, item), list)),
      model_(modelVolume(item.modelClipPlanes())),
      colouring_(list, item, viewerOf(viewOf(list, item)), options.highlight) {
    const InteriorStyleSet* interior = nullptr;
    if (const auto* fill = primitiveIf<DrawFillArea>(item.primitive)) interior = &fill->interior.get();
    if (const auto* mesh = primitiveIf<DrawMesh>(item.primitive)) interior = &mesh->interior.get();
    if (!interior) return;
    for (int side = 0; side < 2; ++side) {
        if (interior->styleOf(side == 1) != InteriorStyle::Pattern) continue;
        // No pattern defined, or a pattern box with no area on the primitive: drawn solid.
        const DrawPattern* pattern = render::findPattern(list, interior->styleIndexOf(side == 1));
        pattern_[side] = pattern;
        if (pattern && pattern->columns >= 1 && pattern->rows >= 1 &&
            pattern->colours.size() == std::size_t(pattern->columns) * std::size_t(pattern->rows))
            patternMap_[side] = render::itemPatternMap(item, *pattern);
    }
}

std::shared_ptr<const PagePattern> ItemPipeline::pagePattern(
    const std::vector<std::vector<glm::dvec3>>& world, double depth, int side,
    const ItemColouring::CellLighting& lighting, ColourModel model) const {
    // Three well spread points of the facet: the first, the farthest from it, and the one
    // farthest from the line through those two.
    std::vector<glm::dvec3> points;
    for (const auto& contour : world) points.insert(points.end(), contour.begin(), contour.end());
    if (points.size() < 3) return nullptr;
    const glm::dmat4 toPage = worldToPage();
    auto page = [&](const glm::dvec3& x) {
        const glm::dvec4 h = toPage * glm::dvec4(x, 1.0);
        return glm::dvec2(h) / h.w;
    };
    auto score = [&](auto measure) {
        std::size_t best = 0;
        double most = -1.0;
        for (std::size_t k = 0; k < points.size(); ++k)
            if (const double m = measure(page(points[k])); m > most) most = m, best = k;
        return best;
    };
    const glm::dvec2 p0 = page(points[0]);
    const glm::dvec3 x1 = points[score([&](glm::dvec2 p) { return glm::length(p - p0); })];
    const glm::dvec2 p1 = page(x1);
    const glm::dvec3 x2 = points[score(
        [&](glm::dvec2 p) { return std::abs((p1.x - p0.x) * (p.y - p0.y) - (p1.y - p0.y) * (p.x - p0.x)); })];
    const glm::dvec2 p2 = page(x2);
    // Rows (x, y, 1) of the three page points; the cell coordinates there give u and v.
    const glm::dmat3 rows =
        glm::transpose(glm::dmat3(glm::dvec3(p0, 1), glm::dvec3(p1, 1), glm::dvec3(p2, 1)));
    const double det = glm::determinant(rows);
    if (!(std::abs(det) > 1e-12)) return nullptr;
    const glm::dmat3 inverse = glm::inverse(rows);
    const render::PatternMap& map = *patternMap_[side];
    const glm::dvec2 c0 = map.at(points[0]), c1 = map.at(x1), c2 = map.at(x2);
    auto result = std::make_shared<PagePattern>();
    result->cells = *pattern_[side];
    for (glm::vec3& colour : result->cells.colours)
        colour = colouring_.finish(colour * lighting.gain + lighting.offset, depth, model);
    result->u = inverse * glm::dvec3(c0.x, c1.x, c2.x);
    result->v = inverse * glm::dvec3(c0.y, c1.y, c2.y);
    return result;
}

bool ItemPipeline::modelClipKeeps(const glm::dvec3& world) const {
    return inside(glm::dvec4(world, 1.0), model_);
}

std::optional<glm::dvec4> ItemPipeline::keptPoint(const glm::dvec3& world) const {
    if (!modelClipKeeps(world)) return std::nullopt;
    const glm::dvec4 h = toNpc(world);
    if (!inside(h, view_)) return std::nullopt;
    return h;
}

void ItemPipeline::line(const std::vector<glm::dvec3>& world, bool closed, glm::vec3 colour, LineType type,
                        float width, std::span<const glm::vec3> colours, bool interpolated) {
    if (world.size() < 2) return;
    // Dashes are measured along the line on the page, before clipping (the raster measures on screen).
    std::vector<ClipVertex> vertices;
    double distance = 0.0;
    glm::dvec2 previous(0.0);
    const std::size_t count = world.size() + (closed ? 1 : 0);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3& p = world[i % world.size()];
        const glm::dvec4 page = mapping_.npcToPage * toNpc(p);
        const glm::dvec2 q = page.w > 0.0 ? glm::dvec2(page) / page.w : previous;
        if (i > 0) distance += glm::length(q - previous) / mapping_.nominalPixel;
        previous = q;
        vertices.push_back({glm::dvec4(p, 1.0), distance, double(i)});
    }
    if (colours.size() != world.size()) colours = {};
    for (auto& run : clipPolyline(vertices, model_)) {
        for (ClipVertex& v : run) v.h = worldToNpc_ * v.h;
        if (colours.empty()) {
            npcLine(run, colour, type, width);
            continue;
        }
        for (const auto& viewed : clipPolyline(run, view_))
            colouredRun(viewed, colours, interpolated, type, width);
    }
}

void ItemPipeline::colouredRun(const std::vector<ClipVertex>& run, std::span<const glm::vec3> colours,
                               bool interpolated, LineType type, float width) {
    const std::size_t n = colours.size();
    auto colourAt = [&](double along) {
        const double k = std::clamp(std::floor(along), 0.0, double(n - 1));
        const std::size_t i = std::size_t(k);
        if (!interpolated || i + 1 >= n) return colours[i];
        return glm::mix(colours[i], colours[i + 1], float(along - k));
    };
    auto at = [](const ClipVertex& a, const ClipVertex& b, double t) {
        return ClipVertex{a.h + t * (b.h - a.h), a.distance + t * (b.distance - a.distance),
                          a.along + t * (b.along - a.along)};
    };
    std::vector<ClipVertex> piece;
    glm::vec3 pieceColour(0.0f);
    auto flush = [&] {
        if (piece.size() > 1) emitRun(piece, pieceColour, type, width);
        piece.clear();
    };
    for (std::size_t i = 0; i + 1 < run.size(); ++i) {
        const ClipVertex &a = run[i], &b = run[i + 1];
        // A run segment lies within one segment of the line: its colour at its middle.
        const double middle = 0.5 * (a.along + b.along);
        if (!interpolated) {
            const glm::vec3 c = colourAt(middle);
            if (piece.empty() || c != pieceColour) flush(), piece.push_back(a), pieceColour = c;
            piece.push_back(b);
            continue;
        }
        flush();
        const glm::vec3 d = glm::abs(colourAt(b.along) - colourAt(a.along));
        const int steps = std::clamp(int(std::ceil(std::max({d.x, d.y, d.z}) * 255.0f)), 1, 255);
        for (int k = 0; k < steps; ++k) {
            const ClipVertex p = at(a, b, double(k) / steps), q = at(a, b, double(k + 1) / steps);
            emitRun({p, q}, colourAt(0.5 * (p.along + q.along)), type, width);
        }
    }
    flush();
}

double ItemPipeline::npcPixels(const glm::dvec3& a, const glm::dvec3& b) const {
    const glm::dvec2 pa(mapping_.npcToPage * glm::dvec4(a, 1.0)), pb(mapping_.npcToPage * glm::dvec4(b, 1.0));
    return glm::length(pb - pa) / mapping_.nominalPixel;
}

void ItemPipeline::npcLine(const std::vector<ClipVertex>& npc, glm::vec3 colour, LineType type, float width) {
    for (const auto& run : clipPolyline(npc, view_)) emitRun(run, colour, type, width);
}

void ItemPipeline::emitRun(const std::vector<ClipVertex>& run, glm::vec3 colour, LineType type, float width) {
    ProjectedLine line;
    line.type = type;
    line.width = width;
    line.clip = item_.viewIndex();
    for (const ClipVertex& v : run) {
        line.points.push_back(mapping_.toPage(glm::dvec3(v.h) / v.h.w));
        line.distances.push_back(v.distance);
    }
    if (!colouring_.cued()) {
        line.colour = colouring_.finish(colour, line.points.front().z);
        out_.parts.push_back(std::move(line));
        return;
    }
    // Depth cued: one piece per segment, each coloured at its middle's depth.
    for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
        ProjectedLine piece = line;
        piece.points = {line.points[i], line.points[i + 1]};
        piece.distances = {line.distances[i], line.distances[i + 1]};
        piece.colour = colouring_.finish(colour, 0.5 * (line.points[i].z + line.points[i + 1].z));
        out_.parts.push_back(std::move(piece));
    }
}

void ItemPipeline::facet(const std::vector<std::vector<glm::dvec3>>& world, const FacetPaint& paint) {
    ProjectedFacet f;
    double depth = 0.0;
    std::size_t count = 0;
    std::vector<ClipVertex>& polygon = polygon_;
    // A contour inside a volume is what clipping to it gives back: those skip the clipper.
    auto within = [&](const std::vector<HalfSpace>& volume) {
        return std::all_of(polygon.begin(), polygon.end(),
                           [&](const ClipVertex& v) { return inside(v.h, volume); });
    };
    for (const auto& contour : world) {
        polygon.clear();
        for (const glm::dvec3& p : contour) polygon.push_back({glm::dvec4(p, 1.0), 0.0});
        if (polygon.size() < 3) continue;
        if (!within(model_)) polygon = clipPolygon(std::move(polygon), model_);
        for (ClipVertex& v : polygon) v.h = worldToNpc_ * v.h;
        if (!within(view_)) polygon = clipPolygon(std::move(polygon), view_);
        if (polygon.empty()) continue;
        if (f.contours.empty()) f.contours.reserve(world.size());
        f.contours.emplace_back().reserve(polygon.size());
        for (const ClipVertex& v : polygon) {
            f.contours.back().push_back(mapping_.toPage(glm::dvec3(v.h) / v.h.w));
            depth += f.contours.back().back().z;
            ++count;
        }
    }
    if (f.contours.empty()) return;
    f.colour = paint.coverOnly ? list_.background
                               : colouring_.finish(paint.colour, depth / double(count), paint.model);
    f.opacity = paint.opacity;
    f.hatch = paint.hatch;
    f.hatchIndex = paint.hatchIndex;
    if (const int side = paint.backPattern ? 1 : 0; paint.pattern && !paint.coverOnly && patternMap_[side])
        f.pattern = pagePattern(world, depth / double(count), side, paint.cells, paint.model);
    f.occludes = !paint.hatch && paint.opacity >= 1.0f;
    f.coverOnly = paint.coverOnly;
    f.seam = paint.seam;
    f.clip = item_.viewIndex();
    out_.parts.push_back(std::move(f));
}

void ItemPipeline::marker(const glm::dvec3& world, const MarkerStyle& style) {
    const std::optional<glm::dvec4> h = keptPoint(world);
    if (!h) return;
    ProjectedMarker m;
    m.position = mapping_.toPage(glm::dvec3(*h) / h->w);
    m.style = style;
    m.style.colour = colouring_.finish(style.colour, m.position.z);
    m.clip = item_.viewIndex();
    out_.parts.push_back(m);
}

std::uint32_t ItemPipeline::outsideView(const glm::dvec4& npc) const {
    std::uint32_t bits = 0;
    for (std::size_t i = 0; i < view_.size() && i < 32; ++i)
        if (!(glm::dot(view_[i].plane, npc) - view_[i].offset >= 0.0)) bits |= std::uint32_t(1) << i;
    return bits;
}

int ItemPipeline::facing(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) const {
    return facingNpc(toNpc(a), toNpc(b), toNpc(c));
}

int ItemPipeline::facingNpc(const glm::dvec4& ha, const glm::dvec4& hb, const glm::dvec4& hc) {
    if (!(ha.w > 0.0 && hb.w > 0.0 && hc.w > 0.0)) return 0;
    const glm::dvec2 pa = glm::dvec2(ha) / ha.w, pb = glm::dvec2(hb) / hb.w, pc = glm::dvec2(hc) / hc.w;
    // NPC has y up: counter-clockwise there is the front, as the raster's winding test says.
    const double area = (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
    return area > 0.0 ? 1 : area < 0.0 ? -1 : 0;
}

}  // namespace phigs::hardcopy
