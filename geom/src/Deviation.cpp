#include "geom/Deviation.h"

#include "KeptVector.h"
#include "RemovalDetail.h"
#include "geom/CurveProjector.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/GridEvaluator.h"
#include "geom/SurfaceProjector.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace geom {
namespace {

using detail::MeasureProof;

// Distances by Newton from the sample's own parameter are distances to real points of the other
// shape, so they bound the true ones from above; the global projection (geom's projectors) is
// run on the samples that could hold the maximum (at least half the largest local distance),
// where a nearer point elsewhere would change the answer. Elsewhere the local answer stands.
// (Rational curves.)
template <class Global>
void refineLargest(std::vector<double>& distances, Global&& global) {
    double worst = 0.0;
    for (double d : distances) worst = std::max(worst, d);
    for (std::size_t i = 0; i < distances.size(); ++i)
        if (distances[i] >= 0.5 * worst && distances[i] > 0.0)
            distances[i] = std::min(distances[i], global(i));
}

// The same maximum with fewer global projections: the samples go largest local distance first,
// and the global projection stops once no local distance left exceeds the largest result.
template <class Global>
void largestFirst(std::vector<double>& distances, Global&& global) {
    std::vector<std::size_t> order(distances.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return distances[a] > distances[b]; });
    double worst = 0.0;
    for (std::size_t i : order) {
        if (distances[i] <= worst) break;
        distances[i] = std::min(distances[i], global(i));
        worst = std::max(worst, distances[i]);
    }
}

std::vector<double> distancesTo(const Curve& curve, const std::vector<glm::dvec3>& points,
                                const std::vector<double>& seeds) {
    const CurveProjector projector(curve);
    std::vector<double> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        out[i] = projector.closestPointFrom(points[i], seeds[i]).distance;
    refineLargest(out, [&](std::size_t i) { return projector.closestPoint(points[i]).distance; });
    return out;
}

CurveDeviation summary(const std::vector<double>& da, const std::vector<double>& db, double peakA = 0.0,
                       double peakB = 0.0) {
    CurveDeviation out;
    double sum = 0.0;
    for (double d : da) out.maxOriginalToReduced = std::max(out.maxOriginalToReduced, d), sum += d;
    for (double d : db) out.maxReducedToOriginal = std::max(out.maxReducedToOriginal, d), sum += d;
    out.maxOriginalToReduced = std::max(out.maxOriginalToReduced, peakA);
    out.maxReducedToOriginal = std::max(out.maxReducedToOriginal, peakB);
    out.maxError = std::max(out.maxOriginalToReduced, out.maxReducedToOriginal);
    out.samples = da.size() + db.size();
    out.meanError = sum / static_cast<double>(out.samples);
    return out;
}

// Every sample's distance measured by point inversion (rational curves, different domains).
CurveDeviation measureDeviationByProjection(const Curve& original, const Curve& reduced, int samplesPerSpan) {
    const std::vector<double> pa =
        spanSamples(original.knots, original.degree, original.points.size(), samplesPerSpan);
    const std::vector<double> pb =
        spanSamples(reduced.knots, reduced.degree, reduced.points.size(), samplesPerSpan);
    const std::vector<glm::dvec3> a = evaluateMany(original, pa), b = evaluateMany(reduced, pb);
    return summary(distancesTo(reduced, a, pa), distancesTo(original, b, pb));
}

// A sampler of c that keeps every span's power form: the given forms (detail::powerForms of c),
// or made as the spans are first used.
void emplaceSampler(std::optional<detail::SplineSampler>& sampler, const Curve& c,
                    const std::vector<glm::dvec3>* forms) {
    if (forms)
        sampler.emplace(c.degree, c.knots, c.points.data(), c.points.size(), *forms);
    else
        sampler.emplace(c.degree, c.knots, c.points.data(), c.points.size(), true);
}

// The index in [first, last) of the point nearest to q (first where the range is empty).
std::size_t nearestOf(const std::vector<glm::dvec3>& points, std::size_t first, std::size_t last,
                      const glm::dvec3& q) {
    std::size_t nearest = first;
    double nearestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t k = first; k < last; ++k) {
        const double e = glm::dot(points[k] - q, points[k] - q);
        if (e < nearestDistance) nearestDistance = e, nearest = k;
    }
    return nearest;
}

