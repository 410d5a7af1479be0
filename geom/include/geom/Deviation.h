#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace geom {

/// The most samples per span that spanSamples, measureDeviation (curves and surfaces) and
/// CurveDeviationMeter take (samplesPerSpan, reducedSamplesPerSpan; ReductionOptions::samplesPerSpan
/// has the same limit); a larger count throws GeometryError naming the argument and the limit
/// rather than asking for memory no measurement needs (1 << 30 per span is 8 GiB per span).
inline constexpr int maxSamplesPerSpan = 4096;

/// The measured distance between two curves (an original and its approximation), both ways.
struct CurveDeviation {
    double maxError = 0.0;              ///< Hausdorff distance: the larger of the two below
    double meanError = 0.0;             ///< mean distance over every sample of both curves (see below)
    double maxOriginalToReduced = 0.0;  ///< max over samples of the original of their distance to the other
    double maxReducedToOriginal = 0.0;  ///< the same the other way
    std::size_t samples = 0;            ///< points measured, both curves together
};

/// Samples each curve densely (samplesPerSpan points in every non-empty knot span, ends
/// included, both one-sided limits at a jump: spanSamples) and measures each sample's distance
/// to the other curve by point inversion. For two polynomial curves on one domain, |f(t) - g(t)|
/// bounds a sample's distance from above, so the samples are inverted largest bound first
/// (Newton from t, then CurveProjector's global closest point where the result could be the
/// maximum) until no bound left exceeds the largest distance found: the maxima are those of
/// inverting every sample, and the mean counts the bound for the samples not inverted (an upper
/// bound, below the maximum). Otherwise (rational curves, different domains) every sample gets
/// Newton from the same parameter and those that could hold the maximum (at least half the
/// largest) also the global closest point. GeometryError for samplesPerSpan outside
/// 1..maxSamplesPerSpan.
CurveDeviation measureDeviation(const Curve& original, const Curve& reduced, int samplesPerSpan = 16);

/// A monotone correspondence between the parameters of two curves: the point of the first at
/// from[k] lies near the point of the second at to[k]; both ascending (foot points of a fit).
struct ParameterMap {
    std::vector<double> from;
    std::vector<double> to;
};

/// measureDeviation for two polynomial curves on one domain whose parameters may slip against
/// each other (a fit with free knots and corrected parameters), helped by a map from the
/// original's parameters to the reduced curve's (interpolated linearly): a sample's bound is the
/// distance to the mapped point of the other curve and Newton starts there, so far fewer samples
/// need inverting. The maxima are still those of inverting every sample (the map only changes
/// the bounds and seeds); the mean is an upper bound, as above. The reduced curve is sampled at
/// reducedSamplesPerSpan per span (0: samplesPerSpan), so that a fit with few spans can be
/// sampled densely at little cost. Throws GeometryError for rational curves, different domains,
/// a map that is empty, of two sizes, or not finite and ascending, or a count of samples per span
/// outside 1..maxSamplesPerSpan (reducedSamplesPerSpan: 0..maxSamplesPerSpan).
CurveDeviation measureDeviation(const Curve& original, const Curve& reduced, int samplesPerSpan,
                                const ParameterMap& map, int reducedSamplesPerSpan = 0);

namespace detail {
struct MeterFromSamples;

/// A measurement that only has to prove a bound (CurveDeviationMeter::within): samples whose
/// upper bound is within `floor` keep it uninverted, only the peaks at or past the floor are
/// followed between samples, and the measurement stops at the first distance past `ceiling`.
/// Its maximum says whether the ceiling holds; the rest of what it returns is not a report.
struct MeasureProof {
    double floor = 0.0;
    double ceiling = std::numeric_limits<double>::infinity();
};
}  // namespace detail

/// measureDeviation with a parameter map against one original, many times: the original's
/// samples and span boxes are made once (a search measures every candidate).
class CurveDeviationMeter {
public:
    /// Throws GeometryError for a rational curve or samplesPerSpan outside 1..maxSamplesPerSpan.
    CurveDeviationMeter(const Curve& original, int samplesPerSpan);
    /// The same as measureDeviation(original, reduced, samplesPerSpan, map, reducedSamplesPerSpan).
    CurveDeviation measure(const Curve& reduced, const ParameterMap& map,
                           int reducedSamplesPerSpan = 0) const;
    /// Whether the curves keep within `tolerance` on measure()'s samples, measuring only what that
    /// needs: a sample whose upper bound is within 0.9 of the tolerance is not inverted, the
    /// peaks between samples are followed from those at or past 0.9 of it (measure() follows
    /// those within a tenth of its largest), and the first distance past the tolerance ends it.
    /// False only for a distance past the tolerance to a real point. Throws GeometryError as
    /// measure() does, and for a tolerance that is not positive or is NaN.
    bool within(const Curve& reduced, const ParameterMap& map, double tolerance,
                int reducedSamplesPerSpan = 0) const;

