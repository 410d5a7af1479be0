#include "CairoPainter.h"

#include "phigs/hardcopy/UnionOutline.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <variant>

namespace phigs::hardcopy {
namespace {

/// Twice the signed area of a contour.
double signedArea(const std::vector<glm::dvec2>& c) {
    double a = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const glm::dvec2 &p = c[i], &q = c[(i + 1) % c.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return a;
}

/// A fill of one convex contour, opaque, in a plain colour (a PATTERN fill has a source of its
/// own): inside it the winding number is 1 or -1, so several of them filled as one path by the
/// non-zero rule cover their union, as painting each in turn does.
bool convexOpaque(const VectorFill& fill, bool opaque) {
    if (fill.pattern || fill.contours.size() != 1 || !(opaque || fill.opacity >= 1.0f)) return false;
    const auto& c = fill.contours[0];
    if (c.size() < 3) return false;
    int sign = 0;
    double turning = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const glm::dvec2 a = c[(i + 1) % c.size()] - c[i], b = c[(i + 2) % c.size()] - c[(i + 1) % c.size()];
        const double turn = a.x * b.y - a.y * b.x;
        const int s = turn > 0.0 ? 1 : turn < 0.0 ? -1 : 0;
        if (s != 0 && sign != 0 && s != sign) return false;
        if (s != 0) sign = s;
        if (s == 0 && glm::dot(a, b) < 0.0) return false;  // a spike: the outline turns back
        turning += std::atan2(turn, glm::dot(a, b));
    }
    // Turning one way only is not enough: a star turns one way through 4 pi or more.
    return sign != 0 && std::abs(turning) < 3.0 * std::numbers::pi;
}

/// A convex contour grown outward by `d`: what filling it and stroking its outline `2 d` wide
/// cover (the stroke's round joins as mitres, bevelled where sharp; sub-pixel apart), as one fill,
/// which cairo records, analyses and writes at half the cost of a fill and a stroke.
std::vector<glm::dvec2> grownConvex(const std::vector<glm::dvec2>& contour, double d) {
    // Points too close for an edge direction (its squared length 0 in doubles) count as one.
    auto apart = [](glm::dvec2 a, glm::dvec2 b) { return glm::dot(a - b, a - b) > 0.0; };
    std::vector<glm::dvec2> c;
    c.reserve(contour.size());
    for (const glm::dvec2& p : contour)
        if (c.empty() || apart(p, c.back())) c.push_back(p);
    while (c.size() > 1 && !apart(c.back(), c.front())) c.pop_back();
    if (c.size() < 3) return contour;
    const double side = signedArea(c) >= 0.0 ? 1.0 : -1.0;
    // The outward unit normal of the edge from c[i] to c[i + 1].
    auto normal = [&](std::size_t i) {
        const glm::dvec2 e = glm::normalize(c[(i + 1) % c.size()] - c[i]);
        return side * glm::dvec2(e.y, -e.x);
    };
    std::vector<glm::dvec2> out;
    out.reserve(2 * c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
        const glm::dvec2 before = normal((i + c.size() - 1) % c.size()), after = normal(i);
        const double cosine = glm::dot(before, after);
        if (cosine > -0.5) {
            out.push_back(c[i] + d * (before + after) / (1.0 + cosine));  // mitre at most 2 d long
        } else {
            out.push_back(c[i] + d * before);
            out.push_back(c[i] + d * after);
        }
    }
    return out;
}

/// A colour channel at 8 bits, as the raster has it: finer steps show on no screen or print,
/// and neighbouring facets of a smooth surface then share colours, so runs of them are one path.
double channel8(float c) {
    return std::lround(std::clamp(double(c), 0.0, 1.0) * 255.0) / 255.0;
}

bool sameColour(glm::vec3 a, glm::vec3 b) {
    return channel8(a.x) == channel8(b.x) && channel8(a.y) == channel8(b.y) && channel8(a.z) == channel8(b.z);
}

bool sameFillStyle(const VectorFill& a, const VectorFill& b) {
    return sameColour(a.colour, b.colour) && a.seamWidth == b.seamWidth && a.clip == b.clip;
}

/// A piece of one hatch line inside the region.
struct HatchRun {
    glm::dvec2 from, to;
};

/// The pieces of the lines across . p = k spacing (every integer k) inside the contours by the
/// even-odd rule. An edge crosses line c when c lies in (lower end, upper end] across, so a
/// vertex on a line counts once and every line meets each closed contour an even number of times.
std::vector<HatchRun> hatchRuns(const std::vector<std::vector<glm::dvec2>>& contours, glm::dvec2 along,
                                glm::dvec2 across, double spacing) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& c : contours)
        for (const glm::dvec2& p : c)
            lo = std::min(lo, glm::dot(across, p)), hi = std::max(hi, glm::dot(across, p));
    // Lines a pixel apart over a page: a bound against a region whose size is not a page's (and
    // line numbers beyond 2^53, which doubles cannot count one by one).
    if (!(hi > lo) || !(std::max(std::abs(lo), std::abs(hi)) / spacing < 1e15)) return {};
    const double first = std::floor(lo / spacing);
    const double count = std::floor(hi / spacing) - first + 1.0;
    if (!(count < 1e6)) return {};
    const auto lines = static_cast<std::int64_t>(count);
    std::vector<std::vector<double>> crossings(static_cast<std::size_t>(lines));
    for (const auto& c : contours)
        for (std::size_t i = 0; i < c.size(); ++i) {
            const glm::dvec2 p = c[i], q = c[(i + 1) % c.size()];
            const double dp = glm::dot(across, p), dq = glm::dot(across, q);
            const double low = std::min(dp, dq), high = std::max(dp, dq);
            const auto from =
                std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(low / spacing) - first));
            const auto to = std::min<std::int64_t>(
                lines - 1, static_cast<std::int64_t>(std::floor(high / spacing) - first));
            for (std::int64_t k = from; k <= to; ++k) {
                const double line = (first + double(k)) * spacing;
                if (!(line > low && line <= high)) continue;
                const glm::dvec2 at = p + (q - p) * ((line - dp) / (dq - dp));
                crossings[static_cast<std::size_t>(k)].push_back(glm::dot(along, at));
            }
        }
    std::vector<HatchRun> runs;
    for (std::size_t k = 0; k < crossings.size(); ++k) {
        auto& ts = crossings[k];
        std::sort(ts.begin(), ts.end());
        const glm::dvec2 base = across * ((first + double(k)) * spacing);
        for (std::size_t i = 0; i + 1 < ts.size(); i += 2)
            if (ts[i + 1] > ts[i]) runs.push_back({base + along * ts[i], base + along * ts[i + 1]});
    }
    return runs;
}

}  // namespace

