// Knot removal benchmark: the reference curves of Marcaly (1991) reduced at three tolerances by
// geom::reduceCurve and, in the same run, by SISL's s1940 (ends fixed); the reference surfaces
// by geom::reduceSurface; the thesis's count-driven cases. Every error printed is measured
// afterwards by geom::measureDeviation (dense samples of both shapes, point inversion). geom is
// timed with the report off, as SISL makes no measurement: its final check then runs only where
// no coefficient bound proves the result.

#include "geom/DataReduction.h"
#include "geom/Deviation.h"
#include "geom/Evaluate.h"
#include "geom/GlobalInterpolation.h"
#include "geom/KnotInsertion.h"
#include "geom/ReferenceShapes.h"

#include <sisl.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// Best of a few runs, in milliseconds; the runs stop once a second has gone.
double timeMs(const std::function<void()>& run, int maxRuns = 5) {
    double best = 1e300;
    const auto start = Clock::now();
    for (int i = 0; i < maxRuns; ++i) {
        const auto t0 = Clock::now();
        run();
        best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        if (std::chrono::duration<double>(Clock::now() - start).count() > 1.0) break;
    }
    return best;
}

// Best of `runs` runs each of two programs, in milliseconds, run by turns: a change of load
// during the measurement then falls on both alike, not on whichever ran in that stretch.
std::pair<double, double> timePairMs(const std::function<void()>& first, const std::function<void()>& second,
                                     int runs = 9) {
    double best[2] = {1e300, 1e300};
    for (int i = 0; i < runs; ++i)
        for (int which = 0; which < 2; ++which) {
            const auto t0 = Clock::now();
            (which == 0 ? first : second)();
            best[which] =
                std::min(best[which], std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        }
    return {best[0], best[1]};
}

geom::Curve sislReduce(const geom::Curve& c, double tol, int& status) {
    std::vector<double> coef;
    for (const auto& p : c.points) coef.insert(coef.end(), {p.x, p.y, p.z});
    std::vector<double> knots = c.knots;
    SISLCurve* in =
        newCurve(static_cast<int>(c.points.size()), c.degree + 1, knots.data(), coef.data(), 1, 3, 1);
    double eps[3] = {tol, tol, tol}, maxerr[3] = {0, 0, 0};
    SISLCurve* out = nullptr;
    status = 0;
    s1940(in, eps, 1, 1, 1, 7, &out, maxerr, &status);
    geom::Curve result;
    if (out != nullptr && status >= 0) {
        const int n = out->in, k = out->ik;
        std::vector<double> kn(out->et, out->et + n + k);
        std::vector<glm::dvec3> pts(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i)
            pts[static_cast<std::size_t>(i)] = {out->ecoef[3 * i], out->ecoef[3 * i + 1],
                                                out->ecoef[3 * i + 2]};
        result = geom::Curve(k - 1, kn, pts);
    }
    if (out) freeCurve(out);
    freeCurve(in);
    return result;
}

// ---- Generated classes of curves (every class the reduction must handle, not only the two
// reference curves).

struct CurveCase {
    std::string name;
    geom::Curve curve;
    double tolerance;
};

std::vector<double> clampedUniformKnots(int degree, std::size_t count) {
    std::vector<double> knots(static_cast<std::size_t>(degree) + 1, 0.0);
    const std::size_t interior = count - static_cast<std::size_t>(degree) - 1;
    for (std::size_t i = 1; i <= interior; ++i) knots.push_back(double(i) / double(interior + 1));
    knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, 1.0);
    return knots;
}

/// A random smooth curve of `count` poles on a clamped uniform knot vector (a wandering path).
geom::Curve randomCurve(std::mt19937& rng, int degree, std::size_t count, double step) {
    std::normal_distribution<double> n(0.0, step);
    std::vector<glm::dvec3> points{glm::dvec3(0.0)};
    glm::dvec3 v(step, 0, 0);
    while (points.size() < count) {
        v = 0.7 * v + glm::dvec3(n(rng), n(rng), 0.3 * n(rng));
        points.push_back(points.back() + v);
    }
    return geom::Curve(degree, clampedUniformKnots(degree, count), std::move(points));
}