// Distances from samples of `from` (at ascending params) to `to`, two polynomial curves on one
// domain; seeds[i] is a parameter of `to` near from(params[i]) (params itself for the plain
// measurement). |from(t) - to(seed)| is the distance to a point of `to`, so it bounds the closest
// distance from above: the samples are taken largest bound first, and each is measured by
// Newton from the seed and, where that could still be the maximum, by the global closest point,
// until the next bound is below the largest distance measured (no sample left can reach it). A
// sample not measured keeps its bound, which is below the maximum, so the maximum is exactly
// that of measuring them all; the mean is an upper bound.
// global(q, d) is the closest distance from q to `to`, given a distance d to a point of it;
// toForms, where given, are the power forms of `to` (detail::powerForms). With a proof (see
// MeasureProof), samples whose bound is within its floor keep their bound, and the pass stops
// at the first distance past its ceiling.
template <class Global>
detail::KeptVector<double> sampleDistances(const Curve& to, const std::vector<glm::dvec3>& a,
                                           const std::vector<double>& seeds, Global&& global,
                                           const std::vector<glm::dvec3>* toForms = nullptr,
                                           const MeasureProof& proof = {}) {
    std::optional<detail::SplineSampler> sampler;
    emplaceSampler(sampler, to, toForms);
    detail::SplineSampler& toSampler = *sampler;
    // The bounds |a_i - to(seed_i)|, the curve evaluated a chunk at a time (no array of points
    // as long as the samples').
    detail::KeptVector<double> out(seeds.size());
    std::array<glm::dvec3, 256> chunk;
    for (std::size_t start = 0; start < seeds.size(); start += chunk.size()) {
        const std::size_t n = std::min(chunk.size(), seeds.size() - start);
        detail::evaluateAscending(to.degree, to.knots, to.points.data(), to.points.size(),
                                  std::span<const double>(seeds).subspan(start, n), chunk.data(), toForms);
        for (std::size_t k = 0; k < n; ++k) out[start + k] = glm::length(a[start + k] - chunk[k]);
    }
    double worst = proof.floor;
    auto measure = [&](std::size_t i) {
        double d = detail::newtonDistance(toSampler, a[i], seeds[i], out[i]);
        if (d > worst) d = std::min(d, global(a[i], d));
        out[i] = d;
        worst = std::max(worst, d);
    };
    // The largest bounds first give a maximum close to the final one; every other sample is
    // measured only where its bound exceeds the maximum so far (no sample skipped can reach it).
    // A sample measured has out[i] <= worst from then on, so the pass over all of them skips it.
    constexpr std::size_t head = 16;
    std::array<std::size_t, head> largest{};
    std::size_t kept = 0;  // largest[0, kept) by descending bound
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (kept == head && !(out[i] > out[largest[head - 1]])) continue;
        std::size_t at = kept < head ? kept++ : head - 1;
        for (; at > 0 && out[largest[at - 1]] < out[i]; --at) largest[at] = largest[at - 1];
        largest[at] = i;
    }
    for (std::size_t k = 0; k < kept && out[largest[k]] > worst && worst <= proof.ceiling; ++k)
        measure(largest[k]);
    for (std::size_t i = 0; i < out.size() && worst <= proof.ceiling; ++i)
        if (out[i] > worst) measure(i);
    return out;
}

