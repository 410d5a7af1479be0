#include "phigs/hardcopy/UnionOutline.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace phigs::hardcopy {
namespace {

/// A directed edge between two point numbers, as one key.
std::uint64_t directedEdgeKey(std::uint32_t from, std::uint32_t to) {
    return std::uint64_t(from) << 32 | to;
}

}  // namespace

std::vector<std::vector<glm::dvec2>> unionOutline(
    const std::vector<const std::vector<glm::dvec2>*>& contours) {
    // Number the distinct points (exact equality: shared mesh vertices project to the same bits).
    std::vector<glm::dvec2> points;
    for (const auto* c : contours) points.insert(points.end(), c->begin(), c->end());
    auto less = [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    std::sort(points.begin(), points.end(), less);
    points.erase(std::unique(points.begin(), points.end()), points.end());
    auto number = [&](glm::dvec2 p) {
        return std::uint32_t(std::lower_bound(points.begin(), points.end(), p, less) - points.begin());
    };
    // Each edge adds one to its direction, unless the opposite direction has one to cancel.
    std::unordered_map<std::uint64_t, std::uint32_t> count;
    std::size_t edges = 0;
    for (const auto* c : contours) edges += c->size();
    count.reserve(edges);
    std::vector<std::uint32_t> numbers;
    for (const auto* c : contours) {
        numbers.clear();
        for (glm::dvec2 p : *c) numbers.push_back(number(p));
        for (std::size_t i = 0; i < numbers.size(); ++i) {
            const std::uint32_t a = numbers[i], b = numbers[(i + 1) % numbers.size()];
            if (a == b) continue;
            if (auto it = count.find(directedEdgeKey(b, a)); it != count.end() && it->second > 0)
                --it->second;
            else
                ++count[directedEdgeKey(a, b)];
        }
    }
    // What is left balances at every point (each contour enters a point as often as it leaves
    // it, and a cancelled pair takes one of each), so following edges out of each point closes.
    std::vector<std::uint32_t> first(points.size() + 1, 0);
    std::vector<std::uint64_t> left;
    for (const auto& [key, n] : count)
        for (std::uint32_t k = 0; k < n; ++k) left.push_back(key);
    std::sort(left.begin(), left.end());  // by start point, so each point's edges are a range
    for (std::uint64_t key : left) ++first[(key >> 32) + 1];
    for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
    std::vector<std::uint32_t> taken(points.size(), 0);  // edges used from each point's range
    std::vector<std::vector<glm::dvec2>> loops;
    for (std::size_t start = 0; start < points.size(); ++start) {
        while (first[start] + taken[start] < first[start + 1]) {
            std::vector<glm::dvec2> loop;
            std::uint32_t at = std::uint32_t(start);
            do {
                loop.push_back(points[at]);
                if (first[at] + taken[at] >= first[at + 1]) break;  // unreachable on balanced edges
                const std::uint64_t key = left[first[at] + taken[at]++];
                at = std::uint32_t(key & 0xffffffffu);
            } while (at != start);  // a walk on balanced edges can stop only where it began
            loops.push_back(std::move(loop));
        }
    }
    return loops;
}

}  // namespace phigs::hardcopy
