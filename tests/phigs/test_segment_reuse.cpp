#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <memory>
#include <random>
#include <vector>

namespace test_segment_reuse {

using namespace phigs;

namespace {

struct Scene {
    Phigs phigs;
    StructureStore* store = nullptr;
    Workstation* ws = nullptr;
    Scene() {
        phigs.open();
        store = &phigs.store();
        ws = &phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    }
};

NurbsSurfaceElement patch(double lift) {
    return {geom::Surface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                          {{0, 0, lift}, {0, 1, lift}, {1, 0, lift}, {1, 1, lift}}),
            {}};
}

/// What a list draws, copied out: each item's kind, path and points.
struct Drawn {
    std::size_t kind;
    std::vector<DrawPathLevel> path;
    std::vector<glm::dvec3> points;
    bool operator==(const Drawn&) const = default;
};

std::vector<Drawn> drawn(const DrawList& list) {
    std::vector<Drawn> out;
    for (const DrawItem& item : list.items) {
        Drawn d{item.primitive.index(), item.source.path(), {}};
        if (auto* p = std::get_if<DrawPolyline>(&item.primitive)) d.points = p->points;
        out.push_back(std::move(d));
    }
    return out;
}

}  // namespace

TEST_CASE("reused draw segments let go of the meshes they drew", "[traverse]") {
    Scene s;
    s.store->openStructure(2);
    s.store->insert(patch(0.0));
    s.store->insert(polyline3({{0, 0, 0}, {1, 1, 1}}));
    s.store->closeStructure();
    s.store->openStructure(1);
    s.store->insert(executeStructure(2));
    s.store->closeStructure();
    s.ws->postStructure(1, 0.5);
    s.ws->traverser().setIncremental(false);
    std::weak_ptr<const MeshData> old;
    {
        DrawList list = s.ws->traverse({});
        REQUIRE(list.items.size() == 2);
        old = primitiveAs<DrawMesh>(list.items[0].primitive).mesh;
    }
    // The surface replaced, and the list that drew it gone (its segments wait for reuse).
    s.store->openStructure(2);
    s.store->setEditMode(EditMode::Replace);
    s.store->setElementPointer(1);
    s.store->insert(patch(1.0));
    s.store->closeStructure();
    s.ws->unpostStructure(1);
    // Traversals that take no segment: the spare ones must not keep the old mesh drawn, so the
    // tessellation cache's sweeps forget it.
    for (int k = 0; k < 40; ++k) CHECK(s.ws->traverse({}).items.empty());
    CHECK(old.expired());
}

TEST_CASE("a draw list keeps its items while later traversals reuse segments", "[traverse][random]") {
    std::mt19937 random(20);
    for (int round = 0; round < 20; ++round) {
        Scene s;
        const int leaves = 1 + static_cast<int>(random() % 6);
        s.store->openStructure(1);
        for (int leaf = 0; leaf < leaves; ++leaf) s.store->insert(executeStructure(leaf + 2));
        s.store->closeStructure();
        for (int leaf = 0; leaf < leaves; ++leaf) {
            s.store->openStructure(leaf + 2);
            const int n = static_cast<int>(random() % 12);
            for (int k = 0; k < n; ++k) {
                const double x = static_cast<double>(random() % 100);
                if (random() % 3 == 0)
                    s.store->insert(polylineColourIndex(1 + static_cast<int>(random() % 7)));
                s.store->insert(polyline3({{x, leaf, k}, {x + 1, leaf, k}, {x, leaf + 1, k}}));
            }
            s.store->closeStructure();
        }
        s.ws->postStructure(1, 0.5);
        s.ws->traverser().setIncremental(random() % 2 == 0);
        DrawList kept = s.ws->traverse({});
        const std::vector<Drawn> before = drawn(kept);
        // Edits and traversals whose lists are dropped at once: their segments come back and
        // are taken again, never those of the list still held.
        for (int step = 0; step < 10; ++step) {
            const int leaf = 2 + static_cast<int>(random() % static_cast<unsigned>(leaves));
            s.store->openStructure(leaf);
            s.store->insert(polyline3({{-1, -1, step}, {-2, -2, step}}));
            s.store->closeStructure();
            DrawList dropped = s.ws->traverse({});
            CHECK(dropped.items.size() > kept.items.size());
        }
        CHECK(drawn(kept) == before);
    }
}

}  // namespace test_segment_reuse
