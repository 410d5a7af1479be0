#include "phigs/hardcopy/CurveRefinement.h"

#include "geom/Evaluate.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <optional>

namespace phigs::hardcopy {
namespace {

constexpr int kStartPieces = 4;
constexpr int kMaxDepth = 12;

class Refiner {
public:
    Refiner(const geom::Curve& curve, const glm::dmat4& modelToPage, double tolerance)
        : curve_(curve), toPage_(modelToPage), tolerance_(tolerance) {}

    std::vector<glm::dvec3> points;

    /// Appends the curve's points over (a, b], a's point already in `points`.
    void piece(double a, const glm::dvec3& pa, double b, const glm::dvec3& pb, int depth) {
        if (depth < kMaxDepth && strays(a, pa, b, pb)) {
            const double m = 0.5 * (a + b);
            const glm::dvec3 pm = geom::evaluate(curve_, m);
            piece(a, pa, m, pm, depth + 1);
            piece(m, pm, b, pb, depth + 1);
            return;
        }
        points.push_back(pb);
    }

private:
    std::optional<glm::dvec2> page(const glm::dvec3& p) const {
        const glm::dvec4 h = toPage_ * glm::dvec4(p, 1.0);
        if (!(h.w > 0.0)) return std::nullopt;
        return glm::dvec2(h) / h.w;
    }

    /// Whether the curve between a and b leaves the chord by more than the tolerance on the page.
    bool strays(double a, const glm::dvec3& pa, double b, const glm::dvec3& pb) const {
        const auto qa = page(pa), qb = page(pb);
        if (!qa || !qb) return false;
        const glm::dvec2 chord = *qb - *qa;
        const double length = glm::length(chord);
        for (double f : {0.25, 0.5, 0.75}) {
            const auto q = page(geom::evaluate(curve_, a + f * (b - a)));
            if (!q) return false;
            const glm::dvec2 d = *q - *qa;
            const double off =
                length > 0.0 ? std::abs(d.x * chord.y - d.y * chord.x) / length : glm::length(d);
            if (off > tolerance_) return true;
        }
        return false;
    }

    const geom::Curve& curve_;
    glm::dmat4 toPage_;
    double tolerance_;
};

}  // namespace

std::vector<glm::dvec3> refineCurve(const geom::Curve& curve, double start, double end,
                                    const glm::dmat4& modelToPage, double tolerance) {
    if (!(end > start)) start = curve.domainStart(), end = curve.domainEnd();
    start = std::max(start, curve.domainStart());
    end = std::min(end, curve.domainEnd());
    std::vector<double> breaks{start};
    for (double k : curve.knots)
        if (k > breaks.back() && k < end) breaks.push_back(k);
    if (end > start) breaks.push_back(end);
    Refiner refiner(curve, modelToPage, std::max(tolerance, 1e-6));
    glm::dvec3 previous = geom::evaluate(curve, start);
    refiner.points.push_back(previous);
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
        for (int s = 0; s < kStartPieces; ++s) {
            const double a = breaks[i] + (breaks[i + 1] - breaks[i]) * s / kStartPieces;
            const double b = s + 1 == kStartPieces
                                 ? breaks[i + 1]
                                 : breaks[i] + (breaks[i + 1] - breaks[i]) * (s + 1) / kStartPieces;
            const glm::dvec3 pb = geom::evaluate(curve, b);
            refiner.piece(a, previous, b, pb, 0);
            previous = pb;
        }
    return std::move(refiner.points);
}

}  // namespace phigs::hardcopy
