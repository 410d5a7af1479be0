#include "phigs/hardcopy/PaintBuilder.h"

#include "phigs/render/LinePattern.h"
#include "phigs/render/MarkerShape.h"

#include <algorithm>
#include <cmath>

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

bool finite(const PagePoint& p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

bool allFinite(const std::vector<std::vector<PagePoint>>& contours) {
    return std::all_of(contours.begin(), contours.end(),
                       [](const auto& c) { return std::all_of(c.begin(), c.end(), finite); });
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
    if (!allFinite(facet.contours)) return;
    if (facet.hatch) {
        VectorHatch h;
        h.contours = flatten(facet.contours);
        h.colour = facet.colour;
        h.opacity = facet.opacity;
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
    if (line.points.size() < 2 || !std::all_of(line.points.begin(), line.points.end(), finite)) return;
    VectorStroke s;
    for (const PagePoint& p : line.points) s.points.push_back(glm::dvec2(p));
    s.colour = line.colour;
    // NaN goes to the thinnest line, infinity to the widest.
    const double scale = std::isnan(line.width) ? 1.0 : std::clamp(double(line.width), 1.0, kMaxLineScale);
    s.width = scale * pixel_;
    const render::LinePattern pattern = render::linePattern(line.type);
    if (pattern.period > 0.0f) {
        for (float length : pattern.lengths) s.dashes.push_back(double(length) * scale * pixel_);
        // A distance along a line far out can overflow; the phase then starts afresh.
        const double offset = line.distances.empty() ? 0.0 : line.distances.front() * pixel_;
        s.dashOffset = std::isfinite(offset) ? offset : 0.0;
    }
    s.clip = line.clip;
    picture_.ops.push_back(std::move(s));
}

void PaintBuilder::operator()(const ProjectedMarker& marker) {
    const double nominalSize = render::kNominalMarkerPixels * double(marker.style.scale) * pixel_;
    if (!finite(marker.position) || !(nominalSize > 0.0)) return;
    // Larger than the page it is only a colour over all of it: cairo would cut an endless circle.
    const float scale = nominalSize > largest_ ? float(largest_ / (render::kNominalMarkerPixels * pixel_))
                                               : marker.style.scale;
    const glm::dvec2 at(marker.position);
    // Marker shapes are in pixels with y up; the page has y down.
    auto place = [&](glm::vec2 offset) { return at + glm::dvec2(offset.x, -offset.y) * pixel_; };
    if (marker.style.type == MarkerType::Circle) {
        VectorCircle c;
        c.centre = at;
        c.radius = 0.5 * render::kNominalMarkerPixels * double(scale) * pixel_;
        c.colour = marker.style.colour;
        c.width = pixel_;
        c.clip = marker.clip;
        picture_.ops.push_back(c);
        return;
    }
    const render::MarkerShape shape = render::markerShape(marker.style.type, scale);
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
