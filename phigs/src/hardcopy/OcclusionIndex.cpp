#include "phigs/hardcopy/OcclusionIndex.h"

#include "phigs/render/Triangulation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace phigs::hardcopy {
namespace {

/// Depth bias of the raster path (Renderer: slope factor 1.5 pixels), and a floor for flat facets.
constexpr double kSlopePixels = 1.5;
constexpr double kMinTolerance = 1e-7;
constexpr int kMaxOcclusionCells = 512;

/// Where f(t) = fa + t (fb - fa) >= c for t in [lo, hi]; narrows [lo, hi], false when empty.
bool atLeast(double fa, double fb, double c, double& lo, double& hi) {
    if (fa >= c && fb >= c) return lo <= hi;
    if (fa < c && fb < c) return false;
    const double t = (c - fa) / (fb - fa);
    if (fa < c)
        lo = std::max(lo, t);
    else
        hi = std::min(hi, t);
    return lo <= hi;
}

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

/// The cell of a coordinate among `count` of size `step` from `origin`, clamped in floating point
/// (a coordinate far off, infinite or NaN gives an end cell, never an out-of-range conversion).
int cellIndex(double v, double origin, double step, int count) {
    const double c = std::floor((v - origin) / step);
    return c >= double(count - 1) ? count - 1 : c >= 0.0 ? int(c) : 0;
}

/// Intervals in order of their start.
void sortByStart(std::vector<glm::dvec2>& intervals) {
    std::sort(intervals.begin(), intervals.end(), [](glm::dvec2 p, glm::dvec2 q) { return p.x < q.x; });
}

/// The parts of [0, 1] outside every interval (sorted by their start), ignoring gaps of 1e-9.
void openParts(const std::vector<glm::dvec2>& sorted, std::vector<glm::dvec2>& open) {
    open.clear();
    double from = 0.0;
    for (const glm::dvec2& h : sorted) {
        if (h.x > from + 1e-9) open.push_back({from, h.x});
        from = std::max(from, h.y);
    }
    if (from < 1.0 - 1e-9) open.push_back({from, 1.0});
}

}  // namespace

OcclusionIndex::OcclusionIndex(const std::vector<ProjectedFacet>& facets, double pixel) : pixel_(pixel) {
    // The triangles the facets make (n - 2 for a simple contour, n + 2 h - 2 with h holes; more
    // where contours cross or the triangulation adds points, hence the slack): one allocation of
    // about the right size, not a doubling vector's spare half.
    std::size_t expected = 0;
    for (const ProjectedFacet& f : facets) {
        if (!f.occludes) continue;
        std::size_t points = 0;
        for (const auto& c : f.contours) points += c.size() + 2;
        expected += points > 4 ? points - 4 : 0;
    }
    triangles_.reserve(expected + expected / 8 + 16);
    for (const ProjectedFacet& f : facets) {
        if (!f.occludes) continue;
        if (f.contours.size() == 1 && f.contours[0].size() == 3) {
            add(f.contours[0][0], f.contours[0][1], f.contours[0][2]);
            continue;
        }
        std::vector<std::vector<glm::dvec2>> flat;
        std::vector<glm::dvec3> all;
        for (const auto& c : f.contours) {
            flat.emplace_back();
            for (const PagePoint& p : c) flat.back().push_back(glm::dvec2(p)), all.push_back(p);
        }
        const render::Triangulation tri = render::triangulateEvenOdd(flat);
        auto at = [&](std::uint32_t i) {
            const render::TriangulationVertex& v = tri.vertices[i];
            return all[v.from] + (all[v.to] - all[v.from]) * v.t;
        };
        for (std::size_t t = 0; t + 2 < tri.triangles.size(); t += 3)
            add(at(tri.triangles[t]), at(tri.triangles[t + 1]), at(tri.triangles[t + 2]));
    }
    bin();
}

void OcclusionIndex::add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    // Edge-on on the page: it covers nothing.
    if (!(std::abs(n.z) > 1e-12 * glm::length(n))) return;
    Triangle t;
    // Counter-clockwise on the page, so that hides() needs no orientation of its own.
    const bool clockwise = n.z < 0.0;
    t.p[0] = glm::dvec2(a), t.p[1] = glm::dvec2(clockwise ? c : b), t.p[2] = glm::dvec2(clockwise ? b : c);
    t.plane = {-n.x / n.z, -n.y / n.z, 0.0};
    t.plane.z = a.z - t.plane.x * a.x - t.plane.y * a.y;
    triangles_.push_back(t);
}

double OcclusionIndex::tolerance(const Triangle& t) const {
    return kMinTolerance + kSlopePixels * std::max(std::abs(t.plane.x), std::abs(t.plane.y)) * pixel_;
}

