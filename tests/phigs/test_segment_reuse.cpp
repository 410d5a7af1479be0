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
        if (const auto* p = primitiveIf<DrawPolyline>(item.primitive)) d.points = p->points;
        if (const auto* p = primitiveIf<DrawColouredPolyline>(item.primitive)) d.points = p->line.points;
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

TEST_CASE("meshes, curves and vertex colours held out of line keep their values in copies",
          "[traverse][random]") {
    for (unsigned seed : {11u, 12u, 13u, 14u}) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        Scene s;
        s.ws->traverser().setIncremental(false);
        // A structure of surfaces, curves and coloured polyline sets in random order.
        s.store->openStructure(2);
        for (int n = pick(3, 12); n > 0; --n) {
            const double at = pick(-9, 9);
            switch (pick(0, 2)) {
                case 0:
                    s.store->insert(patch(at));
                    break;
                case 1:
                    s.store->insert(NurbsCurveElement{
                        geom::Curve(2, {0, 0, 0, 1, 1, 1}, {{at, 0, 0}, {at + 1, 2, 0}, {at + 2, 0, 1}}), 0.0,
                        0.0});
                    break;
                default: {
                    PolylineSetWithDataElement e;
                    e.polylines = {{{at, 0, 0}, {at, 1, 0}, {at, 1, 1}}};
                    e.vertexColours = {{Colour::fromRgb({0.25, 0.5, 1}), Colour::indexed(pick(1, 7)),
                                        Colour::fromRgb({1, 0, at / 9})}};
                    s.store->insert(e);
                }
            }
        }
        s.store->closeStructure();
        s.store->openStructure(1);
        s.store->insert(executeStructure(2));
        s.store->closeStructure();
        s.ws->postStructure(1, 0.5);

        DrawList original = s.ws->traverse({});
        REQUIRE_FALSE(original.items.empty());
        DrawList copy = original;
        // Writing the copy copies its segment: out-of-line records become values of its own.
        const std::size_t written = static_cast<std::size_t>(pick(0, int(copy.items.size()) - 1));
        copy.items[written].context.edit().viewIndex = 0;
        for (std::size_t i = 0; i < copy.items.size(); ++i) {
            INFO("seed " << seed << " item " << i);
            const DrawPrimitive& a = original.items[i].primitive;
            const DrawPrimitive& b = copy.items[i].primitive;
            REQUIRE(a.index() == b.index());
            // Traversal's meshes, curves and coloured polylines view their segment's records; the
            // copy's items hold their own.
            CHECK_FALSE(ItemVector::ownsSomething(a));
            CHECK(ItemVector::ownsSomething(b));
            if (const DrawMesh* mesh = primitiveIf<DrawMesh>(a)) {
                // The same shared mesh: a renderer keys its buffers on the pointer.
                CHECK(primitiveAs<DrawMesh>(b).mesh == mesh->mesh);
                CHECK(primitiveAs<DrawMesh>(b).surface == mesh->surface);
                CHECK(primitiveAs<DrawMesh>(b).interior.get() == mesh->interior.get());
            } else if (const DrawCurve* curve = primitiveIf<DrawCurve>(a)) {
                CHECK(primitiveAs<DrawCurve>(b).curve == curve->curve);
                CHECK(primitiveAs<DrawCurve>(b).points == curve->points);
            } else if (const DrawColouredPolyline* line = primitiveIf<DrawColouredPolyline>(a)) {
                CHECK_FALSE(line->line.style.owned());  // each member views the interned style
                REQUIRE(line->colours.values.size() == 3);
                CHECK(primitiveAs<DrawColouredPolyline>(b).colours.values == line->colours.values);
                CHECK(primitiveAs<DrawColouredPolyline>(b).line.points == line->line.points);
            }
        }
        // An edit of the copy's record leaves the original's alone.
        for (std::size_t i = 0; i < copy.items.size(); ++i) {
            DrawPrimitive& b = copy.items[i].primitive;
            if (holdsPrimitive<DrawMesh>(b)) editPrimitive<DrawMesh>(b).interior.edit().colour = {1, 0, 0};
            if (holdsPrimitive<DrawCurve>(b)) editPrimitive<DrawCurve>(b).style.edit().colour = {1, 0, 0};
            if (holdsPrimitive<DrawColouredPolyline>(b))
                editPrimitive<DrawColouredPolyline>(b).colours.values = std::vector<glm::vec3>{{1, 0, 0}};
        }
        const std::vector<Drawn> before = drawn(original);
        for (std::size_t i = 0; i < original.items.size(); ++i) {
            const DrawPrimitive& a = original.items[i].primitive;
            if (const DrawMesh* mesh = primitiveIf<DrawMesh>(a))
                CHECK(mesh->interior->colour != glm::vec3(1, 0, 0));
            if (const DrawCurve* curve = primitiveIf<DrawCurve>(a))
                CHECK(curve->style->colour != glm::vec3(1, 0, 0));
            if (const DrawColouredPolyline* line = primitiveIf<DrawColouredPolyline>(a))
                CHECK(line->colours.values.size() == 3);
        }
        // The original gone and its segments filled again by another traversal: the copy's
        // records are its own, and read the same.
        const std::vector<Drawn> copied = drawn(copy);
        original = DrawList{};
        const DrawList again = s.ws->traverse({});
        CHECK(drawn(again) == before);
        CHECK(drawn(copy) == copied);
        for (const DrawItem& item : copy.items)
            if (const DrawMesh* mesh = primitiveIf<DrawMesh>(item.primitive)) {
                CHECK(mesh->interior->colour == glm::vec3(1, 0, 0));
                CHECK(mesh->mesh->positions.size() > 0);
            }
    }
}

}  // namespace test_segment_reuse