/// `base` with `extra` random knots inserted and every pole jittered by up to `noise`.
geom::Curve refinedAndJittered(std::mt19937& rng, const geom::Curve& base, std::size_t extra, double noise) {
    std::uniform_real_distribution<double> unit(0.01, 0.99), jitter(-noise, noise);
    std::vector<double> inserted;
    for (std::size_t i = 0; i < extra; ++i) inserted.push_back(unit(rng));
    geom::Curve c = geom::refineKnots(base, inserted);
    for (glm::dvec3& p : c.points) p += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
    return c;
}

std::vector<CurveCase> generatedCases(unsigned seed = 2026) {
    std::mt19937 rng(seed);
    std::vector<CurveCase> cases;
    for (int p = 1; p <= 7; ++p)
        cases.push_back({"degree" + std::to_string(p),
                         refinedAndJittered(rng, randomCurve(rng, p, std::size_t(p + 8), 1.0), 80, 1e-5),
                         1e-3});
    {
        // C0 corners: a cubic with three triple interior knots, refined.
        geom::Curve base = randomCurve(rng, 3, 16, 1.0);
        base.knots = {0, 0, 0, 0, 0.25, 0.25, 0.25, 0.5, 0.5, 0.5, 0.75, 0.75, 0.75, 1, 1, 1, 1};
        base.points.resize(13);
        cases.push_back({"c0_corners", refinedAndJittered(rng, base, 80, 1e-5), 1e-3});
    }
    {
        // Digitised data: 400 points on a smooth path with 1e-4 noise, interpolated by a cubic.
        const geom::Curve path = randomCurve(rng, 3, 12, 1.0);
        std::uniform_real_distribution<double> jitter(-1e-4, 1e-4);
        std::vector<glm::dvec3> data;
        for (int i = 0; i < 400; ++i)
            data.push_back(geom::evaluate(path, i / 399.0) +
                           glm::dvec3(jitter(rng), jitter(rng), jitter(rng)));
        cases.push_back({"noisy_digitised", geom::interpolateCurve(data, 3, geom::Closure::Open), 1e-3});
    }
    // Nothing to remove: random poles far apart against the tolerance.
    cases.push_back({"incompressible", randomCurve(rng, 3, 200, 1.0), 1e-4});
    // Long: 2,500 poles.
    cases.push_back({"long_2500", refinedAndJittered(rng, randomCurve(rng, 3, 100, 1.0), 2400, 1e-6), 1e-3});
    return cases;
}

/// The rational class: a cubic with weights spanning 1e-1..1e1, refined and jittered (geom only:
/// s1940 takes the homogeneous coefficients and returns NaN poles).
CurveCase rationalCase() {
    std::mt19937 rng(7);
    geom::Curve base = randomCurve(rng, 3, 12, 1.0);
    std::uniform_real_distribution<double> exponent(-1.0, 1.0);
    for (std::size_t i = 0; i < base.points.size(); ++i)
        base.weights.push_back(std::pow(10.0, exponent(rng)));
    return {"rational", refinedAndJittered(rng, base, 80, 1e-5), 1e-3};
}

