// Curve mapping benchmark: the five-curve ACSYNT-like logo mapped onto a 20x20-patch
// wave and a 20x20-patch wing at tolerance 1e-4 of the span, adaptive sampling against the ACSYNT
// curve-mapping thesis's fixed sampling (ten projected points per curve segment) and against fixed sampling
// made fine enough to reach the same maximum deviation. Prints figures, then one JSON object.

#include "geom/CurveFile.h"
#include "geom/Evaluate.h"
#include "geom/Intersect.h"
#include "geom/SurfaceIntersector.h"
#include "geom/curvemap/CurveMapper.h"
#include "geom/curvemap/SampleSurfaces.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace geom;
using namespace geom::curvemap;

namespace {

struct Hit {
    bool ok = false;
    glm::dvec2 uv{0.0};
    glm::dvec3 point{0.0};
};

Hit nearestHit(const SurfaceIntersector& intersector, const glm::dvec3& from, const glm::dvec3& z) {
    const auto hits = intersector.intersect(from, z);
    Hit h;
    for (const auto& x : hits)
        if (!h.ok || glm::length(x.point - from) < glm::length(h.point - from)) h = {true, x.uv, x.point};
    return h;
}

/// Deviation of a mapped polyline (uv + points, with curve parameters) from the true mapped
/// curve, measured at the middle parameter of every segment: from the 3D chord and from the
/// surface image of the (u, w) segment.
double deviation(const Surface& surface, const SurfaceIntersector& intersector, const PlacementFrame& frame,
                 const Curve& curve, const std::vector<double>& s, const std::vector<glm::dvec2>& uv,
                 const std::vector<glm::dvec3>& points) {
    double worst = 0.0;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        if (std::isnan(s[i]) || std::isnan(s[i + 1]) || s[i + 1] < s[i]) continue;
        const Hit t =
            nearestHit(intersector, frame.toModel(evaluate(curve, 0.5 * (s[i] + s[i + 1]))), frame.z);
        if (!t.ok) continue;
        const glm::dvec3 ab = points[i + 1] - points[i];
        const double lambda = std::clamp(glm::dot(t.point - points[i], ab) / glm::dot(ab, ab), 0.0, 1.0);
        worst = std::max(worst, glm::length(t.point - (points[i] + lambda * ab)));
        const glm::dvec2 d = uv[i + 1] - uv[i];
        const double mu = std::clamp(glm::dot(t.uv - uv[i], d) / glm::dot(d, d), 0.0, 1.0);
        const glm::dvec2 q = uv[i] + mu * d;
        worst = std::max(worst, glm::length(evaluate(surface, q.x, q.y) - t.point));
    }
    return worst;
}

struct Fixed {
    double seconds = 0.0;
    std::size_t projections = 0;
    double deviation = 0.0;
};

Fixed fixedSamplingOnce(const Surface& surface, const SurfaceIntersector& intersector,
                        const PlacementFrame& frame, const std::vector<Curve>& curves, int perSegment);

/// The ACSYNT curve-mapping thesis's method: a fixed number of projected points per curve segment (knot
/// span); the time is the best of three runs, like the adaptive one's best of five.
Fixed fixedSampling(const Surface& surface, const SurfaceIntersector& intersector,
                    const PlacementFrame& frame, const std::vector<Curve>& curves, int perSegment) {
    Fixed best = fixedSamplingOnce(surface, intersector, frame, curves, perSegment);
    for (int run = 0; run < 2; ++run)
        best.seconds = std::min(best.seconds,
                                fixedSamplingOnce(surface, intersector, frame, curves, perSegment).seconds);
    return best;
}

