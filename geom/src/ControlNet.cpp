#include "geom/ControlNet.h"
#include "Checked.h"
#include "NumberText.h"

#include "geom/GeometryError.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {

ControlNet homogeneousNet(const Curve& curve) {
    if (!curve.weights.empty() && curve.weights.size() != curve.points.size())
        throw GeometryError("homogeneousNet: " + std::to_string(curve.weights.size()) + " weights for " +
                            std::to_string(curve.points.size()) + " control points");
    ControlNet net;
    net.stride = 1;
    net.data.reserve(curve.points.size());
    for (std::size_t i = 0; i < curve.points.size(); ++i) {
        const double w = curve.weight(i);
        net.data.emplace_back(curve.points[i] * w, w);
    }
    return net;
}

ControlNet homogeneousNet(const Surface& surface, bool alongV) {
    if (!detail::gridSizeIs(surface.points.size(), surface.countU, surface.countV) ||
        (!surface.weights.empty() && surface.weights.size() != surface.points.size()))
        throw GeometryError("homogeneousNet: " + std::to_string(surface.points.size()) + " points and " +
                            std::to_string(surface.weights.size()) + " weights for a " +
                            std::to_string(surface.countU) + " x " + std::to_string(surface.countV) + " net");
    ControlNet net;
    net.stride = alongV ? surface.countU : surface.countV;
    net.data.resize(surface.points.size());
    for (std::size_t i = 0; i < surface.countU; ++i)
        for (std::size_t j = 0; j < surface.countV; ++j) {
            const double w = surface.weight(i, j);
            const std::size_t at = alongV ? j * surface.countU + i : i * surface.countV + j;
            net.data[at] = glm::dvec4(surface.point(i, j) * w, w);
        }
    return net;
}

void setFromNet(Curve& curve, const ControlNet& net, bool rational) {
    curve.points.resize(net.data.size());
    curve.weights.clear();
    if (rational) curve.weights.resize(net.data.size());
    for (std::size_t i = 0; i < net.data.size(); ++i) {
        const glm::dvec4& h = net.data[i];
        curve.points[i] = glm::dvec3(h) / h.w;
        if (rational) curve.weights[i] = h.w;
    }
}

void setFromNet(Surface& surface, const ControlNet& net, bool alongV, bool rational) {
    const std::size_t blocks = net.blocks();
    surface.countU = alongV ? net.stride : blocks;
    surface.countV = alongV ? blocks : net.stride;
    surface.points.resize(net.data.size());
    surface.weights.clear();
    if (rational) surface.weights.resize(net.data.size());
    for (std::size_t i = 0; i < surface.countU; ++i)
        for (std::size_t j = 0; j < surface.countV; ++j) {
            const glm::dvec4& h =
                alongV ? net.data[j * surface.countU + i] : net.data[i * surface.countV + j];
            surface.points[i * surface.countV + j] = glm::dvec3(h) / h.w;
            if (rational) surface.weights[i * surface.countV + j] = h.w;
        }
}

namespace {

void checkParameter(const std::vector<double>& knots, int degree, std::size_t count, double u,
                    const char* where) {
    const double lo = knots[static_cast<std::size_t>(degree)];
    const double hi = knots[count];
    if (!std::isfinite(u) || u < lo || u > hi)
        throw GeometryError(std::string(where) + ": knot value " + detail::numberText(u) +
                            " lies outside the domain [" + detail::numberText(lo) + ", " +
                            detail::numberText(hi) + "]");
}

}  // namespace

void insertKnotInNet(int degree, std::vector<double>& knots, ControlNet& net, double u, int times,
                     const char* where) {
    const std::size_t count = net.blocks();
    checkParameter(knots, degree, count, u, where);
    if (times < 0)
        throw GeometryError(std::string(where) + ": cannot insert a knot " + std::to_string(times) +
                            " times");
    if (times == 0) return;
    const int s = static_cast<int>(std::count(knots.begin(), knots.end(), u));
    if (times > degree - s)  // not s + times > degree: that wraps for times near INT_MAX
        throw GeometryError(std::string(where) + ": inserting knot " + detail::numberText(u) + " " +
                            std::to_string(times) + " times would raise its multiplicity " +
                            std::to_string(s) + " above the degree " + std::to_string(degree));
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t r = static_cast<std::size_t>(times);
    const std::size_t ms = static_cast<std::size_t>(s);
    // k: the last knot index with knots[k] <= u, so knots equal to u sit at k-s+1..k.
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), u) - knots.begin()) - 1;
    const std::size_t stride = net.stride;

    std::vector<double> newKnots(knots.size() + r);
    for (std::size_t i = 0; i <= k; ++i) newKnots[i] = knots[i];
    for (std::size_t i = 1; i <= r; ++i) newKnots[k + i] = u;
    for (std::size_t i = k + 1; i < knots.size(); ++i) newKnots[i + r] = knots[i];

    ControlNet out;
    out.stride = stride;
    out.data.resize((count + r) * stride);
    auto copyBlock = [stride](glm::dvec4* dst, const glm::dvec4* src) { std::copy(src, src + stride, dst); };
    for (std::size_t i = 0; i <= k - p; ++i) copyBlock(out.block(i), net.block(i));
    for (std::size_t i = k - ms; i < count; ++i) copyBlock(out.block(i + r), net.block(i));

    std::vector<glm::dvec4> tmp((p - ms + 1) * stride);
    for (std::size_t i = 0; i <= p - ms; ++i) copyBlock(tmp.data() + i * stride, net.block(k - p + i));
    std::size_t last = 0;
    for (std::size_t j = 1; j <= r; ++j) {
        const std::size_t L = k - p + j;
        for (std::size_t i = 0; i <= p - j - ms; ++i) {
            const double alpha = (u - knots[L + i]) / (knots[i + k + 1] - knots[L + i]);
            glm::dvec4* a = tmp.data() + i * stride;
            const glm::dvec4* b = tmp.data() + (i + 1) * stride;
            for (std::size_t c = 0; c < stride; ++c) a[c] = alpha * b[c] + (1.0 - alpha) * a[c];
        }
        copyBlock(out.block(L), tmp.data());
        copyBlock(out.block(k + r - j - ms), tmp.data() + (p - j - ms) * stride);
        last = L;
    }
    for (std::size_t i = last + 1; i < k - ms; ++i) copyBlock(out.block(i), tmp.data() + (i - last) * stride);
    knots = std::move(newKnots);
    net = std::move(out);
}

