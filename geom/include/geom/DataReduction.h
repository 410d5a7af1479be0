#pragma once

#include "geom/Curve.h"
#include "geom/Deviation.h"
#include "geom/KnotRemoval.h"
#include "geom/Surface.h"

#include <cstddef>
#include <limits>

namespace geom {

/// How a data reduction runs: by tolerance, by count, or both (whichever stops first).
struct ReductionOptions {
    /// Largest allowed distance between the original and the reduced shape, measured; infinity
    /// gives the thesis's count-driven mode, where nothing is measured during the loop.
    double tolerance = std::numeric_limits<double>::infinity();
    /// Stop after this many knots (per direction for surfaces).
    std::size_t maxRemovals = std::numeric_limits<std::size_t>::max();
    /// Knots taken from the ranking before the weights are computed again (the thesis used 5).
    int partitionSize = 5;
    /// Extra free coefficients on each side of the least-squares window (each removal is refitted
    /// to the original on that window, so a wider one spreads the error).
    int margin = 4;
    /// In tolerance mode, knots whose weight exceeds weightCutoff * tolerance are not tried
    /// (they would fail), and where every knot left after the exact removals is past it, the
    /// free-knot search is not run either (a curve with nothing to remove returns at once); 0
    /// tries every knot.
    double weightCutoff = 8.0;
    /// Curves in tolerance mode: after the knots that go exactly, search the control point count
    /// with free-knot fits (FreeKnotFit.h: the knots move, the samples slip along the curve,
    /// Lawson reweighting towards the best max-norm fit), each measured by CurveDeviationMeter;
    /// usually fewer control points than the removal loop. Where the curve's most significant
    /// knots already fit at the first count, the removal loop alone decides; where they fit
    /// nearly as well as moved knots, or no count passes, it runs too and the fewer points win.
    /// false runs the removal loop alone. Surfaces and count mode always take the removal loop.
    bool freeKnots = true;
    /// Fit / correct / move rounds of a free-knot fit from a cold start (the search's later fits,
    /// started from the last one's knots, take half).
    int freeKnotIterations = 16;
    /// The removal loop in tolerance mode (freeKnots false, or where it runs too): remove knots
    /// in batches with one global banded least-squares refit per batch (fewer fits, usually
    /// more control points left); false (the default) runs the group-at-a-time loop with local
    /// refits. Either way the result is within the tolerance.
    bool batch = false;
    /// Batch mode only: rounds of removal; between rounds, lawsonSteps reweighted refits even the
    /// error out (towards the best max-norm fit) and the knots that failed are tried again.
    int rounds = 4;
    int lawsonSteps = 3;
    EndConditions ends;
    /// A closed curve, or a surface closed in a direction, keeps the continuity of its seam: where
    /// the ends meet with derivatives 1 .. k agreeing (k < degree; k = 1 also for tangents that
    /// only share a direction), both ends keep those derivatives (ends.fixedDerivatives raised to
    /// k), so a periodic shape stays smooth across the seam. false treats the seam as two ends.
    bool keepSeams = true;
    /// Measurement density: samples per knot span of the original shape (each direction), from 1
    /// to maxSamplesPerSpan (Deviation.h). A curve's final check takes at least 4, whatever the
    /// loop runs at; the final measurements at multiples of it take at most maxSamplesPerSpan.
    int samplesPerSpan = 8;
    /// Fill the result's deviation report (a global measurement after the loop). In tolerance
    /// mode the measurement is also the final check. With report false a curve's deviation is
    /// left empty (samples 0), and its final check runs only where no coefficient bound proves
    /// the result (coefficients that, refined onto the original's knots, stay within the
    /// tolerance of the original's: the linear stage's states) and only proves the tolerance
    /// (as CurveDeviationMeter::within), which costs less than measuring the deviation.
    bool report = true;
};

/// A reduced curve with its bookkeeping and its measured error report.
struct CurveReduction {
    Curve curve;
    std::size_t removed = 0;      ///< knots removed
    std::size_t fits = 0;         ///< least-squares fits tried (accepted or not)
    std::size_t steppedBack = 0;  ///< accepted states the final measurement undid (usually 0)
    /// True when the curve is a free-knot fit (its knots moved; the report samples it at four
    /// times samplesPerSpan per span), false when it keeps a subset of the original's knots.
    bool freeKnotFit = false;
    CurveDeviation deviation;  ///< measureDeviation(original, curve) where measured (see report)
};

/// Data reduction of a curve. An unclamped curve (a closed, periodic one too) is reduced as its
/// clamped form (the same curve), so its end points stay and a closed curve stays closed; the
/// original stands where that keeps as many points. A closed curve's seam keeps its continuity
/// (ReductionOptions::keepSeams), once the knots that go exactly have gone. In tolerance mode with
/// options.freeKnots (the default) and clamped ends: the knots that go exactly, then a search over the
/// control point count with free-knot fits, each kept only if measureDeviation's parameter-map form finds the
/// Hausdorff distance within the tolerance (see ReductionOptions::freeKnots for when the removal loop runs
/// too). Otherwise the removal loop, rank / remove / approximate (Lyche and Morken, as Marcaly's
/// thesis of 1991 runs it, its errata fixed): rank the interior knots by removal weight, take the
/// partitionSize least significant, group the ones that share a local window, remove each group
/// with one local least-squares fit, and keep a removal only if the distance from the original
/// stays within the tolerance, measured on dense samples of both curves by point inversion in
/// the changed interval. A group that fails is retried knot by knot; a knot that fails is not
/// tried again until a global refit to the original succeeds. A denser final measurement
/// (measureDeviation) checks the result; should it find the tolerance broken, the result steps
/// back to the last accepted state that keeps it (of the last 16; else to the original). A rational curve is
/// reduced in homogeneous space by the removal loop (freeKnots and batch do not apply): the sequences w P and
/// w share the knots, and a removal is kept only if a bound on the Euclidean distance holds (the reduced
/// spline refined onto the original knots: |C - C'| <= max_j |dX_j - P_i dw_j| / min w' over the coefficients
/// that reach each parameter), with every weight kept positive; the final measurement checks it. Throws
/// GeometryError for bad options.
CurveReduction reduceCurve(const Curve& curve, const ReductionOptions& options);

/// Which knot vectors of a surface to reduce; Both reduces u, then v.
enum class ReductionDirection { U, V, Both };

/// A reduced surface with its bookkeeping and its measured error report (with the error field).
struct SurfaceReduction {
    Surface surface;
    std::size_t removedU = 0;
    std::size_t removedV = 0;
    std::size_t fits = 0;
    SurfaceDeviation deviation;  ///< measureDeviation(original, surface) when options.report
};

/// Data reduction of a surface by whole knot rows (a rational one in homogeneous form, w P and
/// w, every weight kept positive and the grid measured on the Euclidean surface): a row's weight
/// is the largest weight over the isoparametric curves of the control net (not the thesis's
/// mean), every isoparametric curve gets its own least-squares fit on the same window, and a
/// removal is kept only if |S(u,v) - S'(u,v)| stays within the tolerance on a dense parameter
/// grid of the original in the changed strip (this bounds the distance between the surfaces
/// from above). The final measurement (measureDeviation) checks the result; should it find the
/// tolerance broken, the reduction runs again with less of the tolerance for the grid. A
/// direction closed round a seam keeps its continuity there (ReductionOptions::keepSeams). Throws
/// GeometryError for bad options.
SurfaceReduction reduceSurface(const Surface& surface, ReductionDirection direction,
                               const ReductionOptions& options);

}  // namespace geom