// Brent's method for the largest value of f in [a, b], from x (where f is fx, the best known),
// until the bracket's half is within 2 `within` of x: parabolas through the last three points
// where they step inside the bracket and shrink it fast enough, golden sections otherwise. A
// smooth peak takes a few evaluations where golden sections alone take 18 for the same bracket;
// a kink falls back to golden sections. Returns the best value.
template <class F>
double maximiseBetween(F&& f, double a, double b, double x, double fx, double within) {
    constexpr double golden = 0.3819660112501051;  // (3 - sqrt 5) / 2
    double w = x, v = x, fw = fx, fv = fx;
    double step = 0.0, previous = 0.0;  // the last step, and the one before it
    for (int evaluations = 1; evaluations < 40; ++evaluations) {
        const double middle = 0.5 * (a + b);
        if (std::abs(x - middle) <= 2.0 * within - 0.5 * (b - a)) break;
        bool parabolic = false;
        if (std::abs(previous) > within) {
            // The vertex of the parabola through (x, fx), (w, fw), (v, fv), as x + p / q.
            const double r = (x - w) * (fv - fx), t = (x - v) * (fw - fx);
            double p = (x - v) * t - (x - w) * r, q = 2.0 * (t - r);
            if (q > 0.0) p = -p;
            q = std::abs(q);
            if (std::abs(p) < std::abs(0.5 * q * previous) && p > q * (a - x) && p < q * (b - x)) {
                previous = step;
                step = p / q;
                parabolic = true;
                if (x + step - a < 2.0 * within || b - (x + step) < 2.0 * within)
                    step = middle > x ? within : -within;
            }
        }
        if (!parabolic) {
            previous = x >= middle ? a - x : b - x;
            step = golden * previous;
        }
        const double u = std::abs(step) >= within ? x + step : x + (step > 0.0 ? within : -within);
        const double fu = f(u);
        if (fu >= fx) {
            (u >= x ? a : b) = x;
            v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
        } else {
            (u < x ? a : b) = u;
            if (fu >= fw || w == x) {
                v = w, fv = fw, w = u, fw = fu;
            } else if (fu >= fv || v == x || v == w) {
                v = u, fv = fu;
            }
        }
    }
    return fx;
}

// The largest distance from `from` to `to` near the sampled maxima: the distances d at
// ascending params (seeds as in sampleDistances) peak between samples, by up to a few percent
// of the maximum where a span is long. Each local maximum within a tenth of the largest is
// searched by Brent's method between its neighbours from it (to a bracket of 5e-4 of their
// interval), every point measured as the samples are.
// With a proof, only the maxima at or past its floor are followed (the samples below it may hold
// bounds, not distances), and none once a distance is past its ceiling.
template <class Global>
double peakDistance(const Curve& from, const std::vector<double>& params, const Curve& to,
                    const std::vector<double>& seeds, const std::vector<double>& d, Global&& global,
                    const std::vector<glm::dvec3>* toForms = nullptr,
                    const std::vector<glm::dvec3>* fromForms = nullptr, const MeasureProof& proof = {}) {
    const std::size_t n = d.size();
    double best = 0.0;
    for (double x : d) best = std::max(best, x);
    if (n < 2 || !(best > 0.0) || best > proof.ceiling) return best;
    std::optional<detail::SplineSampler> sampler, fromSampler;
    emplaceSampler(sampler, to, toForms);
    emplaceSampler(fromSampler, from, fromForms);
    const double threshold = std::max(0.9 * best, proof.floor);
    for (std::size_t i = 0; i < n && best <= proof.ceiling; ++i) {
        if (d[i] < threshold || (i > 0 && d[i - 1] > d[i]) || (i + 1 < n && d[i + 1] > d[i])) continue;
        const std::size_t l = i > 0 ? i - 1 : i, r = i + 1 < n ? i + 1 : i;
        const double lo = params[l], hi = params[r];
        if (!(hi > lo)) continue;
        auto distanceAt = [&](double t) {
            const double seed = seeds[l] + (t - lo) / (hi - lo) * (seeds[r] - seeds[l]);
            const glm::dvec3 p = fromSampler->value(t);
            const double bound = glm::length(p - sampler->value(seed));
            double e = detail::newtonDistance(*sampler, p, seed, bound);
            if (e > best) e = std::min(e, global(p, e));
            best = std::max(best, e);
            return e;
        };
        maximiseBetween(distanceAt, lo, hi, params[i], d[i], 1.25e-4 * (hi - lo));
    }
    return best;
}

// The global step of the plain measurement: geom's CurveProjector, and since its Newton runs may
// all end in local minima on a wiggly curve, Newton from the nearest of the other curve's samples.
struct ProjectorStep {
    const Curve& to;
    const std::vector<double>& toParams;
    const std::vector<glm::dvec3>& toPoints;
    std::optional<CurveProjector> projector;
    std::optional<detail::SplineSampler> sampler;

    double operator()(const glm::dvec3& q, double d) {
        if (!projector) projector.emplace(to);
        d = std::min(d, projector->closestPoint(q).distance);
        const std::size_t nearest = nearestOf(toPoints, 0, toPoints.size(), q);
        if (!sampler) sampler.emplace(to.degree, to.knots, to.points.data(), to.points.size());
        return std::min(d, detail::newtonDistance(*sampler, q, toParams[nearest], d));
    }
};

