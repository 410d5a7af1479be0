#pragma once

#include "geom/Curve.h"
#include "geom/Deviation.h"
#include "geom/KnotRemoval.h"

#include <cstddef>
#include <functional>
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
    /// Fit / correct / move rounds per fit (the best round is kept): the first half moves the
    /// knots, the second runs Lawson's reweighting on them. A fit started from given knots
    /// (converged for another count) takes warmIterations.
    int iterations = 16;
    int warmIterations = 8;
    /// The knot-moving rounds end early where one moves the free knots by less than settledMove
    /// of their nearer neighbour's distance on average (the knots have settled), Lawson's where
    /// one lowers the sample error by less than lawsonSettled (relative); 0 runs all of either.
    double settledMove = 0.01;
    double lawsonSettled = 0.005;
    /// Where the knot density gives a fit at least pinShare knots in a span of the original, the
    /// fit keeps the original's knots there (pinned), and the other knots move between them.
    /// The original is exact on its own knots; moved knots at about that density land between
    /// them, and the fit needs more of them for the same error (the airfoil's leading edge). 0
    /// lets every knot move.
    double pinShare = 1.0;
    /// The end points always stay; fixedDerivatives = k also keeps the first and last k+1
    /// control points and k interior knots of the original, so derivatives up to k stay.
    EndConditions ends;
};

/// Where a free-knot fit may stop early: giveUpAbove and stopBelow are judged at its first round
/// on the final knots by the error expected after Lawson's rounds (0.8 of that round's, or the
/// best round's if lower), passAt at every round.
struct FreeKnotStops {
    /// Give up where the expected error is above this (FreeKnotFit::gaveUp).
    double giveUpAbove = std::numeric_limits<double>::infinity();
    /// Stop where it is below this: a smaller count would do (FreeKnotFit::overshot).
    double stopBelow = 0.0;
    /// Stop at the first round (of either kind) whose sample error is at most this: any fit that
    /// good will do (the caller's next count down has failed).
    double passAt = 0.0;
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
    /// Interior knots kept at the original's (FreeKnotOptions::pinShare).
    std::size_t pinnedKnots = 0;
    /// Rounds run: fewer than asked where the knots or Lawson's rounds settled or a stop came.
    int rounds = 0;
};

/// Least-squares approximation of a polynomial curve by a spline of the same degree with a given
/// number of control points and free interior knots, for the Hausdorff distance: each round fits
/// the coefficients to dense samples of the original by one banded least-squares solve, moves
/// every sample's parameter to its foot point on the fit (the distance lets the fit slip along
/// the curve), reweights the samples towards the best max-norm fit (Lawson) and moves the knots
/// so that every span carries about the same error (h_i scaled by e_i^(-1/(p+1))), except where
/// the density reaches a knot per span of the original: there the original's knots stay
/// (FreeKnotOptions::pinShare). The samples are made once, so fits of several counts share
/// them. The domain and the clamped end points of the original stay.
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

    /// The original's span power forms (span * (degree + 1) on, in the local parameter of each
    /// non-empty span; empty above degree 7), made when first needed.
    const std::vector<glm::dvec3>& originalForms() const;
    /// Takes the original's power forms from source when first needed instead of making them (a
    /// caller that needs them too makes them once); source must outlive the fitter.
    void shareForms(std::function<const std::vector<glm::dvec3>&()> source) {
        formsSource_ = std::move(source);
    }

private:
    // A fit's starting knots, and by free knot (interior, not held by the end conditions) whether
    // it stays at the original's (none where pin is false).
    struct KnotLayout {
        std::vector<double> knots;
        std::vector<char> pinned;
    };
    KnotLayout initialKnots(std::size_t count, std::span<const double> startKnots, bool pin) const;
    // The length of an original span inside [from, to]; the density's integral over [from, to];
    // count parameters at equal steps of that integral inside it (appended to out), as the
    // starting knots and the samples are spread.
    double clippedLength(std::size_t span, double from, double to) const;
    double densityIntegral(double from, double to) const;
    void densitySteps(double from, double to, std::size_t count, std::vector<double>& out) const;

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
    mutable std::vector<glm::dvec3> forms_;  // the original's span power forms, made when first needed
    std::function<const std::vector<glm::dvec3>&()> formsSource_;  // where they are shared, their maker
    std::vector<double> density_;
    std::vector<double> corners_;   // interior knots of multiplicity >= p where C' jumps
    double densityIntegral_ = 0.0;  // per original span: |C^(p+1)|^(1/(p+1)), estimated
};

}  // namespace geom