void refineNet(int degree, std::vector<double>& knots, ControlNet& net, std::vector<double> inserted,
               const char* where) {
    if (inserted.empty()) return;
    const std::size_t count = net.blocks();
    for (double x : inserted) checkParameter(knots, degree, count, x, where);
    std::sort(inserted.begin(), inserted.end());
    for (std::size_t i = 0; i < inserted.size();) {
        std::size_t j = i;
        while (j < inserted.size() && inserted[j] == inserted[i]) ++j;
        const std::size_t total =
            static_cast<std::size_t>(std::count(knots.begin(), knots.end(), inserted[i])) + (j - i);
        if (total > static_cast<std::size_t>(degree))
            throw GeometryError(std::string(where) + ": refinement would raise the multiplicity of knot " +
                                detail::numberText(inserted[i]) + " to " + std::to_string(total) +
                                ", above the degree " + std::to_string(degree));
        i = j;
    }

    // The NURBS Book A5.4, with n = count - 1 and m = knots.size() - 1.
    const long p = degree;
    const long n = static_cast<long>(count) - 1;
    const long m = static_cast<long>(knots.size()) - 1;
    const long r = static_cast<long>(inserted.size()) - 1;
    const std::size_t stride = net.stride;
    auto span = [&](double x) -> long {
        // The book's FindSpan: u == knots[n+1] belongs to span n.
        if (x >= knots[static_cast<std::size_t>(n + 1)]) return n;
        return static_cast<long>(std::upper_bound(knots.begin() + p, knots.begin() + n + 1, x) -
                                 knots.begin()) -
               1;
    };
    const long a = span(inserted.front());
    const long b = span(inserted.back()) + 1;
    auto U = [&](long i) { return knots[static_cast<std::size_t>(i)]; };

    std::vector<double> Ubar(knots.size() + inserted.size());
    ControlNet Q;
    Q.stride = stride;
    Q.data.resize((count + inserted.size()) * stride);
    auto copyBlock = [stride](glm::dvec4* dst, const glm::dvec4* src) { std::copy(src, src + stride, dst); };
    auto Qb = [&](long i) { return Q.block(static_cast<std::size_t>(i)); };
    auto Pb = [&](long i) { return net.block(static_cast<std::size_t>(i)); };

    for (long j = 0; j <= a - p; ++j) copyBlock(Qb(j), Pb(j));
    for (long j = b - 1; j <= n; ++j) copyBlock(Qb(j + r + 1), Pb(j));
    for (long j = 0; j <= a; ++j) Ubar[static_cast<std::size_t>(j)] = U(j);
    for (long j = b + p; j <= m; ++j) Ubar[static_cast<std::size_t>(j + r + 1)] = U(j);

    long i = b + p - 1;
    long k = b + p + r;
    for (long j = r; j >= 0; --j) {
        const double x = inserted[static_cast<std::size_t>(j)];
        while (x <= U(i) && i > a) {
            copyBlock(Qb(k - p - 1), Pb(i - p - 1));
            Ubar[static_cast<std::size_t>(k)] = U(i);
            --k;
            --i;
        }
        copyBlock(Qb(k - p - 1), Qb(k - p));
        for (long l = 1; l <= p; ++l) {
            const long ind = k - p + l;
            double alpha = Ubar[static_cast<std::size_t>(k + l)] - x;
            glm::dvec4* dst = Qb(ind - 1);
            const glm::dvec4* src = Qb(ind);
            if (std::abs(alpha) == 0.0) {
                copyBlock(dst, src);
            } else {
                alpha /= Ubar[static_cast<std::size_t>(k + l)] - U(i - p + l);
                for (std::size_t c = 0; c < stride; ++c) dst[c] = alpha * dst[c] + (1.0 - alpha) * src[c];
            }
        }
        Ubar[static_cast<std::size_t>(k)] = x;
        --k;
    }
    knots = std::move(Ubar);
    net = std::move(Q);
}

}  // namespace geom
