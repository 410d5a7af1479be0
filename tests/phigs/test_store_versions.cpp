// Subtree versions against a model: after every random edit (inserts and replacements of
// executes and other elements, deletions of elements, ranges and structures, copies, renames,
// reference changes, retrievals), a structure's subtree version must change exactly when the
// version or existence of some structure of its network (as network() walks it) changed.

#include "RandomElements.h"

#include "phigs/store/StructureStore.h"

#include <catch2/catch.hpp>

#include <map>
#include <random>

namespace test_store_versions {

using namespace phigs;

namespace {

constexpr int kStructures = 10;

/// What a structure's network is made of: every member with its version (0: missing).
std::vector<std::pair<int, std::uint64_t>> fingerprint(const StructureStore& store, int id) {
    std::vector<std::pair<int, std::uint64_t>> out;
    for (int member : store.network(id)) {
        const Structure* s = store.find(member);
        out.emplace_back(member, s ? s->version : 0);
    }
    return out;
}

/// An element for `id`: an execute of a higher-numbered structure half the time (acyclic).
Element randomFor(std::mt19937& rng, int id) {
    if (id < kStructures && testing::randomInt(rng, 0, 1))
        return executeStructure(testing::randomInt(rng, id + 1, kStructures));
    if (testing::randomInt(rng, 0, 3) == 0) return label(testing::randomInt(rng, 1, 3));
    return testing::randomElement(rng, id, kStructures);
}

void insertSome(StructureStore& store, std::mt19937& rng, int id, int count) {
    store.openStructure(id);
    store.setEditMode(EditMode::Insert);
    for (int k = 0; k < count; ++k) {
        store.setElementPointer(testing::randomInt(rng, 0, store.elementPointer()));
        store.insert(randomFor(rng, id));
    }
    store.closeStructure();
}

void editInOpen(StructureStore& store, std::mt19937& rng, int id) {
    store.openStructure(id);
    const int count = store.elementPointer();
    switch (testing::randomInt(rng, 0, 4)) {
        case 0:
            store.setEditMode(EditMode::Replace);
            store.setElementPointer(testing::randomInt(rng, 0, count));
            store.insert(randomFor(rng, id));
            store.setEditMode(EditMode::Insert);
            break;
        case 1:
            store.setElementPointer(testing::randomInt(rng, 0, count));
            store.deleteElement();
            break;
        case 2:
            store.deleteElementRange(testing::randomInt(rng, 0, count), testing::randomInt(rng, 0, count));
            break;
        case 3:
            store.setElementPointer(0);
            try {
                store.deleteElementsBetweenLabels(testing::randomInt(rng, 1, 3),
                                                  testing::randomInt(rng, 1, 3));
            } catch (const Error&) {
                // labels not found: nothing changed
            }
            break;
        default:
            // Copies of a higher-numbered structure keep the network acyclic.
            if (id < kStructures)
                store.copyAllElementsFromStructure(testing::randomInt(rng, id + 1, kStructures));
    }
    store.closeStructure();
}

void editOnce(StructureStore& store, std::mt19937& rng) {
    const int id = testing::randomInt(rng, 1, kStructures);
    const int other = testing::randomInt(rng, 1, kStructures);
    try {
        switch (testing::randomInt(rng, 0, 9)) {
            case 0:
                store.emptyStructure(id);
                break;
            case 1:
                store.deleteStructure(id);
                break;
            case 2:
                store.deleteStructureNetwork(
                    id, testing::randomInt(rng, 0, 1) ? ReferenceHandling::Delete : ReferenceHandling::Keep);
                break;
            case 3:
                store.changeStructureIdentifier(id, other);
                break;
            case 4:
                store.changeStructureReferences(id, other);
                break;
            case 5:
                store.changeStructureIdentifierAndReferences(id, other);
                break;
            case 6: {
                std::map<int, std::vector<Element>> contents;
                for (int k = testing::randomInt(rng, 0, 3); k > 0; --k)
                    contents[id].push_back(randomFor(rng, id));
                store.replaceStructures(contents, "RETRIEVE STRUCTURES");
                break;
            }
            case 7:
                editInOpen(store, rng, id);
                break;
            default:
                insertSome(store, rng, id, testing::randomInt(rng, 1, 3));
        }
    } catch (const Error&) {
        // a refused edit (a cycle through a rename) must leave the store as it was
        if (store.isStructureOpen()) store.closeStructure();
    }
}

}  // namespace

TEST_CASE("subtree versions change exactly when their network changes", "[store][random]") {
    for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
        std::mt19937 rng(seed);
        StructureStore store;
        for (int id = kStructures; id >= 1; --id) insertSome(store, rng, id, testing::randomInt(rng, 1, 6));
        std::map<int, std::pair<std::vector<std::pair<int, std::uint64_t>>, std::uint64_t>> before;
        for (int step = 0; step < 400; ++step) {
            INFO("seed " << seed << " step " << step);
            std::map<int, std::pair<std::vector<std::pair<int, std::uint64_t>>, std::uint64_t>> now;
            for (int id : store.structureIds()) {
                now[id] = {fingerprint(store, id), store.subtreeVersion(id)};
                REQUIRE(now[id].second > 0);
                auto was = before.find(id);
                if (was == before.end()) continue;
                const bool networkChanged = was->second.first != now[id].first;
                const bool versionChanged = was->second.second != now[id].second;
                REQUIRE(networkChanged == versionChanged);
            }
            for (int id = 1; id <= kStructures; ++id)
                if (!store.exists(id)) REQUIRE(store.subtreeVersion(id) == 0);
            before = std::move(now);
            editOnce(store, rng);
        }
    }
}

