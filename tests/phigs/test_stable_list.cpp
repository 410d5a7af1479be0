// StableList against a plain record of what it should hold: random appends and clears; every
// value stays at the address it was built at until a clear, each value is destroyed exactly
// once, an empty list holds no storage (none but its inline room, with one) and a cleared one
// refills its blocks without allocating.

#include "phigs/traverse/StableList.h"

#include <catch2/catch.hpp>

#include <memory>
#include <random>
#include <string>
#include <vector>

namespace test_stable_list {

using namespace phigs;

namespace {

/// A value that counts the live instances (and owns a heap string, so a leak or a double
/// destruction shows under the sanitizers too).
struct Counted {
    explicit Counted(int v, int* live)
        : value(v), text(std::to_string(v) + " and some longer text"), live(live) {
        ++*live;
    }
    Counted(Counted&& other) noexcept : value(other.value), text(std::move(other.text)), live(other.live) {
        ++*live;
    }
    Counted(const Counted&) = delete;
    ~Counted() { --*live; }
    int value;
    std::string text;
    int* live;
};

/// The random appends and clears on a StableList<Counted, InlineCount>.
template <std::size_t InlineCount>
void checkStableList() {
    for (unsigned seed = 1; seed <= 40; ++seed) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        int live = 0;
        {
            StableList<Counted, InlineCount> list;
            REQUIRE(list.capacity() == InlineCount);           // empty: no storage but its own
            std::vector<std::pair<const Counted*, int>> held;  // each value's address and number
            std::size_t capacityBefore = list.capacity();
            for (int step = pick(1, 30); step > 0; --step) {
                if (pick(0, 5) == 0) {
                    capacityBefore = list.capacity();
                    list.clear();
                    held.clear();
                    REQUIRE(live == 0);
                    REQUIRE(list.capacity() == capacityBefore);
                }
                for (int n = pick(0, 40); n > 0; --n) {
                    const int value = pick(-1000, 1000);
                    const Counted& c = pick(0, 1) ? list.emplace_back(value, &live)
                                                  : list.emplace_back(Counted(value, &live));
                    held.emplace_back(&c, value);
                }
                INFO("seed " << seed << " step " << step);
                REQUIRE(list.size() == held.size());
                REQUIRE(list.empty() == held.empty());
                REQUIRE(live == static_cast<int>(held.size()));
                REQUIRE(list.capacity() >= held.size());
                if (held.size() <= capacityBefore) REQUIRE(list.capacity() == capacityBefore);
                for (const auto& [at, value] : held) {
                    REQUIRE(at->value == value);
                    REQUIRE(at->text == std::to_string(value) + " and some longer text");
                }
            }
        }
        REQUIRE(live == 0);  // the list's destructor destroyed what it held
    }
}

}  // namespace

TEST_CASE("StableList keeps its values in place until cleared", "[traverse][stable-list]") {
    checkStableList<0>();
}

TEST_CASE("StableList with inline room keeps its values in place until cleared", "[traverse][stable-list]") {
    checkStableList<1>();
    checkStableList<3>();
}

}  // namespace test_stable_list