void CairoPainter::paint(VectorPicture& picture) {
    picture_ = &picture;
    clip_ = -1;
    cairo_reset_clip(cr_);
    cairo_set_line_cap(cr_, CAIRO_LINE_CAP_BUTT);
    cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
    if (picture.paintBackground && !picture.backgroundRect.empty()) {
        const PageRect& r = picture.backgroundRect;
        colour(picture.background);
        cairo_rectangle(cr_, r.min.x, r.min.y, r.max.x - r.min.x, r.max.y - r.min.y);
        cairo_fill(cr_);
    }
    auto& ops = picture.ops;
    for (std::size_t i = 0; i < ops.size();) {
        // A run of opaque convex fills of one style is one path: the same area in one colour, and
        // a fraction of the operations for cairo to record, analyse and write.
        std::size_t end = i;
        const auto* first = std::get_if<VectorFill>(&ops[i]);
        while (first && end < ops.size()) {
            const auto* next = std::get_if<VectorFill>(&ops[end]);
            if (!next || !sameFillStyle(*first, *next) || !convexOpaque(*next, opaque_)) break;
            ++end;
        }
        if (end > i + 1) {
            fillRun(ops, i, end);
        } else {
            std::visit(*this, ops[i]);
            end = i + 1;
        }
        // Once recorded, cairo holds an operation's points: ours go now, not after the page, so
        // the two copies of the page never add up.
        for (; i < end; ++i) ops[i] = VectorCircle{};
    }
    ops = {};
    cairo_reset_clip(cr_);
    picture_ = nullptr;
}

void CairoPainter::useClip(int clip) {
    if (clip == clip_) return;
    clip_ = clip;
    cairo_reset_clip(cr_);
    if (clip < 0 || clip >= int(picture_->clips.size())) return;
    const PageRect& r = picture_->clips[std::size_t(clip)];
    cairo_rectangle(cr_, r.min.x, r.min.y, std::max(0.0, r.max.x - r.min.x),
                    std::max(0.0, r.max.y - r.min.y));
    cairo_clip(cr_);
}

