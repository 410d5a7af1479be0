#include "phigs/hardcopy/PaintBuilder.h"

#include "phigs/render/LinePattern.h"
#include "phigs/render/MarkerShape.h"

#include <algorithm>

namespace phigs::hardcopy {
namespace {

/// The raster's hatch lines (prim.frag hatchOn): 8 pixels apart, 1 pixel wide.
constexpr double kHatchSpacing = 8.0;

std::vector<double> hatchAngles(int index) {
    switch (index) {
        case 1:
            return {0.0};
        case 2:
            return {90.0};
        case 3:
            return {45.0};
        case 4:
            return {-45.0};
        case 5:
            return {0.0, 90.0};
        default:
            return {45.0, -45.0};
    }
}

std::vector<std::vector<glm::dvec2>> flatten(const std::vector<std::vector<PagePoint>>& contours) {
    std::vector<std::vector<glm::dvec2>> out;
    for (const auto& c : contours) {
        out.emplace_back();
        for (const PagePoint& p : c) out.back().push_back(glm::dvec2(p));
    }
    return out;
}

}  // namespace

void PaintBuilder::operator()(const ProjectedFacet& facet) {
    if (facet.hatch) {
        VectorHatch h;
        h.contours = flatten(facet.contours);
        h.colour = facet.colour;
        h.angles = hatchAngles(facet.hatchIndex);
        h.spacing = kHatchSpacing * pixel_;
        h.width = pixel_;
        h.clip = facet.clip;
        picture_.ops.push_back(std::move(h));
        return;
    }
    VectorFill f;
    f.contours = flatten(facet.contours);
    f.colour = facet.colour;
    f.opacity = facet.opacity;
    f.pattern = facet.pattern;
    // Half a pixel of outline closes the hairline a viewer's anti-aliasing leaves between pieces.
    f.seamWidth = facet.seam && facet.opacity >= 1.0f ? 0.5 * pixel_ : 0.0;
    f.clip = facet.clip;
    picture_.ops.push_back(std::move(f));
}

void PaintBuilder::operator()(const ProjectedLine& line) {
    if (line.points.size() < 2) return;
    VectorStroke s;
    for (const PagePoint& p : line.points) s.points.push_back(glm::dvec2(p));
    s.colour = line.colour;
    const double scale = std::max(1.0, double(line.width));
    s.width = scale * pixel_;
    const render::LinePattern pattern = render::linePattern(line.type);
    if (pattern.period > 0.0f) {
        for (float length : pattern.lengths) s.dashes.push_back(double(length) * scale * pixel_);
        s.dashOffset = line.distances.front() * pixel_;
    }
    s.clip = line.clip;
    picture_.ops.push_back(std::move(s));
}

void PaintBuilder::operator()(const ProjectedMarker& marker) {
    const glm::dvec2 at(marker.position);
    // Marker shapes are in pixels with y up; the page has y down.
    auto place = [&](glm::vec2 offset) { return at + glm::dvec2(offset.x, -offset.y) * pixel_; };
    if (marker.style.type == MarkerType::Circle) {
        VectorCircle c;
        c.centre = at;
        c.radius = 0.5 * render::kNominalMarkerPixels * std::max(marker.style.scale, 0.0f) * pixel_;
        c.colour = marker.style.colour;
        c.width = pixel_;
        c.clip = marker.clip;
        picture_.ops.push_back(c);
        return;
    }
    const render::MarkerShape shape = render::markerShape(marker.style.type, marker.style.scale);
    if (!shape.triangles.empty()) {
        glm::dvec2 lo(1e300), hi(-1e300);
        for (glm::vec2 o : shape.triangles) lo = glm::min(lo, place(o)), hi = glm::max(hi, place(o));
        VectorFill f;
        f.contours = {{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}};
        f.colour = marker.style.colour;
        f.clip = marker.clip;
        picture_.ops.push_back(std::move(f));
    }
    for (std::size_t i = 0; i + 1 < shape.segments.size(); i += 2) {
        VectorStroke s;
        s.points = {place(shape.segments[i]), place(shape.segments[i + 1])};
        s.colour = marker.style.colour;
        s.width = pixel_;
        s.clip = marker.clip;
        picture_.ops.push_back(std::move(s));
    }
}

}  // namespace phigs::hardcopy