void OcclusionIndex::bin() {
    if (triangles_.empty()) return;
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const Triangle& t : triangles_) lo = glm::min(lo, t.lo()), hi = glm::max(hi, t.hi());
    // About four cells per triangle: the model covers a part of the page only, and a query then
    // meets few triangles that its cells hold but its segment misses.
    const int n =
        std::clamp(int(std::ceil(2.0 * std::sqrt(double(triangles_.size())))), 1, kMaxOcclusionCells);
    columns_ = rows_ = n;
    lo_ = lo;
    cell_ = glm::max((hi - lo) / double(n), glm::dvec2(1e-9));
    // The cells' lists in one array (counted, then filled): no allocation per cell.
    cellStart_.assign(std::size_t(columns_) * std::size_t(rows_) + 1, 0);
    for (const Triangle& t : triangles_)
        forCells(t.lo(), t.hi(), [&](std::size_t cell) { ++cellStart_[cell + 1]; });
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    cellItems_.resize(cellStart_.back());
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::uint32_t i = 0; i < triangles_.size(); ++i)
        forCells(triangles_[i].lo(), triangles_[i].hi(),
                 [&](std::size_t cell) { cellItems_[fill[cell]++] = i; });
    stamp_.assign(triangles_.size(), 0);
}

template <class F>
void OcclusionIndex::forCells(glm::dvec2 lo, glm::dvec2 hi, F&& f) const {
    if (cellStart_.empty()) return;
    const int x0 = cellIndex(lo.x, lo_.x, cell_.x, columns_), x1 = cellIndex(hi.x, lo_.x, cell_.x, columns_);
    const int y0 = cellIndex(lo.y, lo_.y, cell_.y, rows_), y1 = cellIndex(hi.y, lo_.y, cell_.y, rows_);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) f(std::size_t(y) * std::size_t(columns_) + std::size_t(x));
}

bool OcclusionIndex::hides(const Triangle& t, const PagePoint& a, const PagePoint& b,
                           glm::dvec2& interval) const {
    const glm::dvec2 pa(a), pb(b);
    const glm::dvec2 boxLo = t.lo(), boxHi = t.hi();
    if (std::max(pa.x, pb.x) < boxLo.x || std::min(pa.x, pb.x) > boxHi.x || std::max(pa.y, pb.y) < boxLo.y ||
        std::min(pa.y, pb.y) > boxHi.y)
        return false;
    double lo = 0.0, hi = 1.0;
    // Behind: the facet's depth minus the line's exceeds the tolerance (z grows toward the viewer).
    // Tested first, as it is the cheaper test and rejects the segment's own surface; the interval
    // is the intersection of all four, in any order.
    const double ga = t.plane.x * pa.x + t.plane.y * pa.y + t.plane.z - a.z;
    const double gb = t.plane.x * pb.x + t.plane.y * pb.y + t.plane.z - b.z;
    if (!atLeast(ga, gb, tolerance(t), lo, hi)) return false;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 p = t.p[i], edge = t.p[(i + 1) % 3] - p;
        if (!atLeast(cross(edge, pa - p), cross(edge, pb - p), 0.0, lo, hi)) return false;
    }
    if (hi - lo <= 1e-12) return false;
    interval = {lo, hi};
    return true;
}

void OcclusionIndex::collectHidden(const PagePoint& a, const PagePoint& b, glm::dvec2 lo, glm::dvec2 hi,
                                   std::vector<glm::dvec2>& hidden,
                                   std::vector<std::uint32_t>* hiders) const {
    if (++query_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), query_ = 1;
    forCells(lo, hi, [&](std::size_t cell) {
        for (std::uint32_t i : items(cell)) {
            if (stamp_[i] == query_) continue;
            stamp_[i] = query_;
            glm::dvec2 interval;
            if (hides(triangles_[i], a, b, interval)) {
                hidden.push_back(interval);
                if (hiders) hiders->push_back(i);
            }
        }
    });
}

void OcclusionIndex::hiddenIntervals(const PagePoint& a, const PagePoint& b, std::vector<glm::dvec2>& hidden,
                                     std::vector<std::uint32_t>* hiders) const {
    hidden.clear();
    collectHidden(a, b, glm::min(glm::dvec2(a), glm::dvec2(b)), glm::max(glm::dvec2(a), glm::dvec2(b)),
                  hidden, hiders);
    sortByStart(hidden);
}

std::vector<glm::dvec2> OcclusionIndex::visibleParts(const PagePoint& a, const PagePoint& b) const {
    std::vector<glm::dvec2> hidden, visible;
    hiddenIntervals(a, b, hidden);
    openParts(hidden, visible);
    return visible;
}

