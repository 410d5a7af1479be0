#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <random>

namespace test_picture_limits {

using namespace phigs;

namespace {

/// Structures 1..levels: each but the last executes the next twice, the last holds one primitive,
/// so the posted root draws 2^(levels - 1) instances from 2 * levels - 1 elements.
void buildDoublingNetwork(StructureStore& store, int levels, std::mt19937& rng) {
    for (int id = 1; id < levels; ++id) {
        store.openStructure(id);
        store.insert(executeStructure(id + 1));
        store.insert(executeStructure(id + 1));
        store.closeStructure();
    }
    const PointList points{{0.1, 0.1, 0}, {0.9, 0.2, 0}, {0.5, 0.8, 0}};
    store.openStructure(levels);
    switch (rng() % 3) {
        case 0:
            store.insert(polyline3(points));
            break;
        case 1:
            store.insert(polymarker3(points));
            break;
        default:
            store.insert(fillArea3(points));
            break;
    }
    store.closeStructure();
}

}  // namespace

TEST_CASE("traversal: a picture past the limit is refused with 900, the store kept, a smaller one drawn",
          "[traverse][limits]") {
    std::mt19937 rng(20261207);
    for (int trial = 0; trial < 12; ++trial) {
        const int levels = 8 + static_cast<int>(rng() % 6);  // 128 .. 4096 instances
        const std::size_t instances = std::size_t{1} << (levels - 1);
        const bool incremental = trial % 2 == 0;
        CAPTURE(trial, levels, incremental);
        Phigs phigs;
        phigs.open();
        StructureStore& store = phigs.store();
        buildDoublingNetwork(store, levels, rng);
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        ws.traverser().setIncremental(incremental);
        ws.postStructure(1, 0.5);

        // Room for four times the instances: every instance drawn.
        ws.traverser().setMaxPictureBytes(instances * 4096);
        REQUIRE(ws.display().items.size() == instances);

        // A quarter of a kilobyte an instance: refused, by number, and nothing in the store changed.
        ws.traverser().setMaxPictureBytes(instances * 256);
        const std::uint64_t version = store.structure(levels).version;
        try {
            ws.redrawAllStructures();
            FAIL("a picture past the limit was made");
        } catch (const Error& e) {
            CHECK(e.number() == errors::StorageOverflow);
            CHECK(e.detail().find("KiB") != std::string::npos);
        }
        CHECK(store.elementCount(1) == 2);
        CHECK(store.structure(levels).version == version);
        // Nothing of the refused picture is kept (the leaf's points are the store's alone).
        const std::weak_ptr<const void> points = store.structure(levels).elements.pointPool();
        CHECK(points.use_count() == 1);

        // The root executing structure 5 once: a sixteenth of the instances, within the limit.
        store.openStructure(1);
        store.setElementPointer(0);
        store.deleteElementRange(1, 2);
        store.insert(executeStructure(5));
        store.closeStructure();
        REQUIRE(ws.display().items.size() == instances / 16);
    }
}

TEST_CASE("traversal: a picture that shrinks lets go of its old draw segments at once",
          "[traverse][limits]") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 12; ++trial) {
        const int levels = 6 + static_cast<int>(rng() % 6);
        const bool incremental = trial % 2 == 0;
        CAPTURE(trial, levels, incremental);
        Phigs phigs;
        phigs.open();
        StructureStore& store = phigs.store();
        store.openStructure(levels);  // the leaf: a polyline, whose items view the store's points
        store.insert(polyline3({{0.1, 0.1, 0}, {0.9, 0.2, 0}}));
        store.closeStructure();
        for (int id = levels - 1; id >= 1; --id) {
            store.openStructure(id);
            store.insert(executeStructure(id + 1));
            store.insert(executeStructure(id + 1));
            store.closeStructure();
        }
        const std::weak_ptr<const void> points = store.structure(levels).elements.pointPool();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        ws.traverser().setIncremental(incremental);
        ws.postStructure(1, 0.5);
        for (int repeat = 0; repeat < 1 + static_cast<int>(rng() % 3); ++repeat) {
            REQUIRE(ws.display().items.size() == std::size_t{1} << (levels - 1));
            ws.redrawAllStructures();
        }
        CHECK(points.use_count() > 1);  // the picture's segments hold the points they view
        // The picture shrinks to nothing: emptying a structure on the way, or unposting the root.
        const int emptied = rng() % 2 ? 2 + static_cast<int>(rng() % static_cast<unsigned>(levels - 2)) : 0;
        CAPTURE(emptied);
        if (emptied) {
            store.openStructure(emptied);
            store.emptyStructure(store.openStructureId());
            store.closeStructure();
        } else {
            ws.unpostStructure(1);
        }
        CHECK(ws.display().items.empty());
        CHECK(points.use_count() == 1);  // the store's own share only
    }
}

TEST_CASE("traversal: a scene with a changing cursor keeps reusing the scene's unchanged subtrees",
          "[traverse][limits]") {
    // Root 1 executes structure 2, which executes leaves 100.. of 20 elements each; root 3 (a
    // cursor) changes every frame, structure 2's own elements every other frame: the leaves are
    // reused whenever structure 2 is walked again, however its earlier frames reused it whole.
    std::mt19937 rng(11);
    for (int trial = 0; trial < 4; ++trial) {
        const int leaves = 50 + static_cast<int>(rng() % 150);
        CAPTURE(trial, leaves);
        Phigs phigs;
        phigs.open();
        StructureStore& store = phigs.store();
        for (int leaf = 0; leaf < leaves; ++leaf) {
            store.openStructure(100 + leaf);
            for (int k = 0; k < 20; ++k) store.insert(polyline3({{0.01 * k, 0.01 * leaf, 0}, {0.5, 0.5, 0}}));
            store.closeStructure();
        }
        store.openStructure(2);
        for (int leaf = 0; leaf < leaves; ++leaf) store.insert(executeStructure(100 + leaf));
        store.closeStructure();
        store.openStructure(1);
        store.insert(executeStructure(2));
        store.closeStructure();
        store.openStructure(3);
        store.insert(polyline3({{0, 0, 0}, {0.1, 0.1, 0}}));
        store.closeStructure();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        ws.postStructure(1, 0.5);
        ws.postStructure(3, 0.6);
        ws.display();
        for (int frame = 0; frame < 40; ++frame) {
            const bool editScene = frame % 2 == 1;
            const int edited = editScene ? 2 : 3;
            store.openStructure(edited);
            store.setElementPointer(store.elementCount(edited));  // at the end: the paths stay
            store.insert(label(frame + 10));
            store.closeStructure();
            ws.display();
            if (editScene && frame > 4) {
                CAPTURE(frame);
                CHECK(ws.traverser().elementsReused() >= static_cast<std::uint64_t>(20 * leaves));
            }
        }
    }
}

}  // namespace test_picture_limits