Fixed fixedSamplingOnce(const Surface& surface, const SurfaceIntersector& intersector,
                        const PlacementFrame& frame, const std::vector<Curve>& curves, int perSegment) {
    Fixed f;
    std::vector<std::vector<double>> params(curves.size());
    std::vector<std::vector<glm::dvec2>> uvs(curves.size());
    std::vector<std::vector<glm::dvec3>> points(curves.size());
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t c = 0; c < curves.size(); ++c) {
        const Curve& curve = curves[c];
        for (std::size_t i = 3; i < curve.points.size(); ++i) {
            const double a = curve.knots[i], b = curve.knots[i + 1];
            if (!(b > a)) continue;
            for (int k = 0; k < perSegment; ++k) {
                const double s = a + (b - a) * k / perSegment;
                const Hit h = nearestHit(intersector, frame.toModel(evaluate(curve, s)), frame.z);
                ++f.projections;
                if (!h.ok) continue;
                params[c].push_back(s);
                uvs[c].push_back(h.uv);
                points[c].push_back(h.point);
            }
        }
    }
    f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (std::size_t c = 0; c < curves.size(); ++c)
        f.deviation = std::max(
            f.deviation, deviation(surface, intersector, frame, curves[c], params[c], uvs[c], points[c]));
    return f;
}
/// One surface's figures, printed as lines and returned as JSON members with a prefix.
std::string benchmark(const char* name, const Surface& surface, const Placement& place, double tolerance,
                      const std::vector<Curve>& logo) {
    const CurveMapper mapper(surface);
    MapOptions options;
    options.tolerance = tolerance;

    // Adaptive: best of five runs.
    double best = 1e300;
    MapResult result;
    for (int run = 0; run < 5; ++run) {
        const auto start = std::chrono::steady_clock::now();
        result = mapper.map(logo, place, options);
        best =
            std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::size_t projections = 0, points = 0, loops = 0;
    double adaptiveDeviation = 0.0;
    const SurfaceIntersector intersector(surface);
    for (std::size_t p = 0; p < result.parts.size(); ++p) {
        projections += result.parts[p].projections;
        for (const MappedLoop& loop : result.parts[p].loops) {
            ++loops;
            points += loop.uv.size();
            adaptiveDeviation =
                std::max(adaptiveDeviation, deviation(surface, intersector, result.frame, logo[p],
                                                      loop.curveParameters, loop.uv, loop.points));
        }
    }
    std::printf(
        "%s: adaptive: %.2f ms, %zu loops, %zu projections, %zu loop points, max deviation %.3g "
        "(tolerance %.3g)\n",
        name, best * 1e3, loops, projections, points, adaptiveDeviation, tolerance);

    const Fixed seed = fixedSampling(surface, intersector, result.frame, logo, 10);
    std::printf("%s: seed fixed sampling, 10 per segment: %.2f ms, %zu projections, max deviation %.3g\n",
                name, seed.seconds * 1e3, seed.projections, seed.deviation);
    // The fewest points per segment (doubling, then bisection) whose deviation is no larger.
    int low = 10, perSegment = 10;
    Fixed equal = seed;
    while (equal.deviation > adaptiveDeviation && perSegment < 20000) {
        low = perSegment;
        perSegment *= 2;
        equal = fixedSampling(surface, intersector, result.frame, logo, perSegment);
    }
    while (perSegment - low > 1) {
        const int mid = (low + perSegment) / 2;
        const Fixed f = fixedSampling(surface, intersector, result.frame, logo, mid);
        if (f.deviation <= adaptiveDeviation) {
            perSegment = mid;
            equal = f;
        } else {
            low = mid;
        }
    }
    std::printf(
        "%s: fixed sampling at equal deviation: %d per segment, %.2f ms, %zu projections, max deviation "
        "%.3g\n",
        name, perSegment, equal.seconds * 1e3, equal.projections, equal.deviation);

    char json[1024];
    std::snprintf(
        json, sizeof json,
        "\"%s_tolerance_model_units\": %.6g, \"%s_adaptive_ms\": %.4f, \"%s_loops\": %zu, "
        "\"%s_adaptive_projections\": %zu, \"%s_adaptive_loop_points\": %zu, "
        "\"%s_adaptive_max_deviation\": %.6g, \"%s_seed10_ms\": %.4f, \"%s_seed10_projections\": %zu, "
        "\"%s_seed10_max_deviation\": %.6g, \"%s_fixed_equal_per_segment\": %d, "
        "\"%s_fixed_equal_ms\": %.4f, \"%s_fixed_equal_projections\": %zu, "
        "\"%s_fixed_equal_max_deviation\": %.6g",
        name, tolerance, name, best * 1e3, name, loops, name, projections, name, points, name,
        adaptiveDeviation, name, seed.seconds * 1e3, name, seed.projections, name, seed.deviation, name,
        perSegment, name, equal.seconds * 1e3, name, equal.projections, name, equal.deviation);
    return json;
}

}  // namespace

int main() {
    // The test data beside the sources (the benchmark takes no arguments).
    const std::filesystem::path data =
        std::filesystem::path(__FILE__).parent_path().parent_path() / "tests/data/curvemap/acslogo.crv";
    const std::vector<Curve> logo = interpolateModel(readCurveFile(data));

    // The thesis's tutorial: the logo in the middle of a wave (here 20 x 20 patches, span 10),
    // turned twice; and a wing (20 x 20 patches, span 20), on the upper surface at
    // mid-span, long axis along the span. Tolerance 1e-4 of the span in both.
    Placement onWave;
    onWave.reference = {10, 10};
    onWave.quarterTurns = 2;
    Placement onWing;
    onWing.reference = {15, 10};
    onWing.quarterTurns = 1;
    const std::string wave = benchmark("wave", makeWaveSurface(20, 20, 10.0, 0.6, 5.0), onWave, 1e-3, logo);
    const std::string wing = benchmark("wing", makeWingSurface(20, 20, 20.0, 8.0, 0.12), onWing, 2e-3, logo);
    std::printf("{\"surface_patches\": 400, %s, %s}\n", wave.c_str(), wing.c_str());
    return 0;
}