// The global step of the meter: every non-empty span whose control points' box (the span lies
// in their convex hull) is nearer than the best distance so far, by Newton from the nearest of
// the span's samples. Cheaper to set up than a projector (no Bezier extraction).
struct SpanStep {
    const Curve& to;
    const std::vector<double>& toParams;
    const std::vector<glm::dvec3>& toPoints;
    const CurveDeviationMeter::SpanBoxes& boxes;
    std::optional<detail::SplineSampler> sampler;

    SpanStep(const Curve& c, const std::vector<double>& params, const std::vector<glm::dvec3>& points,
             const CurveDeviationMeter::SpanBoxes& b, const std::vector<glm::dvec3>* forms = nullptr)
        : to(c), toParams(params), toPoints(points), boxes(b) {
        emplaceSampler(sampler, c, forms);
    }

    static bool fartherThan(const glm::dvec3& low, const glm::dvec3& high, const glm::dvec3& q, double d) {
        const glm::dvec3 out = glm::max(glm::max(low - q, q - high), glm::dvec3(0.0));
        return glm::dot(out, out) >= d * d;
    }

    double operator()(const glm::dvec3& q, double d) {
        // A group's box holds its spans' boxes: where it is farther than d, so is each of them.
        const std::size_t size = CurveDeviationMeter::SpanBoxes::groupSize;
        for (std::size_t s = 0; s < boxes.low.size(); ++s) {
            if (s % size == 0 && fartherThan(boxes.groupLow[s / size], boxes.groupHigh[s / size], q, d)) {
                s += size - 1;
                continue;
            }
            if (fartherThan(boxes.low[s], boxes.high[s], q, d)) continue;
            const std::size_t nearest = nearestOf(toPoints, boxes.first[s], boxes.last[s], q);
            if (nearest < toParams.size())
                d = std::min(d, detail::newtonDistance(*sampler, q, toParams[nearest], d));
        }
        return d;
    }
};

detail::KeptVector<glm::dvec3> valuesAt(const Curve& c, const std::vector<double>& params,
                                        const std::vector<glm::dvec3>* forms = nullptr) {
    detail::KeptVector<glm::dvec3> out(params.size());
    detail::evaluateAscending(c.degree, c.knots, c.points.data(), c.points.size(), params, out.data(), forms);
    return out;
}

// The map's piecewise linear interpolant at ascending parameters x (clamped to its ends).
detail::KeptVector<double> interpolate(const std::vector<double>& xs, const std::vector<double>& ys,
                                       const std::vector<double>& x) {
    detail::KeptVector<double> out(x.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        while (k + 2 < xs.size() && xs[k + 1] <= x[i]) ++k;
        if (xs.size() == 1 || x[i] <= xs[k]) {
            out[i] = ys[k];
        } else if (x[i] >= xs[k + 1]) {
            out[i] = ys[k + 1];
        } else {
            const double f = (x[i] - xs[k]) / (xs[k + 1] - xs[k]);
            out[i] = ys[k] + f * (ys[k + 1] - ys[k]);
        }
    }
    return out;
}

// A grid's maxima can sit between its vertices. Each local maximum within a tenth of the largest is followed
// by a compass search inside its neighbours' cell, to 5e-4 of the cell; distanceAt(u, v) measures as the
// vertices are measured and gives a distance to a real point, so the result never overstates (a global
// projection where the local one would raise the largest so far, passed as its third argument).
template <class Distance>
double followPeaks(const std::vector<double>& u, const std::vector<double>& v, const std::vector<double>& d,
                   Distance&& distanceAt) {
    double best = 0.0;
    for (double x : d) best = std::max(best, x);
    if (!(best > 0.0)) return best;
    const double threshold = 0.9 * best;
    const std::size_t nu = u.size(), nv = v.size();
    auto value = [&](std::size_t i, std::size_t j) { return d[i * nv + j]; };
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const std::size_t i0 = i > 0 ? i - 1 : i, i1 = i + 1 < nu ? i + 1 : i;
            const std::size_t j0 = j > 0 ? j - 1 : j, j1 = j + 1 < nv ? j + 1 : j;
            double f = value(i, j);
            bool peak = f >= threshold;
            for (std::size_t a = i0; peak && a <= i1; ++a)
                for (std::size_t b = j0; peak && b <= j1; ++b) peak = value(a, b) <= f;
            if (!peak) continue;
            const double loU = u[i0], hiU = u[i1], loV = v[j0], hiV = v[j1];
            double cu = u[i], cv = v[j], hu = 0.25 * (hiU - loU), hv = 0.25 * (hiV - loV);
            for (int step = 0; step < 64 && (hu > 5e-4 * (hiU - loU) || hv > 5e-4 * (hiV - loV)); ++step) {
                bool moved = false;
                for (const auto& [du, dv] : {std::pair{hu, 0.0}, {-hu, 0.0}, {0.0, hv}, {0.0, -hv}}) {
                    const double tu = std::clamp(cu + du, loU, hiU), tv = std::clamp(cv + dv, loV, hiV);
                    if (tu == cu && tv == cv) continue;
                    if (const double e = distanceAt(tu, tv, best); e > f) {
                        f = e, cu = tu, cv = tv, moved = true;
                        break;
                    }
                }
                if (!moved) hu *= 0.5, hv *= 0.5;
            }
            best = std::max(best, f);
        }
    return best;
}