bool OcclusionIndex::hiddenWhole(const PagePoint& a, const PagePoint& b) const {
    // First the triangles that hid the facet's centre or its other edges: neighbouring edges are
    // mostly behind the same few. Their intervals are some of all the triangles' intervals, so
    // when they cover the segment all of them do, and the answer is the full query's.
    scratch_.clear();
    for (std::size_t k = 0; k < hints_.size(); ++k) {
        glm::dvec2 interval;
        if (hides(triangles_[hints_[k]], a, b, interval)) scratch_.push_back(interval), hintUsed_[k] = 1;
    }
    // Only the triangles over the parts the hints leave open are tested (their boxes meet fewer
    // cells than the whole segment's), on the whole segment: the intervals and the cover test are
    // the full query's, less triangles that can hide nothing the hints leave open.
    sortByStart(scratch_);
    openParts(scratch_, gaps_);
    if (gaps_.empty()) return true;
    found_.clear();
    const glm::dvec2 from(a), along = glm::dvec2(b) - from;
    // Each part's box widened by a hair, so that rounding in its ends loses no triangle touching it.
    const glm::dvec2 hair = 1e-9 * (glm::abs(along) + 1.0);
    for (const glm::dvec2& gap : gaps_) {
        const glm::dvec2 p = from + along * gap.x, q = from + along * gap.y;
        collectHidden(a, b, glm::min(p, q) - hair, glm::max(p, q) + hair, scratch_, &found_);
    }
    sortByStart(scratch_);
    openParts(scratch_, gaps_);
    if (!gaps_.empty()) return false;
    for (std::uint32_t i : found_)
        if (std::find(hints_.begin(), hints_.end(), i) == hints_.end())
            hints_.push_back(i), hintUsed_.push_back(1);
    return true;
}

bool OcclusionIndex::visible(const PagePoint& p) const {
    bool hidden = false;
    forCells(glm::dvec2(p), glm::dvec2(p), [&](std::size_t cell) {
        for (std::uint32_t i : items(cell)) {
            glm::dvec2 interval;
            hidden = hidden || hides(triangles_[i], p, p, interval);
        }
    });
    return !hidden;
}

void OcclusionIndex::hidersOf(const PagePoint& p, std::vector<std::uint32_t>& hiders) const {
    // A point lies in one cell: no triangle is met twice.
    forCells(glm::dvec2(p), glm::dvec2(p), [&](std::size_t cell) {
        for (std::uint32_t i : items(cell)) {
            glm::dvec2 interval;
            if (hides(triangles_[i], p, p, interval)) hiders.push_back(i);
        }
    });
}

bool OcclusionIndex::hidden(const ProjectedFacet& facet, double margin) const {
    PagePoint centre(0.0);
    std::size_t count = 0;
    for (const auto& c : facet.contours)
        for (const PagePoint& p : c) centre += p, ++count;
    if (count == 0) return false;
    centre /= double(count);
    // A facet with a point not on the page (NaN, infinite) is not known to be hidden.
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z)) return false;
    // The centre must lie behind some triangle. The last facet's hiders are tried first; where
    // one hides the centre they are the hints (they only shorten the edges' queries, so the
    // answer is the same), else the centre's own hiders are, and with none the facet shows.
    hints_.clear();
    for (std::uint32_t i : carried_) {
        glm::dvec2 interval;
        if (hides(triangles_[i], centre, centre, interval)) {
            hints_ = carried_;
            break;
        }
    }
    if (hints_.empty()) hidersOf(centre, hints_);
    if (hints_.empty()) return false;
    hintUsed_.assign(hints_.size(), 0);
    auto inside = [&](const PagePoint& p) {
        const double distance = glm::length(glm::dvec2(centre - p));
        return distance > 0.0 ? p + (centre - p) * std::min(0.1, margin / distance) : p;
    };
    bool whole = true;
    for (const auto& c : facet.contours)
        for (std::size_t i = 0; whole && i < c.size(); ++i)
            whole = hiddenWhole(inside(c[i]), inside(c[(i + 1) % c.size()]));
    carried_.clear();
    for (std::size_t k = 0; k < hints_.size(); ++k)
        if (hintUsed_[k]) carried_.push_back(hints_[k]);
    return whole;
}

std::vector<ProjectedLine> OcclusionIndex::visibleRuns(const ProjectedLine& line) const {
    std::vector<ProjectedLine> runs;
    bool open = false;  // the last run reaches the end of the previous segment
    for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
        const PagePoint &a = line.points[i], &b = line.points[i + 1];
        const double da = line.distances[i], db = line.distances[i + 1];
        bool reachedEnd = false;
        for (const glm::dvec2& part : visibleParts(a, b)) {
            if (!(open && part.x <= 1e-9)) {
                ProjectedLine run = line;
                run.points = {a + (b - a) * part.x};
                run.distances = {da + (db - da) * part.x};
                runs.push_back(std::move(run));
            }
            runs.back().points.push_back(a + (b - a) * part.y);
            runs.back().distances.push_back(da + (db - da) * part.y);
            open = false;
            reachedEnd = part.y >= 1.0 - 1e-9;
        }
        open = reachedEnd;
    }
    return runs;
}

}  // namespace phigs::hardcopy