/// A lower bound on the control points of any degree-1 curve within Hausdorff distance `eps` of
/// the degree-1 curve `c` with the same end points (both reductions keep them): the number of
/// disjoint balls B(v, rho) around corners v of c that must each hold a vertex of such a curve,
/// plus its two end points. A corner v with legs along unit rays a, b (c within delta of them
/// inside radius rho + eps, nothing else of c there) certifies at rho when
/// (rho - eta) |a + b| / 2 > eps + eta, eta = eps + delta: a segment of the approximation that
/// passes within eps of v and crosses the ball has, along the bisector m = (a + b) / |a + b|, the
/// affine height m . (x - v) at most eps there but more than it at both crossings of the sphere,
/// each within eta of a leg at distance rho - eta or more from v; so a vertex lies inside.
std::size_t polylineVertexLowerBound(const geom::Curve& c, double eps) {
    const std::vector<glm::dvec3>& v = c.points;
    const std::size_t n = v.size();
    if (c.degree != 1 || n < 3) return std::min<std::size_t>(n, 2);
    auto segmentDistance = [](const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b) {
        const glm::dvec3 d = b - a;
        const double dd = glm::dot(d, d);
        const double t = dd > 0.0 ? std::clamp(glm::dot(q - a, d) / dd, 0.0, 1.0) : 0.0;
        return glm::length(q - (a + t * d));
    };
    auto rayDistance = [](const glm::dvec3& q, const glm::dvec3& o, const glm::dvec3& u) {
        const double t = std::max(0.0, glm::dot(q - o, u));
        return glm::length(q - (o + t * u));
    };
    // The leg from corner i towards step (-1 or +1) leaving the ball of radius r: its unit ray,
    // the largest distance of the chain inside from it, and the last vertex inside; none where
    // the chain ends inside.
    struct Leg {
        glm::dvec3 ray;
        double delta;
        std::size_t last;
    };
    auto leg = [&](std::size_t i, int step, double r) -> std::optional<Leg> {
        std::size_t k = i;
        for (;;) {
            if ((step < 0 && k == 0) || (step > 0 && k + 1 == n)) return std::nullopt;
            const std::size_t next = step < 0 ? k - 1 : k + 1;
            if (glm::length(v[next] - v[i]) >= r) break;
            k = next;
        }
        const glm::dvec3 a = v[k] - v[i], d = v[step < 0 ? k - 1 : k + 1] - v[k];
        // |a + s d| = r for s in [0, 1]: the exit from the ball.
        const double qa = glm::dot(d, d), qb = 2.0 * glm::dot(a, d), qc = glm::dot(a, a) - r * r;
        const double s = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
        const glm::dvec3 ray = glm::normalize(a + s * d);
        double delta = 0.0;
        for (std::size_t j = std::min(i, k); j <= std::max(i, k); ++j)
            delta = std::max(delta, rayDistance(v[j], v[i], ray));
        return Leg{ray, delta, k};
    };
    auto certifies = [&](std::size_t i, double rho) {
        const double r = rho + eps;
        if (glm::length(v.front() - v[i]) < rho || glm::length(v.back() - v[i]) < rho) return false;
        const auto back = leg(i, -1, r), ahead = leg(i, 1, r);
        if (!back || !ahead) return false;
        // Nothing of the curve but the two legs within r of the corner.
        for (std::size_t j = 0; j + 1 < n; ++j)
            if ((j + 1 < back->last || j > ahead->last) && !(segmentDistance(v[i], v[j], v[j + 1]) > r))
                return false;
        const double eta = eps + std::max(back->delta, ahead->delta);
        return rho > eta && (rho - eta) * glm::length(back->ray + ahead->ray) / 2.0 > eps + eta;
    };
    struct Ball {
        std::size_t corner;
        double rho;
    };
    std::vector<Ball> balls;
    for (std::size_t i = 1; i + 1 < n; ++i)
        for (double rho = 4.0 * eps; rho < 1e6 * eps; rho *= 1.25)
            if (certifies(i, rho)) {
                balls.push_back({i, rho});
                break;
            }
    // The smallest balls first, each kept where it is disjoint from those kept.
    std::sort(balls.begin(), balls.end(), [](const Ball& x, const Ball& y) { return x.rho < y.rho; });
    std::vector<Ball> kept;
    for (const Ball& b : balls)
        if (std::all_of(kept.begin(), kept.end(), [&](const Ball& k) {
                return glm::length(v[b.corner] - v[k.corner]) >= b.rho + k.rho;
            }))
            kept.push_back(b);
    return kept.size() + 2;
}

std::string json;
void figure(const std::string& name, double value) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s\"%s\": %.6g", json.empty() ? "" : ", ", name.c_str(), value);
    json += buf;
}

/// One generated member reduced by geom (report off, as SISL: no measurement beyond what the
/// guarantee needs) and by SISL, by turns, best of `runs`; geom's error measured after the timing.
struct MemberRun {
    geom::CurveReduction geom;
    geom::Curve sisl;  // no points where s1940 failed
    double geomMs = 0, sislMs = 0, errorOverTolerance = 0;