/// Throws GeometryError naming the first entry of a parameter map's side that is not finite or
/// lies below the one before it (std::is_sorted lets a NaN through: every comparison is false).
void checkMapSide(const std::vector<double>& side, const char* name) {
    for (std::size_t i = 0; i < side.size(); ++i)
        if (!std::isfinite(side[i]) || (i > 0 && side[i] < side[i - 1]))
            throw GeometryError(
                std::string("measureDeviation: the parameter map must be finite and ascending: ") + name +
                "[" + std::to_string(i) + "] = " + std::to_string(side[i]) +
                (std::isfinite(side[i]) ? " is below the one before it" : " is not finite"));
}

/// Throws GeometryError naming `where` and the argument unless least <= n <= maxSamplesPerSpan.
void checkSamplesPerSpan(int n, const char* where, const char* name, int least = 1) {
    if (n < least || n > maxSamplesPerSpan)
        throw GeometryError(std::string(where) + ": " + name + " must be from " + std::to_string(least) +
                            " to " + std::to_string(maxSamplesPerSpan) + " (is " + std::to_string(n) + ")");
}

}  // namespace

void detail::spanSamplesInto(std::vector<double>& out, const std::vector<double>& knots, int degree,
                             std::size_t count, int samplesPerSpan) {
    if (samplesPerSpan < 1) throw GeometryError("spanSamples: samplesPerSpan must be at least 1");
    if (degree < 0 || knots.size() != count + static_cast<std::size_t>(degree) + 1)
        throw GeometryError("spanSamples: " + std::to_string(knots.size()) + " knots do not fit degree " +
                            std::to_string(degree) + " and " + std::to_string(count) +
                            " control points (knots = count + degree + 1)");
    out.clear();
    out.reserve((count - std::min<std::size_t>(count, static_cast<std::size_t>(degree))) *
                    (static_cast<std::size_t>(samplesPerSpan) + 1) +
                1);
    const std::size_t p = static_cast<std::size_t>(degree);
    for (std::size_t i = p; i < count; ++i) {
        const double a = knots[i], b = knots[i + 1];
        if (!(b > a)) continue;
        for (int k = 0; k < samplesPerSpan; ++k) out.push_back(a + (b - a) * k / samplesPerSpan);
        // At a jump (an interior knot of multiplicity degree + 1) a parameter at the knot gives
        // the point after it: the piece's own end is reached from the double just below.
        const double beforeJump = std::nextafter(b, -std::numeric_limits<double>::infinity());
        if (i + 1 < count && knots[i + 1 + p] == b && beforeJump > out.back()) out.push_back(beforeJump);
    }
    out.push_back(knots[count]);
}

std::vector<double> spanSamples(const std::vector<double>& knots, int degree, std::size_t count,
                                int samplesPerSpan) {
    checkSamplesPerSpan(samplesPerSpan, "spanSamples", "samplesPerSpan");
    std::vector<double> out;
    detail::spanSamplesInto(out, knots, degree, count, samplesPerSpan);
    return out;
}