void CairoPainter::contours(const std::vector<std::vector<glm::dvec2>>& contours, bool stroked) {
    cairo_new_path(cr_);
    for (const auto& c : contours) {
        if (c.size() < 2) continue;
        cairo_move_to(cr_, c[0].x, c[0].y);
        for (std::size_t i = 1; i < c.size(); ++i) cairo_line_to(cr_, c[i].x, c[i].y);
        // A fill closes every contour itself; closing one costs a "close" and, after the last, a
        // move back to its start in the file. Only an outline that is stroked must be closed.
        if (stroked) cairo_close_path(cr_);
    }
}

void CairoPainter::fillRun(const std::vector<VectorOp>& ops, std::size_t begin, std::size_t end) {
    const VectorFill& style = std::get<VectorFill>(ops[begin]);
    useClip(style.clip);
    // All counter-clockwise (in page coordinates), so that overlaps add up rather than cancel;
    // then the edges neighbours share cancel, and cairo gets the outline of the union.
    std::vector<std::vector<glm::dvec2>> reversed;
    reversed.reserve(end - begin);
    std::vector<const std::vector<glm::dvec2>*> run;
    for (std::size_t i = begin; i < end; ++i) {
        const auto& c = std::get<VectorFill>(ops[i]).contours[0];
        if (signedArea(c) >= 0.0) {
            run.push_back(&c);
        } else {
            reversed.emplace_back(c.rbegin(), c.rend());
            run.push_back(&reversed.back());
        }
    }
    contours(unionOutline(run), style.seamWidth > 0.0);
    colour(style.colour);
    cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
    if (style.seamWidth > 0.0) {
        cairo_fill_preserve(cr_);
        cairo_set_line_width(cr_, style.seamWidth);
        cairo_set_dash(cr_, nullptr, 0, 0.0);
        cairo_stroke(cr_);
    } else {
        cairo_fill(cr_);
    }
}

void CairoPainter::colour(glm::vec3 rgb, float opacity) {
    const double r = channel8(rgb.x), g = channel8(rgb.y), b = channel8(rgb.z);
    if (opaque_ || opacity >= 1.0f)
        cairo_set_source_rgb(cr_, r, g, b);
    else
        cairo_set_source_rgba(cr_, r, g, b, std::max(0.0f, opacity));
}

void CairoPainter::patternSource(const PagePattern& pattern, float opacity) {
    const DrawPattern& cells = pattern.cells;
    // Each cell a block of pixels: a viewer that smooths images then blurs only a seam of a
    // pixel between cells. PDF says not to smooth (the nearest filter); SVG cannot say it
    // (cairo), and its renderers smooth: there blocks as large as a million pixels in all allow,
    // up to 128, keep the seam a small part of a cell.
    const bool smoothed = cairo_surface_get_type(cairo_get_target(cr_)) == CAIRO_SURFACE_TYPE_SVG;
    const double cellCount = double(cells.columns) * double(cells.rows);
    const int block = smoothed ? std::clamp(int(std::sqrt(double(1 << 20) / cellCount)), 1, 128)
                               : std::clamp(1024 / std::max(cells.columns, cells.rows), 1, 16);
    cairo_surface_t* surface =
        cairo_image_surface_create(CAIRO_FORMAT_ARGB32, cells.columns * block, cells.rows * block);
    cairo_surface_flush(surface);
    unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    const double alpha = opaque_ ? 1.0 : std::clamp(double(opacity), 0.0, 1.0);
    auto channel = [&](float c) {
        return std::uint32_t(std::lround(std::clamp(double(c), 0.0, 1.0) * alpha * 255.0));
    };
    for (int y = 0; y < cells.rows * block; ++y)
        for (int x = 0; x < cells.columns * block; ++x) {
            const glm::vec3 c = cells.colours[std::size_t((y / block) * cells.columns + x / block)];
            // Premultiplied ARGB in native byte order.
            const std::uint32_t pixel = std::uint32_t(std::lround(alpha * 255.0)) << 24 | channel(c.x) << 16 |
                                        channel(c.y) << 8 | channel(c.z);
            std::memcpy(data + y * stride + x * 4, &pixel, 4);
        }
    cairo_surface_mark_dirty(surface);
    cairo_pattern_t* source = cairo_pattern_create_for_surface(surface);
    cairo_surface_destroy(surface);
    cairo_pattern_set_extend(source, CAIRO_EXTEND_REPEAT);
    cairo_pattern_set_filter(source, CAIRO_FILTER_NEAREST);
    // The pattern matrix maps user space (the page) to pattern space (cells, `block` pixels each).
    cairo_matrix_t matrix;
    const glm::dvec3 u = pattern.u * double(block), v = pattern.v * double(block);
    cairo_matrix_init(&matrix, u.x, v.x, u.y, v.y, u.z, v.z);
    cairo_pattern_set_matrix(source, &matrix);
    cairo_set_source(cr_, source);
    cairo_pattern_destroy(source);
}

