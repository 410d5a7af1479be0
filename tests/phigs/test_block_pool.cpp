// BlockPool against a plain record of what it should hold: random runs of values added and
// clears; every run keeps its values at the address it was copied to until a clear, a run never
// straddles two blocks, and a cleared pool refills its blocks without allocating. With and
// without inline room.

#include "phigs/traverse/BlockPool.h"

#include <catch2/catch.hpp>

#include <cstddef>
#include <random>
#include <utility>
#include <vector>

namespace test_block_pool {

using namespace phigs;

namespace {

/// The random runs and clears on a BlockPool<int, InlineCount>.
template <std::size_t InlineCount>
void checkBlockPool() {
    for (unsigned seed = 1; seed <= 40; ++seed) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        BlockPool<int, InlineCount> pool;
        REQUIRE(pool.capacity() == InlineCount);
        std::vector<std::pair<const int*, std::vector<int>>> held;  // each run's address and values
        std::size_t capacityBefore = pool.capacity();
        std::size_t added = 0;
        for (int step = pick(1, 30); step > 0; --step) {
            if (pick(0, 5) == 0) {
                capacityBefore = pool.capacity();
                pool.clear();
                held.clear();
                added = 0;
                REQUIRE(pool.capacity() == capacityBefore);
            }
            if (pick(0, 7) == 0) pool.reserve(static_cast<std::size_t>(pick(0, 20)));
            for (int n = pick(0, 12); n > 0; --n) {
                std::vector<int> run(static_cast<std::size_t>(pick(0, 9)));
                for (int& v : run) v = pick(-1000, 1000);
                const int* at = pool.add(run.data(), run.size());
                REQUIRE((at == nullptr) == run.empty());
                added += run.size();
                held.emplace_back(at, std::move(run));
            }
            INFO("seed " << seed << " step " << step);
            REQUIRE(pool.capacity() >= added);
            if (added <= capacityBefore && added <= InlineCount) REQUIRE(pool.capacity() == capacityBefore);
            for (const auto& [at, values] : held)
                for (std::size_t i = 0; i < values.size(); ++i) REQUIRE(at[i] == values[i]);
        }
    }
}

}  // namespace

TEST_CASE("BlockPool keeps its runs in place until cleared", "[traverse][block-pool]") {
    checkBlockPool<0>();
}

TEST_CASE("BlockPool with inline room keeps its runs in place until cleared", "[traverse][block-pool]") {
    checkBlockPool<1>();
    checkBlockPool<4>();
}

}  // namespace test_block_pool
