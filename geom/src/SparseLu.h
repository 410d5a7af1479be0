#pragma once

// Private to geom: the square solver of global interpolation, whose collocation matrices are
// banded (open) or banded with wrapped corners (periodic): Gaussian elimination with partial
// pivoting on sparse rows, O(n p^2) time and O(n p) room where a dense LU takes O(n^2) room.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace geom::detail {

/// LU factorization with partial pivoting of a sparse square matrix given by rows, reused for
/// every right-hand side of one problem.
class SparseLu {
public:
    /// One row: (column, value) pairs in increasing column order, no zero values needed.
    using Row = std::vector<std::pair<std::size_t, double>>;

    /// Factors the size x size matrix. A pivot not above relativeTolerance times the largest entry
    /// stops the factorization: singular() is then true and singularColumn() says where.
    SparseLu(std::vector<Row> rows, double relativeTolerance)
        : n_(rows.size()), pivotRow_(rows.size()), upper_(rows.size()), singularColumn_(rows.size()) {
        double scale = 0.0;
        for (const Row& row : rows)
            for (const auto& entry : row) scale = std::max(scale, std::abs(entry.second));
        // Rows wait in the bucket of their first column; eliminating column k moves each row of
        // bucket k but the pivot to the bucket of its new first column.
        std::vector<std::vector<std::size_t>> buckets(n_);
        for (std::size_t r = 0; r < n_; ++r)
            if (!rows[r].empty()) buckets[rows[r].front().first].push_back(r);
        Row merged;
        for (std::size_t k = 0; k < n_; ++k) {
            std::vector<std::size_t>& candidates = buckets[k];
            std::size_t best = n_;
            for (std::size_t r : candidates)
                if (best == n_ || std::abs(rows[r].front().second) > std::abs(rows[best].front().second))
                    best = r;
            if (best == n_ || !(std::abs(rows[best].front().second) > relativeTolerance * scale)) {
                singularColumn_ = k;
                return;
            }
            const Row& pivot = rows[best];
            for (std::size_t r : candidates) {
                if (r == best) continue;
                const double f = rows[r].front().second / pivot.front().second;
                eliminations_.push_back({best, r, f});
                subtract(rows[r], pivot, f, merged);
                std::swap(rows[r], merged);
                if (!rows[r].empty()) buckets[rows[r].front().first].push_back(r);
            }
            candidates = {};
            pivotRow_[k] = best;
            upper_[k] = std::move(rows[best]);
        }
    }

    /// Adds `value` at `column` of a row being built (columns in any order, repeats summed).
    static void add(Row& row, std::size_t column, double value) {
        auto at = std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.first == column; });
        if (at != row.end())
            at->second += value;
        else
            row.emplace_back(column, value);
    }

    /// Puts a row built by add() in column order without its zeros.
    static void finish(Row& row) {
        std::sort(row.begin(), row.end());
        std::erase_if(row, [](const auto& e) { return e.second == 0.0; });
    }

    bool singular() const { return singularColumn_ < n_; }
    std::size_t singularColumn() const { return singularColumn_; }

    /// The solution x of A x = b for a regular matrix; V is double or a GLM vector.
    template <class V>
    std::vector<V> solve(std::vector<V> b) const {
        for (const Elimination& e : eliminations_) b[e.row] -= e.factor * b[e.pivot];
        std::vector<V> x(n_);
        for (std::size_t k = n_; k-- > 0;) {
            const Row& row = upper_[k];
            V sum = b[pivotRow_[k]];
            for (std::size_t i = 1; i < row.size(); ++i) sum -= row[i].second * x[row[i].first];
            x[k] = sum / row.front().second;
        }
        return x;
    }

private:
    struct Elimination {
        std::size_t pivot, row;
        double factor;
    };

    /// out = row - f * pivot over the columns after the first (which cancels), zeros left out.
    static void subtract(const Row& row, const Row& pivot, double f, Row& out) {
        out.clear();
        std::size_t i = 1, j = 1;
        while (i < row.size() || j < pivot.size()) {
            std::pair<std::size_t, double> next;
            if (j == pivot.size() || (i < row.size() && row[i].first < pivot[j].first)) {
                next = row[i++];
            } else if (i == row.size() || pivot[j].first < row[i].first) {
                next = {pivot[j].first, -f * pivot[j].second};
                ++j;
            } else {
                next = {row[i].first, row[i].second - f * pivot[j].second};
                ++i, ++j;
            }
            if (next.second != 0.0) out.push_back(next);
        }
    }

    std::size_t n_;
    std::vector<std::size_t> pivotRow_;  ///< the row that became U's row k
    std::vector<Row> upper_;             ///< U by rows, its diagonal first
    std::vector<Elimination> eliminations_;
    std::size_t singularColumn_;
};

}  // namespace geom::detail
