// IdTable against a std::map: random ids near and far (negative, dense, huge), random sets,
// erasures and clears; after each step every id reads the same as in the model.

#include "phigs/store/IdTable.h"

#include <catch2/catch.hpp>

#include <climits>
#include <map>
#include <random>

namespace test_id_table {

using phigs::IdTable;

TEST_CASE("id tables read like a map over random edits", "[store][random]") {
    for (unsigned seed : {1u, 2u, 3u}) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        auto randomId = [&] {
            switch (pick(0, 3)) {
                case 0:
                    return pick(-50, 50);
                case 1:
                    return pick(0, 5000);
                case 2:
                    return pick(1 << 21, (1 << 23));
                default:
                    return pick(INT_MIN, INT_MAX);
            }
        };
        IdTable<std::uint64_t> table;
        std::map<int, std::uint64_t> model;
        std::vector<int> seen;
        for (int step = 0; step < 3000; ++step) {
            const int id = seen.empty() || pick(0, 2) == 0
                               ? randomId()
                               : seen[static_cast<std::size_t>(pick(0, int(seen.size()) - 1))];
            seen.push_back(id);
            switch (pick(0, 9)) {
                case 0:
                    table.erase(id), model.erase(id);
                    break;
                case 1:
                    if (pick(0, 50) == 0) table.clear(), model.clear();
                    break;
                default: {
                    const auto value = static_cast<std::uint64_t>(pick(1, 1000));
                    table[id] = value, model[id] = value;
                }
            }
            for (int probe : {id, randomId(), seen.front()}) {
                auto it = model.find(probe);
                const std::uint64_t* found = table.find(probe);
                REQUIRE((found != nullptr) == (it != model.end()));
                if (found) REQUIRE(*found == it->second);
            }
        }
        std::map<int, std::uint64_t> listed;
        table.forEach([&](int id, std::uint64_t value) { listed[id] = value; });
        CHECK(listed == model);
    }
}

TEST_CASE("an id table growing an id at a time takes over the ids it kept aside", "[store]") {
    // Negative ids stay aside for good; ids far past the dense part wait there until the dense
    // part grows over them, one id at a time (each growth looks up only the ids it adds).
    IdTable<std::uint64_t> table;
    for (int id = -1; id >= -300; --id) table[id] = std::uint64_t(1000 - id);
    for (int id : {5000, 5001, 7777, 9000}) table[id] = std::uint64_t(id) * 3;
    for (int id = 0; id < 10000; ++id)
        if (id != 5000 && id != 5001 && id != 7777 && id != 9000) table[id] = std::uint64_t(id) + 1;
    for (int id = 0; id < 10000; ++id) {
        const std::uint64_t* v = table.find(id);
        REQUIRE(v != nullptr);
        const bool aside = id == 5000 || id == 5001 || id == 7777 || id == 9000;
        REQUIRE(*v == (aside ? std::uint64_t(id) * 3 : std::uint64_t(id) + 1));
    }
    for (int id = -1; id >= -300; --id) REQUIRE(*table.find(id) == std::uint64_t(1000 - id));
    std::size_t listed = 0;
    table.forEach([&](int, std::uint64_t) { ++listed; });
    CHECK(listed == 10300);
}

TEST_CASE("an id table treats an empty value as absent", "[store]") {
    IdTable<std::vector<int>> table;
    table[3].push_back(7);
    table[-4].push_back(1);
    CHECK(table.find(3) != nullptr);
    CHECK(table.find(2) == nullptr);
    table[3].clear();
    CHECK(table.find(3) == nullptr);
    CHECK(table.find(-4) != nullptr);
}

}  // namespace test_id_table