    /// Per non-empty span of a curve: the box of its control points (the span lies in their
    /// convex hull) and the range [first, last) of the ascending samples in it, ends included.
    /// The boxes of every groupSize consecutive spans together (groupLow, groupHigh), so that a
    /// search can pass over a far group at once.
    struct SpanBoxes {
        std::vector<glm::dvec3> low, high;
        std::vector<std::size_t> first, last;
        static constexpr std::size_t groupSize = 16;
        std::vector<glm::dvec3> groupLow, groupHigh;
    };
    static SpanBoxes spanBoxes(const Curve& curve, const std::vector<double>& params);

private:
    friend struct detail::MeterFromSamples;
    /// The meter on what a caller inside geom made already (shared, not copied): the original's
    /// span power forms (private to geom), and where `points` is given, its samples (spanSamples
    /// at samplesPerSpan) and its points there, made from those forms.
    CurveDeviationMeter(const Curve& original, int samplesPerSpan,
                        std::shared_ptr<const std::vector<glm::dvec3>> forms,
                        std::shared_ptr<const std::vector<double>> params,
                        std::shared_ptr<const std::vector<glm::dvec3>> points);

    /// measure, or with a proof only a proof (see detail::MeasureProof).
    CurveDeviation checkedMeasure(const Curve& reduced, const ParameterMap& map, int reducedSamplesPerSpan,
                                  const detail::MeasureProof& proof) const;
    /// checkedMeasure with the map's two arrays read where they are.
    CurveDeviation measureAlong(const Curve& reduced, const std::vector<double>& from,
                                const std::vector<double>& to, int reducedSamplesPerSpan,
                                const detail::MeasureProof& proof) const;

    Curve original_;
    int samplesPerSpan_;
    std::shared_ptr<const std::vector<double>> params_;
    std::shared_ptr<const std::vector<glm::dvec3>> points_;
    // Every span's power form (private to geom).
    std::shared_ptr<const std::vector<glm::dvec3>> originalForms_;
    SpanBoxes boxes_;
};

/// The measured distance between two surfaces, with a per-vertex error field on a grid of the
/// reduced surface for a colour map.
struct SurfaceDeviation {
    double maxError = 0.0;              ///< the larger of the two maxima below
    double meanError = 0.0;             ///< mean of the error field
    double maxOriginalToReduced = 0.0;  ///< over the same grid on the original surface, and its peaks
    double maxReducedToOriginal = 0.0;  ///< max of the error field, or of a peak between its vertices
    std::vector<double> u;      ///< grid parameters in u (samplesPerSpan per span of the reduced surface)
    std::vector<double> v;      ///< grid parameters in v
    std::vector<double> error;  ///< error[i * v.size() + j]: distance from S'(u[i], v[j]) to the original
};

/// Samples the reduced surface on a grid (samplesPerSpan per non-empty span each way, both
/// one-sided limits at a jump: spanSamples) and measures every vertex's distance to the original
/// surface by point inversion (Newton from the same parameters; then SurfaceProjector's global
/// closest point for the largest values first, until no Newton value left exceeds the largest
/// result), then the maximum from the original's grid to the reduced surface: |S(u,v) - S'(u,v)|
/// bounds each vertex's distance, and the vertices are inverted largest bound first until no
/// bound left exceeds the largest distance found. Each direction's local maxima within a tenth of
/// its largest are then followed between the vertices by a compass search. Both surfaces must
/// share the parameter domain (as knot removal keeps it), and samplesPerSpan be from 1 to
/// maxSamplesPerSpan (else GeometryError).
SurfaceDeviation measureDeviation(const Surface& original, const Surface& reduced, int samplesPerSpan = 4);

/// samplesPerSpan parameters in each non-empty span of knots[degree..count], the domain end included,
/// and at a jump (an interior knot of multiplicity degree + 1) the double just below the knot too,
/// so that the end of the piece before it (its left-hand limit) is sampled as well as the start of
/// the piece after it (GeometryError unless knots.size() == count + degree + 1 and samplesPerSpan
/// is from 1 to maxSamplesPerSpan).
std::vector<double> spanSamples(const std::vector<double>& knots, int degree, std::size_t count,
                                int samplesPerSpan);

}  // namespace geom