CurveDeviation measureDeviation(const Curve& original, const Curve& reduced, int samplesPerSpan) {
    checkSamplesPerSpan(samplesPerSpan, "measureDeviation", "samplesPerSpan");
    validate(original, "measureDeviation: original");
    validate(reduced, "measureDeviation: reduced");
    if (original.rational() || reduced.rational())
        return measureDeviationByProjection(original, reduced, samplesPerSpan);
    if (original.domainStart() != reduced.domainStart() || original.domainEnd() != reduced.domainEnd())
        return measureDeviationByProjection(original, reduced, samplesPerSpan);
    const std::vector<double> pa =
        spanSamples(original.knots, original.degree, original.points.size(), samplesPerSpan);
    const std::vector<double> pb =
        spanSamples(reduced.knots, reduced.degree, reduced.points.size(), samplesPerSpan);
    const detail::KeptVector<glm::dvec3> a = valuesAt(original, pa), b = valuesAt(reduced, pb);
    ProjectorStep toReduced{reduced, pb, b, {}, {}}, toOriginal{original, pa, a, {}, {}};
    const detail::KeptVector<double> da = sampleDistances(reduced, a, pa, toReduced);
    const detail::KeptVector<double> db = sampleDistances(original, b, pb, toOriginal);
    return summary(da, db, peakDistance(original, pa, reduced, pa, da, toReduced),
                   peakDistance(reduced, pb, original, pb, db, toOriginal));
}

CurveDeviation measureDeviation(const Curve& original, const Curve& reduced, int samplesPerSpan,
                                const ParameterMap& map, int reducedSamplesPerSpan) {
    return CurveDeviationMeter(original, samplesPerSpan).measure(reduced, map, reducedSamplesPerSpan);
}

CurveDeviationMeter::SpanBoxes CurveDeviationMeter::spanBoxes(const Curve& c,
                                                              const std::vector<double>& params) {
    SpanBoxes out;
    const std::size_t p = static_cast<std::size_t>(c.degree);
    for (std::size_t j = p; j < c.points.size(); ++j) {
        if (!(c.knots[j + 1] > c.knots[j])) continue;
        glm::dvec3 lo = c.points[j - p], hi = lo;
        for (std::size_t k = j - p + 1; k <= j; ++k)
            lo = glm::min(lo, c.points[k]), hi = glm::max(hi, c.points[k]);
        out.low.push_back(lo);
        out.high.push_back(hi);
        const auto from = std::lower_bound(params.begin(), params.end(), c.knots[j]);
        const auto to = std::upper_bound(from, params.end(), c.knots[j + 1]);
        out.first.push_back(static_cast<std::size_t>(from - params.begin()));
        out.last.push_back(static_cast<std::size_t>(to - params.begin()));
    }
    for (std::size_t s = 0; s < out.low.size(); ++s) {
        if (s % SpanBoxes::groupSize == 0)
            out.groupLow.push_back(out.low[s]), out.groupHigh.push_back(out.high[s]);
        out.groupLow.back() = glm::min(out.groupLow.back(), out.low[s]);
        out.groupHigh.back() = glm::max(out.groupHigh.back(), out.high[s]);
    }
    return out;
}

CurveDeviationMeter::CurveDeviationMeter(const Curve& original, int samplesPerSpan)
    : CurveDeviationMeter(
          original,
          (checkSamplesPerSpan(samplesPerSpan, "measureDeviation", "samplesPerSpan"), samplesPerSpan),
          nullptr, nullptr, nullptr) {
}

CurveDeviationMeter::CurveDeviationMeter(const Curve& original, int samplesPerSpan,
                                         std::shared_ptr<const std::vector<glm::dvec3>> forms,
                                         std::shared_ptr<const std::vector<double>> params,
                                         std::shared_ptr<const std::vector<glm::dvec3>> points)
    : original_(original), samplesPerSpan_(samplesPerSpan) {
    validate(original, "measureDeviation: original");
    if (original.rational()) throw GeometryError("measureDeviation: a parameter map needs polynomial curves");
    params_ = points ? std::move(params)
                     : std::make_shared<const std::vector<double>>(spanSamples(
                           original.knots, original.degree, original.points.size(), samplesPerSpan));
    originalForms_ =
        forms ? std::move(forms)
              : std::make_shared<const std::vector<glm::dvec3>>(detail::powerForms(
                    original.degree, original_.knots, original_.points.data(), original_.points.size()));
    points_ = points ? std::move(points)
                     : std::make_shared<const std::vector<glm::dvec3>>(
                           valuesAt(original_, *params_, originalForms_.get()));
    boxes_ = spanBoxes(original, *params_);
}