    double timeRatio() const { return geomMs / sislMs; }
    /// geom's control points over SISL's where SISL removed anything, else 0.
    double cpRatio(const geom::Curve& original) const {
        const bool removed = !sisl.points.empty() && sisl.points.size() < original.points.size();
        return removed ? double(geom.curve.points.size()) / double(sisl.points.size()) : 0.0;
    }
};

MemberRun runMember(const CurveCase& c, int runs) {
    geom::ReductionOptions o;
    o.tolerance = c.tolerance;
    o.report = false;
    MemberRun m;
    int status = 0;
    std::tie(m.geomMs, m.sislMs) =
        timePairMs([&] { m.geom = geom::reduceCurve(c.curve, o); },
                   [&] { m.sisl = sislReduce(c.curve, c.tolerance, status); }, runs);
    m.errorOverTolerance = geom::measureDeviation(c.curve, m.geom.curve).maxError / c.tolerance;
    return m;
}

void runMembers(const std::string& only);

/// Reduces every generated class (or the one named `only`) with geom and SISL by turns; prints
/// the table and adds the worst geom/SISL time and control point ratios to the JSON.
void runClasses(const std::string& only = {}) {
    std::printf("\nGenerated classes: control points left, measured error / tolerance, best of 9 runs\n");
    std::printf("%-16s %6s %8s | %6s %7s %9s | %6s %7s %9s | %6s %6s\n", "class", "poles", "tol", "geom",
                "err/tol", "ms", "sisl", "err/tol", "ms", "time", "cps");
    double worstTime = 0, worstCps = 0, worstError = 0, worstCpsOpen = 0;
    for (const CurveCase& c : generatedCases()) {
        if (!only.empty() && c.name != only) continue;
        const MemberRun m = runMember(c, 9);
        const geom::CurveReduction& r = m.geom;
        const geom::Curve& s = m.sisl;
        const double ms = m.geomMs, sms = m.sislMs, gerr = m.errorOverTolerance;
        const double serr =
            s.points.empty() ? -1.0 : geom::measureDeviation(c.curve, s).maxError / c.tolerance;
        const double timeRatio = m.timeRatio(), cpRatio = m.cpRatio(c.curve);
        std::printf("%-16s %6zu %8.1e | %6zu %7.3f %9.3f | %6zu %7.3f %9.3f | %6.2f %6.2f\n", c.name.c_str(),
                    c.curve.points.size(), c.tolerance, r.curve.points.size(), gerr, ms, s.points.size(),
                    serr, sms, timeRatio, cpRatio);
        worstTime = std::max(worstTime, timeRatio);
        worstCps = std::max(worstCps, cpRatio);
        worstError = std::max(worstError, gerr);
        // Where a lower bound proves SISL's count minimal, no curve keeps fewer points.
        const std::size_t bound = c.curve.degree == 1 ? polylineVertexLowerBound(c.curve, c.tolerance) : 0;
        if (bound > 0) {
            std::printf(
                "%-16s any curve of degree 1 within the tolerance keeps at least %zu control points\n", "",
                bound);
            figure(c.name + "_control_points_lower_bound", double(bound));
        }
        if (bound < s.points.size()) worstCpsOpen = std::max(worstCpsOpen, cpRatio);
        figure(c.name + "_geom_control_points", double(r.curve.points.size()));
        figure(c.name + "_sisl_control_points", double(s.points.size()));
        figure(c.name + "_geom_ms", ms);
        figure(c.name + "_sisl_ms", sms);
        figure(c.name + "_geom_error_over_tolerance", gerr);
    }
    if (only.empty() || only == "rational") {
        const CurveCase rational = rationalCase();
        const geom::Curve& c = rational.curve;
        geom::ReductionOptions o;
        o.tolerance = rational.tolerance;
        geom::CurveReduction r;
        const double ms = timeMs([&] { r = geom::reduceCurve(c, o); }, 3);
        const double gerr = geom::measureDeviation(c, r.curve).maxError / o.tolerance;
        std::printf("%-16s %6zu %8.1e | %6zu %7.3f %9.3f | %6s %7s %9s |\n", "rational", c.points.size(),
                    o.tolerance, r.curve.points.size(), gerr, ms, "-", "-", "-");
        worstError = std::max(worstError, gerr);
        figure("rational_geom_control_points", double(r.curve.points.size()));
        figure("rational_geom_ms", ms);
        figure("rational_geom_error_over_tolerance", gerr);
    }
    figure("worst_time_ratio_vs_sisl", worstTime);
    figure("worst_cp_ratio_vs_sisl", worstCps);
    figure("worst_cp_ratio_vs_sisl_not_proven_minimal", worstCpsOpen);
    figure("worst_error_over_tolerance", worstError);
    runMembers(only);
}