TEST_CASE("subtree versions survive more edits than the store carries one by one", "[store]") {
    StructureStore store;
    store.openStructure(1);
    store.insert(executeStructure(2));
    store.closeStructure();
    const std::uint64_t root = store.subtreeVersion(1), leaf = store.subtreeVersion(2);
    // Two structures edited in turn, far more often than the store keeps edits to carry.
    for (int k = 0; k < 500; ++k) {
        store.openStructure(3 + k % 2);
        store.insert(label(k));
        store.closeStructure();
    }
    const std::uint64_t other = store.subtreeVersion(3);
    store.openStructure(2);
    store.insert(label(7));
    store.closeStructure();
    CHECK(store.subtreeVersion(1) != root);
    CHECK(store.subtreeVersion(2) != leaf);
    CHECK(store.subtreeVersion(3) == other);
    CHECK(store.subtreeVersion(1) == store.subtreeVersion(1));
}

TEST_CASE("the index of executing structures stays exact through deletions and emptying", "[store][random]") {
    // wouldCycle reads the index the deletions keep up to date (rather than rebuild): after each
    // one it must agree with a walk down the networks.
    for (unsigned seed : {11u, 12u, 13u, 14u, 15u, 16u}) {
        std::mt19937 rng(seed);
        StructureStore store;
        for (int id = kStructures; id >= 1; --id) insertSome(store, rng, id, testing::randomInt(rng, 2, 8));
        REQUIRE(store.subtreeVersion(1) > 0);  // settling the versions builds the index
        for (int step = 0; step < 60; ++step) {
            INFO("seed " << seed << " step " << step);
            const int id = testing::randomInt(rng, 1, kStructures);
            switch (testing::randomInt(rng, 0, 3)) {
                case 0:
                    store.emptyStructure(id);
                    break;
                case 1:  // the open structure is emptied, not removed
                    store.openStructure(id);
                    store.deleteStructure(id);
                    store.closeStructure();
                    break;
                case 2:
                    store.deleteStructure(id);
                    break;
                default:
                    insertSome(store, rng, id, testing::randomInt(rng, 1, 3));
            }
            for (int parent = 1; parent <= kStructures; ++parent)
                for (int child = 1; child <= kStructures; ++child) {
                    if (!store.exists(parent) || !store.exists(child)) continue;
                    const bool below = store.network(child).contains(parent);
                    REQUIRE(store.wouldCycle(parent, child) == below);
                }
        }
    }
}

}  // namespace test_store_versions