CurveDeviation CurveDeviationMeter::measure(const Curve& reduced, const ParameterMap& map,
                                            int reducedSamplesPerSpan) const {
    checkSamplesPerSpan(reducedSamplesPerSpan, "measureDeviation", "reducedSamplesPerSpan", 0);
    return checkedMeasure(reduced, map, reducedSamplesPerSpan, {});
}

bool CurveDeviationMeter::within(const Curve& reduced, const ParameterMap& map, double tolerance,
                                 int reducedSamplesPerSpan) const {
    if (!(tolerance > 0.0)) throw GeometryError("CurveDeviationMeter::within: tolerance must be positive");
    checkSamplesPerSpan(reducedSamplesPerSpan, "CurveDeviationMeter::within", "reducedSamplesPerSpan", 0);
    return checkedMeasure(reduced, map, reducedSamplesPerSpan, {0.9 * tolerance, tolerance}).maxError <=
           tolerance;
}

CurveDeviation CurveDeviationMeter::checkedMeasure(const Curve& reduced, const ParameterMap& map,
                                                   int reducedSamplesPerSpan,
                                                   const MeasureProof& proof) const {
    validate(reduced, "measureDeviation: reduced");
    if (reduced.rational()) throw GeometryError("measureDeviation: a parameter map needs polynomial curves");
    if (original_.domainStart() != reduced.domainStart() || original_.domainEnd() != reduced.domainEnd())
        throw GeometryError("measureDeviation: a parameter map needs curves on one domain");
    if (map.from.empty() || map.from.size() != map.to.size())
        throw GeometryError(
            "measureDeviation: the parameter map must be non-empty, from and to of one size (" +
            std::to_string(map.from.size()) + " and " + std::to_string(map.to.size()) + ")");
    checkMapSide(map.from, "from");
    checkMapSide(map.to, "to");
    if (reducedSamplesPerSpan < 0) throw GeometryError("measureDeviation: reducedSamplesPerSpan is negative");
    return measureAlong(reduced, map.from, map.to, reducedSamplesPerSpan, proof);
}

CurveDeviation CurveDeviationMeter::measureAlong(const Curve& reduced, const std::vector<double>& from,
                                                 const std::vector<double>& to, int reducedSamplesPerSpan,
                                                 const MeasureProof& proof) const {
    detail::KeptVector<double> pb;
    detail::spanSamplesInto(pb, reduced.knots, reduced.degree, reduced.points.size(),
                            reducedSamplesPerSpan > 0 ? reducedSamplesPerSpan : samplesPerSpan_);
    auto clampTo = [](detail::KeptVector<double>&& u, const Curve& c) {
        for (double& x : u) x = std::clamp(x, c.domainStart(), c.domainEnd());
        return std::move(u);
    };
    const detail::KeptVector<glm::dvec3> b = valuesAt(reduced, pb);
    const std::vector<double>& params = *params_;
    const std::vector<glm::dvec3>& points = *points_;
    const std::vector<glm::dvec3>* forms = originalForms_.get();
    const detail::KeptVector<double> seedsA = clampTo(interpolate(from, to, params), reduced);
    const detail::KeptVector<double> seedsB = clampTo(interpolate(to, from, pb), original_);
    const SpanBoxes reducedBoxes = spanBoxes(reduced, pb);  // SpanStep keeps a reference
    SpanStep toReduced(reduced, pb, b, reducedBoxes);
    SpanStep toOriginal(original_, params, points, boxes_, forms);
    const detail::KeptVector<double> da = sampleDistances(reduced, points, seedsA, toReduced, nullptr, proof);
    const double peakA =
        peakDistance(original_, params, reduced, seedsA, da, toReduced, nullptr, forms, proof);
    // A proof that failed one way needs nothing from the other.
    if (peakA > proof.ceiling) return summary(da, {}, peakA);
    const detail::KeptVector<double> db = sampleDistances(original_, b, seedsB, toOriginal, forms, proof);
    return summary(da, db, peakA,
                   peakDistance(reduced, pb, original_, seedsB, db, toOriginal, forms, nullptr, proof));
}