/// The worst of kMembers other members of each generated class (seeds 1 to kMembers, as --seeds
/// makes them): one member per class can flatter or wrong a class.
void runMembers(const std::string& only) {
    constexpr unsigned kMembers = 8;
    struct Worst {
        double time = 0, cps = 0, error = 0;
    };
    std::vector<std::pair<std::string, Worst>> worst;
    for (unsigned seed = 1; seed <= kMembers; ++seed)
        for (const CurveCase& c : generatedCases(seed)) {
            if (!only.empty() && c.name != only) continue;
            const MemberRun m = runMember(c, 5);
            auto at =
                std::find_if(worst.begin(), worst.end(), [&](const auto& w) { return w.first == c.name; });
            if (at == worst.end()) at = worst.insert(worst.end(), {c.name, Worst{}});
            Worst& w = at->second;
            w.time = std::max(w.time, m.timeRatio());
            w.cps = std::max(w.cps, m.cpRatio(c.curve));
            w.error = std::max(w.error, m.errorOverTolerance);
        }
    std::printf("\nThe same classes, worst of %u other members (best of 5 runs each)\n", kMembers);
    std::printf("%-16s | %6s %6s %7s\n", "class", "time", "cps", "err/tol");
    Worst all;
    for (const auto& [name, w] : worst) {
        std::printf("%-16s | %6.2f %6.2f %7.3f\n", name.c_str(), w.time, w.cps, w.error);
        figure(name + "_members_worst_time_ratio", w.time);
        figure(name + "_members_worst_cp_ratio", w.cps);
        all.time = std::max(all.time, w.time);
        all.cps = std::max(all.cps, w.cps);
        all.error = std::max(all.error, w.error);
    }
    figure("members_worst_time_ratio_vs_sisl", all.time);
    figure("members_worst_cp_ratio_vs_sisl", all.cps);
    figure("members_worst_error_over_tolerance", all.error);
}

}  // namespace

