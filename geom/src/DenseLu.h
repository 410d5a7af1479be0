#pragma once

// Private to geom: the one dense square solver behind global interpolation, constrained cubic
// interpolation and degree elevation (least squares lives in RemovalDetail.h).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace geom::detail {

/// LU factorization with partial pivoting of a small dense square matrix, reused for every
/// right-hand side of one problem.
class DenseLu {
public:
    /// Factors the row-major size x size matrix. A pivot not above relativeTolerance times the
    /// largest entry stops the factorization: singular() is then true and singularColumn() says where.
    DenseLu(std::vector<double> matrix, std::size_t size, double relativeTolerance)
        : a_(std::move(matrix)), n_(size), pivot_(size), singularColumn_(size) {
        double scale = 0.0;
        for (double x : a_) scale = std::max(scale, std::abs(x));
        for (std::size_t k = 0; k < n_; ++k) {
            std::size_t best = k;
            for (std::size_t r = k + 1; r < n_; ++r)
                if (std::abs(at(r, k)) > std::abs(at(best, k))) best = r;
            if (!(std::abs(at(best, k)) > relativeTolerance * scale)) {
                singularColumn_ = k;
                return;
            }
            pivot_[k] = best;
            if (best != k)
                for (std::size_t c = 0; c < n_; ++c) std::swap(at(k, c), at(best, c));
            for (std::size_t r = k + 1; r < n_; ++r) {
                const double f = at(r, k) / at(k, k);
                at(r, k) = f;
                if (f == 0.0) continue;
                for (std::size_t c = k + 1; c < n_; ++c) at(r, c) -= f * at(k, c);
            }
        }
    }

    bool singular() const { return singularColumn_ < n_; }
    std::size_t singularColumn() const { return singularColumn_; }

    /// The solution x of A x = b for a regular matrix; V is double or a GLM vector.
    template <class V>
    std::vector<V> solve(std::vector<V> b) const {
        // The stored multipliers went through every later row swap, so all swaps come first.
        for (std::size_t k = 0; k < n_; ++k) std::swap(b[k], b[pivot_[k]]);
        for (std::size_t k = 0; k < n_; ++k)
            for (std::size_t r = k + 1; r < n_; ++r)
                if (at(r, k) != 0.0) b[r] -= at(r, k) * b[k];
        for (std::size_t k = n_; k-- > 0;) {
            for (std::size_t c = k + 1; c < n_; ++c) b[k] -= at(k, c) * b[c];
            b[k] /= at(k, k);
        }
        return b;
    }

private:
    double& at(std::size_t r, std::size_t c) { return a_[r * n_ + c]; }
    double at(std::size_t r, std::size_t c) const { return a_[r * n_ + c]; }

    std::vector<double> a_;
    std::size_t n_;
    std::vector<std::size_t> pivot_;
    std::size_t singularColumn_;
};

}  // namespace geom::detail