void CairoPainter::operator()(const VectorFill& fill) {
    useClip(fill.clip);
    if (fill.seamWidth > 0.0 && convexOpaque(fill, opaque_)) {
        contours({grownConvex(fill.contours[0], 0.5 * fill.seamWidth)}, false);
        colour(fill.colour);
        cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
        cairo_fill(cr_);
        return;
    }
    contours(fill.contours, fill.seamWidth > 0.0);
    if (fill.pattern)
        patternSource(*fill.pattern, fill.opacity);
    else
        colour(fill.colour, fill.opacity);
    cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_EVEN_ODD);
    if (fill.seamWidth > 0.0) {
        cairo_fill_preserve(cr_);
        cairo_set_line_width(cr_, fill.seamWidth);
        cairo_set_dash(cr_, nullptr, 0, 0.0);
        cairo_stroke(cr_);
    } else {
        cairo_fill(cr_);
    }
}

void CairoPainter::operator()(const VectorHatch& hatch) {
    useClip(hatch.clip);
    colour(hatch.colour, hatch.opacity);
    cairo_set_line_width(cr_, hatch.width);
    cairo_set_dash(cr_, nullptr, 0, 0.0);
    const double spacing = std::max(hatch.spacing, 1e-3);
    for (double degrees : hatch.angles) {
        // Lines across . p = k spacing; y is down on the page, angles count up. Each line's runs
        // inside the region are worked out here, even-odd, rather than left to a clip path: SVG
        // readers take a clip path's own rule, which cairo does not write.
        const double a = degrees * std::numbers::pi / 180.0;
        const glm::dvec2 along(std::cos(a), -std::sin(a)), across(std::sin(a), std::cos(a));
        cairo_new_path(cr_);
        for (const HatchRun& run : hatchRuns(hatch.contours, along, across, spacing)) {
            cairo_move_to(cr_, run.from.x, run.from.y);
            cairo_line_to(cr_, run.to.x, run.to.y);
        }
        cairo_stroke(cr_);
    }
}

void CairoPainter::operator()(const VectorStroke& stroke) {
    useClip(stroke.clip);
    cairo_new_path(cr_);
    cairo_move_to(cr_, stroke.points[0].x, stroke.points[0].y);
    for (std::size_t i = 1; i < stroke.points.size(); ++i)
        cairo_line_to(cr_, stroke.points[i].x, stroke.points[i].y);
    colour(stroke.colour);
    cairo_set_line_width(cr_, stroke.width);
    cairo_set_dash(cr_, stroke.dashes.empty() ? nullptr : stroke.dashes.data(), int(stroke.dashes.size()),
                   stroke.dashOffset);
    cairo_stroke(cr_);
}

void CairoPainter::operator()(const VectorCircle& circle) {
    useClip(circle.clip);
    cairo_new_path(cr_);
    // cairo cuts a circle into pieces by its size: one far larger than the page would never end.
    const double radius = std::min(circle.radius, 2.0 * glm::length(picture_->pageSize));
    if (!(radius > 0.0) || !std::isfinite(circle.centre.x) || !std::isfinite(circle.centre.y)) return;
    cairo_arc(cr_, circle.centre.x, circle.centre.y, radius, 0.0, 2.0 * std::numbers::pi);
    cairo_close_path(cr_);
    colour(circle.colour);
    cairo_set_line_width(cr_, circle.width);
    cairo_set_dash(cr_, nullptr, 0, 0.0);
    cairo_stroke(cr_);
}

}  // namespace phigs::hardcopy