int main(int argc, char** argv) {
    const bool curvesOnly = argc > 1 && std::string(argv[1]) == "--curves";
    const bool classesOnly = argc > 1 && std::string(argv[1]) == "--classes";
    const auto wallStart = Clock::now();
    const std::clock_t cpuStart = std::clock();
    auto finish = [&] {
        figure("wall_seconds", std::chrono::duration<double>(Clock::now() - wallStart).count());
        figure("cpu_seconds", static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC);
        std::printf("{%s}\n", json.c_str());
        return 0;
    };
    // --profile CLASS N [SEED]: geom's reduction of one generated class (or "rational", or "ibeam" /
    // "airfoil" at 1e-4) N times, nothing else (for a profiler); prints the control points left and a digest
    // of the result's bits (a change meant to leave results alone must leave it alone). SEED picks the
    // member as --seeds does (the table's by default), so the worst member of a class can be profiled.
    if (argc > 3 && std::string(argv[1]) == "--profile") {
        std::vector<CurveCase> cases =
            argc > 4 ? generatedCases(static_cast<unsigned>(std::stoul(argv[4]))) : generatedCases();
        cases.push_back(rationalCase());
        cases.push_back({"ibeam", geom::iBeamCurve(), 1e-4});
        cases.push_back({"airfoil", geom::nacaAirfoilCurve(), 1e-4});
        bool found = false;
        for (const CurveCase& c : cases) {
            if (c.name != argv[2]) continue;
            found = true;
            geom::ReductionOptions o;
            o.tolerance = c.tolerance;
            o.report = false;
            geom::CurveReduction r;
            for (int i = 0, runs = std::stoi(argv[3]); i < runs; ++i) r = geom::reduceCurve(c.curve, o);
            std::uint64_t digest =
                1469598103934665603ull;  // FNV-1a over the knots', points' and weights' bytes
            auto add = [&](const void* data, std::size_t size) {
                for (std::size_t i = 0; i < size; ++i)
                    digest = (digest ^ static_cast<const unsigned char*>(data)[i]) * 1099511628211ull;
            };
            add(r.curve.knots.data(), r.curve.knots.size() * sizeof(double));
            add(r.curve.points.data(), r.curve.points.size() * sizeof(glm::dvec3));
            add(r.curve.weights.data(), r.curve.weights.size() * sizeof(double));
            std::printf("%s: %zu control points (%s, %zu fits), digest %016llx\n", c.name.c_str(),
                        r.curve.points.size(), r.freeKnotFit ? "free-knot fit" : "removal loop", r.fits,
                        static_cast<unsigned long long>(digest));
        }
        if (!found) {
            std::fprintf(stderr, "bench_knot_removal --profile: no class named '%s'\n", argv[2]);
            return 1;
        }
        return 0;
    }
    // --seeds CLASS N: the class generated from N other seeds, geom and SISL on each (control
    // points and time), for a change judged on the whole class rather than one member.
    if (argc > 3 && std::string(argv[1]) == "--seeds") {
        double worstTime = 0, worstCps = 0, worstError = 0;
        for (unsigned seed = 1, seeds = static_cast<unsigned>(std::stoi(argv[3])); seed <= seeds; ++seed)
            for (const CurveCase& c : generatedCases(seed)) {
                if (c.name != argv[2]) continue;
                const MemberRun m = runMember(c, 5);
                const geom::CurveReduction& r = m.geom;
                const geom::Curve& s = m.sisl;
                const double ms = m.geomMs, sms = m.sislMs, gerr = m.errorOverTolerance;
                const double cps =
                    double(r.curve.points.size()) / double(std::max<std::size_t>(s.points.size(), 1));
                std::printf(
                    "%s seed %u: geom %zu (err/tol %.3f, %.3f ms), sisl %zu (%.3f ms): time %.2f cps %.2f\n",
                    c.name.c_str(), seed, r.curve.points.size(), gerr, ms, s.points.size(), sms, ms / sms,
                    cps);
                if (c.curve.degree == 1)
                    std::printf("%s seed %u: at least %zu control points (lower bound)\n", c.name.c_str(),
                                seed, polylineVertexLowerBound(c.curve, c.tolerance));
                worstTime = std::max(worstTime, ms / sms);
                worstCps = std::max(worstCps, cps);
                worstError = std::max(worstError, gerr);
            }
        std::printf("worst time %.2f, worst cps %.2f, worst err/tol %.3f\n", worstTime, worstCps, worstError);
        return 0;
    }
    if (classesOnly) {
        runClasses(argc > 2 ? argv[2] : "");
        return finish();
    }
    struct Named {
        const char* name;
        geom::Curve curve;
    };
    const std::vector<Named> curves{{"ibeam", geom::iBeamCurve()}, {"airfoil", geom::nacaAirfoilCurve()}};
    std::printf(
        "Curves: control points left, measured Hausdorff error, time (best of 9 runs, geom and SISL by "
        "turns)\n");
    std::printf("%-8s %8s | %6s %10s %9s | %6s %10s %9s | %6s | %6s %10s %9s\n", "curve", "tol", "geom",
                "error", "ms", "sisl", "error", "ms", "ratio", "loop", "error", "ms");
    for (const Named& c : curves)
        for (double tol : {1e-2, 1.2e-3, 1e-3, 1e-4}) {
            geom::ReductionOptions o;
            o.tolerance = tol;
            o.report = false;
            geom::CurveReduction r;
            // geom and SISL by turns, as many runs each, the best of each.
            int status = 0;
            geom::Curve s;
            const auto [ms, sms] = timePairMs([&] { r = geom::reduceCurve(c.curve, o); },
                                              [&] { s = sislReduce(c.curve, tol, status); });
            const double serr = s.points.empty() ? -1.0 : geom::measureDeviation(c.curve, s).maxError;
            // geom's own report is its final check; this is the same independent measurement as
            // SISL's.
            const double gerr = geom::measureDeviation(c.curve, r.curve).maxError;
            const double ratio =
                s.points.empty() ? 0.0 : double(r.curve.points.size()) / double(s.points.size());
            // The removal loop alone (ReductionOptions::freeKnots = false) on the same input.
            geom::ReductionOptions ob = o;
            ob.freeKnots = false;
            ob.report = true;
            geom::CurveReduction b;
            const double bms = timeMs([&] { b = geom::reduceCurve(c.curve, ob); }, 3);
            std::printf("%-8s %8.1e | %6zu %10.3e %9.3f | %6zu %10.3e %9.3f | %6.2f | %6zu %10.3e %9.3f\n",
                        c.name, tol, r.curve.points.size(), gerr, ms, s.points.size(), serr, sms, ratio,
                        b.curve.points.size(), b.deviation.maxError, bms);
            char key[64];
            std::snprintf(key, sizeof key, "%s_tol%.1e", c.name, tol);
            const std::string k = key;
            figure(k + "_geom_control_points", double(r.curve.points.size()));
            figure(k + "_geom_max_error", gerr);
            figure(k + "_geom_reported_max_error", r.deviation.maxError);
            figure(k + "_geom_ms", ms);
            figure(k + "_sisl_control_points", double(s.points.size()));
            figure(k + "_sisl_max_error", serr);
            figure(k + "_sisl_ms", sms);
            figure(k + "_geom_loop_control_points", double(b.curve.points.size()));
            figure(k + "_geom_loop_max_error", b.deviation.maxError);
            figure(k + "_geom_loop_ms", bms);
        }

    runClasses();
    if (curvesOnly) return finish();
    std::printf("\nThesis count-driven cases (tolerance off, partitions of 5)\n");
    {
        geom::ReductionOptions o;
        o.maxRemovals = 50;
        const auto r = geom::reduceCurve(geom::nacaAirfoilCurve(), o);
        std::printf("airfoil 100 -> %zu control points: max error %.3e, mean %.3e (thesis ~1.2e-3)\n",
                    r.curve.points.size(), r.deviation.maxError, r.deviation.meanError);
        figure("airfoil_remove50_max_error", r.deviation.maxError);
        for (std::size_t n : {80u, 160u}) {
            o.maxRemovals = n;
            const auto b = geom::reduceCurve(geom::iBeamCurve(), o);
            std::printf("ibeam 401 -> %zu control points: max error %.3e, mean %.3e\n", b.curve.points.size(),
                        b.deviation.maxError, b.deviation.meanError);
            figure("ibeam_remove" + std::to_string(n) + "_max_error", b.deviation.maxError);
        }
    }

    std::printf("\nSurfaces: control points left per direction, measured error, time\n");
    struct NamedSurface {
        const char* name;
        geom::Surface surface;
    };
    const std::vector<NamedSurface> surfaces{{"paraboloid", geom::paraboloidSurface()},
                                             {"wing", geom::wingSurface()}};
    for (const NamedSurface& s : surfaces)
        for (double tol : {1e-2, 1e-3}) {
            geom::ReductionOptions o;
            o.tolerance = tol;
            geom::SurfaceReduction r;
            const double ms =
                timeMs([&] { r = geom::reduceSurface(s.surface, geom::ReductionDirection::Both, o); }, 1);
            std::printf("%-10s %8.1e  %zux%zu -> %zux%zu  max error %.3e  mean %.3e  %.1f ms\n", s.name, tol,
                        s.surface.countU, s.surface.countV, r.surface.countU, r.surface.countV,
                        r.deviation.maxError, r.deviation.meanError, ms);
            char key[64];
            std::snprintf(key, sizeof key, "%s_tol%.0e", s.name, tol);
            const std::string k = key;
            figure(k + "_control_points_u", double(r.surface.countU));
            figure(k + "_control_points_v", double(r.surface.countV));
            figure(k + "_max_error", r.deviation.maxError);
            figure(k + "_ms", ms);
        }
    return finish();
}
