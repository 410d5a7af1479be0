// Molt's blade case: C. Molt, Implementation Aspects of Bézier Surfaces to Model Complex
// Geometric Forms (M.S. thesis, University of Southern California, 1994), Fig. 4.3: the third
// impeller blade, front and back each one Bézier patch of 100 x 11 control points (bidegree
// 99 x 10), subdivided to a constant depth of 3: 2 x 4^3 leaves x 1,100 points = 140,800 points,
// 132 s of CPU on a SPARCstation 10. The control meshes are not published, so the nets are
// generated: a twisted, cambered blade of that size, its back side offset by a thickness.
// geom::subdivideAdaptive (fixed depth) against, in the same run, the general quadtree
// recursion (a tolerance no net meets, capped at depth 3) and the thesis's own program
// structure (Appendix A.2: one buffer of 9 M doubles allocated per node, every column split
// along u, then both halves along v). Prints the figures and ends with one JSON object.

#include "BenchClock.h"
#include "geom/BezierSubdivision.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

namespace {

using bench::cpuSeconds;
using bench::wallSeconds;

constexpr std::size_t rows = 100, columns = 11;  // u: along the blade (slow), v: across it
constexpr int depth = 3;

/// One side of a blade: span along u from hub to tip, chord across v, twisted by 40 degrees
/// over the span and cambered; the back side sits `thickness` off the mean surface.
std::vector<glm::dvec3> bladeSide(double thickness) {
    std::vector<glm::dvec3> net;
    for (std::size_t i = 0; i < rows; ++i) {
        const double s = static_cast<double>(i) / (rows - 1);  // span
        const double twist = 0.7 * s, chord = 1.5 - 0.5 * s;
        for (std::size_t j = 0; j < columns; ++j) {
            const double c = static_cast<double>(j) / (columns - 1) - 0.5;  // chord position
            const double camber =
                0.15 * chord * (0.25 - c * c) + thickness * std::sin(std::numbers::pi * (c + 0.5));
            const double x = chord * c, y = camber;
            net.emplace_back(x * std::cos(twist) - y * std::sin(twist),
                             x * std::sin(twist) + y * std::cos(twist), 5.0 * s + 0.05 * std::sin(9.0 * s));
        }
    }
    return net;
}

/// The thesis's program, as its appendix lays it out: [x | y | z] blocks of M doubles, each a
/// run of columns (one curve of `m` points along u), recursion with a calloc'd 9 M buffer.
struct ThesisProgram {
    int m = static_cast<int>(rows), n = static_cast<int>(columns), M = m * n;
    int rec = -1;
    std::vector<double> out;

    /// Midpoint split of `count` values at stride `stride`: left half in place, right into `r`.
    static void split(double* q, double* r, int count, int stride) {
        double line[128] = {};
        for (int k = 0; k < count; ++k) line[k] = q[k * stride];
        r[(count - 1) * stride] = line[count - 1];
        for (int k = 1; k < count; ++k) {
            for (int i = 0; i + k < count; ++i) line[i] = 0.5 * (line[i] + line[i + 1]);
            q[k * stride] = line[0];
            r[(count - 1 - k) * stride] = line[count - 1 - k];
        }
    }
    /// surfsplit for one coordinate block: every column along u (contiguous), then both halves
    /// along v (stride m): Q [0,1/2]^2 in place, R [1/2,1]x[0,1/2], S [0,1/2]x[1/2,1], T the rest.
    void surfsplit(double* q, double* r, double* s, double* t) const {
        for (int col = 0; col < n; ++col) split(q + col * m, r + col * m, m, 1);
        for (int row = 0; row < m; ++row) {
            split(q + row, s + row, n, m);
            split(r + row, t + row, n, m);
        }
    }
    void surfgen(double* p) {
        ++rec;
        if (rec >= depth) {
            out.insert(out.end(), p, p + 3 * M);
        } else {
            double* q = static_cast<double*>(std::calloc(static_cast<std::size_t>(9 * M), sizeof(double)));
            for (int c = 0; c < 3; ++c) surfsplit(p + c * M, q + c * M, q + 3 * M + c * M, q + 6 * M + c * M);
            surfgen(p);
            surfgen(q);
            surfgen(q + 3 * M);
            surfgen(q + 6 * M);
            std::free(q);
        }
        --rec;
    }
    std::size_t run(const std::vector<glm::dvec3>& net) {
        std::vector<double> p(static_cast<std::size_t>(3 * M));
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < n; ++j)
                for (int c = 0; c < 3; ++c)
                    p[static_cast<std::size_t>(c * M + j * m + i)] = net[i * columns + j][c];
        out.clear();
        surfgen(p.data());
        return out.size() / 3;
    }
};

