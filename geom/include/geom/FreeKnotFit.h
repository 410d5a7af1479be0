#pragma once

#include "geom/Curve.h"
#include "geom/Deviation.h"
#include "geom/KnotRemoval.h"

#include <cstddef>
#include <limits>
#include <map>
#include <span>
#include <vector>

namespace geom {

/// How a free-knot fit runs: sampling density, iterations and the end conditions it keeps.
struct FreeKnotOptions {
    /// A fit of n control points samples the original samplesPerFitSpan * n times, spread along
    /// it as the starting knots are (by the estimated |C^(p+1)|^(1/(p+1))), so that every span of
    /// the fit gets about that many.
    int samplesPerFitSpan = 10;
    /// Fit / correct / move rounds per fit (the best round is kept); a fit started from given
    /// knots (converged for another count) takes warmIterations.
    int iterations = 16;
    int warmIterations = 8;
    /// The end points always stay; fixedDerivatives = k also keeps the first and last k+1
    /// control points and k interior knots of the original, so derivatives up to k stay.
    EndConditions ends;
};

/// Where a free-knot fit may stop early, judged at its first round on the final knots by the
/// error expected after Lawson's rounds (0.8 of that round's, or the best round's if lower).
struct FreeKnotStops {
    /// Give up where the expected error is above this (FreeKnotFit::gaveUp).
    double giveUpAbove = std::numeric_limits<double>::infinity();
    /// Stop where it is below this: a smaller count would do (FreeKnotFit::overshot).
    double stopBelow = 0.0;
};

/// A free-knot fit of one control point count, with its sample error.
struct FreeKnotFit {
    Curve curve;
    /// The largest distance from a sample of the original to the fit at the sample's corrected
    /// parameter: a distance to a real point of the fit, so it bounds the original-to-fit
    /// distance at the samples from above (not the other way, not between samples).
    double sampleError = std::numeric_limits<double>::infinity();
    /// The samples' parameters on the original (from) and their corrected ones on the fit (to),
    /// for measureDeviation's parameter map.
    ParameterMap map;
    /// The fit stopped at its first round on the final knots, where the error expected after
    /// Lawson's rounds (expectedError, FreeKnotStops) was above the caller's giveUpAbove;
    /// sampleError is that of the rounds run.
    bool gaveUp = false;
    /// The same stop where that expected error was below the caller's stopBelow (a smaller
    /// count would do).
    bool overshot = false;
    double expectedError = std::numeric_limits<double>::infinity();
};

/// Least-squares approximation of a polynomial curve by a spline of the same degree with a given
/// number of control points and free interior knots, for the Hausdorff distance: each round fits
/// the coefficients to dense samples of the original by one banded least-squares solve, moves
/// every sample's parameter to its foot point on the fit (the distance lets the fit slip along
/// the curve), reweights the samples towards the best max-norm fit (Lawson) and moves the knots
/// so that every span carries about the same error (h_i scaled by e_i^(-1/(p+1))). The samples
/// are made once, so fits of several counts share them. The domain and the clamped end points
/// of the original stay.
class FreeKnotFitter {
public:
    /// Throws GeometryError for a rational or unclamped curve or bad options.
    FreeKnotFitter(const Curve& original, const FreeKnotOptions& options);

    /// The best fit with `count` control points found in the options' iterations, started from
    /// the interior knots of `startKnots` (a clamped knot vector on the original's domain, of
    /// any count, e.g. another fit's: its knot distribution is resampled to this count) when
    /// given, else from knots spread by the original's (p+1)-th derivative. With moveKnots false
    /// the knots stay where they start (every round corrects parameters and reweights), for
    /// start knots that are already right, e.g. the original's most significant ones.
    /// rounds > 0 replaces the options' number of rounds, samplesPerFitSpan > 0 the options'
    /// samples. A fit may stop early (stops). sampleError is infinite when the count cannot keep
    /// the end conditions.
    FreeKnotFit fit(std::size_t count, std::span<const double> startKnots = {}, bool moveKnots = true,
                    int rounds = 0, const FreeKnotStops& stops = {}, int samplesPerFitSpan = 0) const;

    const Curve& original() const { return original_; }

    /// The error model of an l-infinity fit with best knots, up to a constant:
    /// (integral of |C^(p+1)|^(1/(p+1)) / (count - p))^(p+1); the ratio of two counts' errors
    /// follows it, the constant depends on the fit (the caller calibrates it).
    double predictedError(std::size_t count) const;

private:
    std::vector<double> initialKnots(std::size_t count) const;

    // Samples of the original at one density: parameters, points, the parameter length each
    // stands for.
    struct Samples {
        std::vector<double> params;
        std::vector<glm::dvec3> points;
        std::vector<double> spacing;
    };
    const Samples& samplesFor(std::size_t count, int samplesPerFitSpan) const;
    static std::vector<double> spacingOf(const std::vector<double>& params);

    Curve original_;
    FreeKnotOptions options_;

    mutable std::map<std::size_t, Samples> samples_;  // by number, made when first needed
    std::vector<glm::dvec3> forms_;                   // the original's span power forms (private to geom)
    std::vector<double> density_;
    double densityIntegral_ = 0.0;  // per original span: |C^(p+1)|^(1/(p+1)), estimated
};

}  // namespace geom