SurfaceDeviation measureDeviation(const Surface& original, const Surface& reduced, int samplesPerSpan) {
    checkSamplesPerSpan(samplesPerSpan, "measureDeviation", "samplesPerSpan");
    validate(original, "measureDeviation: original");
    validate(reduced, "measureDeviation: reduced");
    if (original.domainStartU() != reduced.domainStartU() || original.domainEndU() != reduced.domainEndU() ||
        original.domainStartV() != reduced.domainStartV() || original.domainEndV() != reduced.domainEndV())
        throw GeometryError("measureDeviation: the two surfaces have different parameter domains");
    SurfaceDeviation out;
    out.u = spanSamples(reduced.knotsU, reduced.degreeU, reduced.countU, samplesPerSpan);
    out.v = spanSamples(reduced.knotsV, reduced.degreeV, reduced.countV, samplesPerSpan);
    out.error.resize(out.u.size() * out.v.size());
    const SurfaceProjector toOriginal(original), toReduced(reduced);
    const std::vector<GridSample> reducedGrid = GridEvaluator(reduced).evaluate(out.u, out.v);
    std::vector<glm::dvec3> onReduced(out.error.size());
    for (std::size_t i = 0; i < out.u.size(); ++i)
        for (std::size_t j = 0; j < out.v.size(); ++j) {
            const std::size_t k = i * out.v.size() + j;
            onReduced[k] = reducedGrid[k].point;
            out.error[k] = toOriginal.closestPointFrom(onReduced[k], {out.u[i], out.v[j]}).distance;
        }
    largestFirst(out.error, [&](std::size_t k) { return toOriginal.closestPoint(onReduced[k]).distance; });
    double sum = 0.0;
    for (double d : out.error) sum += d;
    out.meanError = sum / static_cast<double>(out.error.size());
    out.maxReducedToOriginal = followPeaks(out.u, out.v, out.error, [&](double u, double v, double best) {
        const glm::dvec3 p = evaluate(reduced, u, v);
        const double e = toOriginal.closestPointFrom(p, {u, v}).distance;
        return e > best ? std::min(e, toOriginal.closestPoint(p).distance) : e;
    });

    const std::vector<double> ou =
        spanSamples(original.knotsU, original.degreeU, original.countU, samplesPerSpan);
    const std::vector<double> ov =
        spanSamples(original.knotsV, original.degreeV, original.countV, samplesPerSpan);
    // The other way only the maximum is reported: |S(u,v) - S'(u,v)| bounds each vertex's
    // distance from above, so the vertices are measured largest bound first (Newton from (u,v),
    // then the global closest point where that could still be the maximum) until no bound left
    // can reach the largest distance found.
    const std::vector<GridSample> originalGrid = GridEvaluator(original).evaluate(ou, ov);
    const std::vector<GridSample> reducedThere = GridEvaluator(reduced).evaluate(ou, ov);
    std::vector<double> bound(originalGrid.size());
    std::vector<std::size_t> order(bound.size());
    for (std::size_t k = 0; k < bound.size(); ++k)
        bound[k] = glm::length(originalGrid[k].point - reducedThere[k].point), order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return bound[a] > bound[b]; });
    // Vertices left unmeasured keep their bound, which is below the maximum, for the peak search.
    std::vector<double> distance = bound;
    for (std::size_t k : order) {
        if (bound[k] <= out.maxOriginalToReduced) break;
        const glm::dvec3& q = originalGrid[k].point;
        double d = std::min(bound[k],
                            toReduced.closestPointFrom(q, {ou[k / ov.size()], ov[k % ov.size()]}).distance);
        if (d > out.maxOriginalToReduced) d = std::min(d, toReduced.closestPoint(q).distance);
        out.maxOriginalToReduced = std::max(out.maxOriginalToReduced, d);
        distance[k] = d;
    }
    out.maxOriginalToReduced = followPeaks(ou, ov, distance, [&](double u, double v, double best) {
        const glm::dvec3 q = evaluate(original, u, v);
        const double e = std::min(glm::length(q - evaluate(reduced, u, v)),
                                  toReduced.closestPointFrom(q, {u, v}).distance);
        return e > best ? std::min(e, toReduced.closestPoint(q).distance) : e;
    });
    out.maxError = std::max(out.maxOriginalToReduced, out.maxReducedToOriginal);
    return out;
}

}  // namespace geom