template <typename F>
double medianMs(F&& f, int runs) {
    std::vector<double> ms;
    for (int r = 0; r < runs; ++r) {
        const double c0 = cpuSeconds();
        f();
        ms.push_back(1e3 * (cpuSeconds() - c0));
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
    const double cpu0 = cpuSeconds(), wall0 = wallSeconds();
    const std::vector<glm::dvec3> sides[2] = {bladeSide(0.0), bladeSide(0.04)};
    const geom::SubdivisionOptions fixed{geom::StoppingRule::FixedDepth, 0.0, depth};
    const geom::SubdivisionOptions recursion{geom::StoppingRule::LocalFlatness, 1e-300, depth};

    std::size_t points = 0, recursivePoints = 0, thesisPoints = 0;
    double difference = 0.0;
    for (const auto& net : sides) {
        geom::SubdivisionStats stats;
        const auto a = geom::subdivideAdaptive(net, rows, columns, fixed, &stats);
        const auto b = geom::subdivideAdaptive(net, rows, columns, recursion);
        points += stats.points;
        for (const auto& leaf : b) recursivePoints += leaf.net.size();
        for (std::size_t l = 0; l < a.size(); ++l)
            for (std::size_t k = 0; k < a[l].net.size(); ++k)
                difference = std::max(difference, glm::length(a[l].net[k] - b[l].net[k]));
        ThesisProgram program;
        thesisPoints += program.run(net);
    }
    const double bladeMs = medianMs(
        [&] {
            for (const auto& net : sides) (void)geom::subdivideAdaptive(net, rows, columns, fixed);
        },
        runs);
    const double recursiveMs = medianMs(
        [&] {
            for (const auto& net : sides) (void)geom::subdivideAdaptive(net, rows, columns, recursion);
        },
        runs);
    const double thesisMs = medianMs(
        [&] {
            for (const auto& net : sides) ThesisProgram().run(net);
        },
        runs);
    std::printf(
        "blade 2 x %zu x %zu nets (bidegree %zu x %zu), depth %d: %zu points (recursion %zu, thesis "
        "program %zu); largest difference to the recursion %.3g\n",
        rows, columns, rows - 1, columns - 1, depth, points, recursivePoints, thesisPoints, difference);
    std::printf(
        "CPU median of %d runs: fixed depth %.2f ms, quadtree recursion %.2f ms, thesis program %.2f ms "
        "(the thesis: 132 s on a SPARCstation 10)\n",
        runs, bladeMs, recursiveMs, thesisMs);
    std::printf(
        "{\"blade_points\": %zu, \"blade_ms\": %.3f, \"recursion_ms\": %.3f, \"thesis_program_ms\": %.3f, "
        "\"recursion_over_blade\": %.2f, \"thesis_program_over_blade\": %.2f, "
        "\"largest_difference\": %.3g, \"thesis_seconds\": 132, \"runs\": %d, \"cpu_seconds\": %.2f, "
        "\"wall_seconds\": %.2f}\n",
        points, bladeMs, recursiveMs, thesisMs, recursiveMs / bladeMs, thesisMs / bladeMs, difference, runs,
        cpuSeconds() - cpu0, wallSeconds() - wall0);
    return points == 140800 && recursivePoints == points && thesisPoints == points && difference < 1e-12 ? 0
                                                                                                         : 1;
}
