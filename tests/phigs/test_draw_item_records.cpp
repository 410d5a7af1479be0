// The shared records of draw items over random networks: every distinct resolved style has one
// interned record (as many records as distinct attribute combinations, equal styles at one
// address), and the transform an item views (one record per run of items of a segment) equals
// the composite transform composed element by element along the item's path.

#include "RandomElements.h"

#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <map>
#include <random>
#include <set>

namespace test_draw_item_records {

using namespace phigs;

namespace {

constexpr int kStructures = 8;

/// Records seen through items: distinct addresses against distinct values.
template <class T>
struct Records {
    std::set<const T*> addresses;
    std::vector<std::pair<T, const T*>> values;  ///< each distinct value with the first address seen

    void add(const ItemRef<T>& ref) {
        const T* at = &ref.get();
        REQUIRE_FALSE(ref.owned());  // traversal makes views of interned records
        addresses.insert(at);
        for (const auto& [value, first] : values)
            if (value == *at) {
                REQUIRE(first == at);  // an equal style is the same record
                return;
            }
        values.emplace_back(*at, at);
    }
    void check() const { CHECK(addresses.size() == values.size()); }
};

struct AllRecords {
    Records<LineStyle> lines;
    Records<MarkerStyle> markers;
    Records<TextStyle> texts;
    Records<InteriorStyleSet> interiors;
    Records<EdgeStyle> edges;

    void add(const DrawItem& item) {
        visitPrimitive(
            [&](const auto& p) {
                using P = std::decay_t<decltype(p)>;
                if constexpr (std::is_same_v<P, DrawPolyline> || std::is_same_v<P, DrawCurve>) {
                    lines.add(p.style);
                } else if constexpr (std::is_same_v<P, DrawColouredPolyline>) {
                    lines.add(p.line.style);
                } else if constexpr (std::is_same_v<P, DrawPolymarker>) {
                    markers.add(p.style);
                } else if constexpr (std::is_same_v<P, DrawText>) {
                    texts.add(p.style);
                } else if constexpr (std::is_same_v<P, DrawFillArea>) {
                    interiors.add(p.interior), edges.add(p.edges);
                } else {
                    static_assert(std::is_same_v<P, DrawMesh>);
                    interiors.add(p.interior), edges.add(p.edges), lines.add(p.isoLineStyle);
                }
            },
            item.primitive);
    }
    void check() const { lines.check(), markers.check(), texts.check(), interiors.check(), edges.check(); }
};

glm::dmat4 compose(const glm::dmat4& current, const TransformElement& t) {
    switch (t.composition) {
        case Composition::Preconcatenate:
            return current * t.matrix;
        case Composition::Postconcatenate:
            return t.matrix * current;
        case Composition::Replace:
            break;
    }
    return t.matrix;
}

/// The composite transform at an item, composed along its path: at each level the transforms
/// before the level's element, a child starting with the parent's composite as its global.
glm::dmat4 pathTransform(const StructureStore& store, const DrawPath& path) {
    glm::dmat4 global(1.0), local(1.0);
    for (std::size_t level = 0; level < path.size(); ++level) {
        if (level > 0) global = global * local, local = glm::dmat4(1.0);
        const Structure* s = store.find(path[level].structureId);
        REQUIRE(s != nullptr);
        for (int i = 0; i + 1 < path[level].elementNumber; ++i) {
            const auto* t = s->elements.get<TransformElement>(static_cast<std::size_t>(i));
            if (!t) continue;
            if (t->type == ElementType::LocalModellingTransformation3 ||
                t->type == ElementType::LocalModellingTransformation)
                local = compose(local, *t);
            else
                global = t->matrix;
        }
    }
    return global * local;
}

void insertSome(StructureStore& store, std::mt19937& rng, int id, int count) {
    store.openStructure(id);
    for (int k = 0; k < count; ++k) {
        try {
            store.insert(testing::randomElement(rng, id, kStructures));
        } catch (const Error&) {
            // a refused element (a cycle) changes nothing
        }
    }
    store.closeStructure();
}

}  // namespace

TEST_CASE("interned styles: one record per distinct attribute combination", "[traverse][random]") {
    for (unsigned seed : {11u, 12u, 13u, 14u, 15u, 16u}) {
        INFO("seed " << seed);
        std::mt19937 rng(seed);
        Phigs phigs;
        phigs.open();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        StructureStore& store = phigs.store();
        for (int id = kStructures; id >= 1; --id) insertSome(store, rng, id, testing::randomInt(rng, 10, 40));
        ws.postStructure(1, 0.5), ws.postStructure(2, 0.25);
        for (int round = 0; round < 3; ++round) {  // later rounds reuse segments and records
            const DrawList& list = ws.display();
            AllRecords records;
            for (const DrawItem& item : list.items) records.add(item);
            records.check();
            insertSome(store, rng, testing::randomInt(rng, 1, kStructures), 5);
        }
    }
}

TEST_CASE("a segment's shared transform is the item's composite transform", "[traverse][random]") {
    std::size_t items = 0, runs = 0;
    for (unsigned seed : {21u, 22u, 23u, 24u, 25u, 26u}) {
        INFO("seed " << seed);
        std::mt19937 rng(seed);
        Phigs phigs;
        phigs.open();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        StructureStore& store = phigs.store();
        for (int id = kStructures; id >= 1; --id) insertSome(store, rng, id, testing::randomInt(rng, 10, 40));
        ws.postStructure(1, 0.5), ws.postStructure(2, 0.25);
        const DrawList& list = ws.display();
        for (const auto& segment : list.items.segments()) {
            const glm::dmat4* last = nullptr;
            for (const DrawItem& item : segment->items) {
                REQUIRE_FALSE(item.modelTransform().owned());
                CHECK(item.modelTransform().get() == pathTransform(store, item.source.path()));
                // One record per run of equal transforms: a new record only where it changed.
                const glm::dmat4* at = &item.modelTransform().get();
                if (last && at != last) CHECK(*at != *last);
                runs += at != last;
                last = at;
                ++items;
            }
        }
    }
    CHECK(items > 0);
    CHECK(runs < items);  // runs of items share one transform
}

TEST_CASE("a segment's items share one context per run of one state", "[traverse][random]") {
    std::size_t items = 0, runs = 0;
    for (unsigned seed : {31u, 32u, 33u, 34u, 35u, 36u}) {
        INFO("seed " << seed);
        std::mt19937 rng(seed);
        Phigs phigs;
        phigs.open();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        StructureStore& store = phigs.store();
        for (int id = kStructures; id >= 1; --id) insertSome(store, rng, id, testing::randomInt(rng, 10, 40));
        ws.postStructure(1, 0.5), ws.postStructure(2, 0.25);
        const DrawList& list = ws.display();
        for (const auto& segment : list.items.segments()) {
            const DrawContext* last = nullptr;
            for (const DrawItem& item : segment->items) {
                REQUIRE_FALSE(item.context.owned());
                CHECK(item.modelTransform().get() == pathTransform(store, item.source.path()));
                const DrawContext* at = &*item.context;
                if (last && at != last) {  // a new record only where something in it changed
                    const bool same =
                        at->modelTransform.get() == last->modelTransform.get() &&
                        at->viewIndex == last->viewIndex && at->lightSet == last->lightSet &&
                        at->depthCue == last->depthCue && at->highlighted == last->highlighted &&
                        at->pickable == last->pickable && at->modelClipPlanes == last->modelClipPlanes;
                    CHECK_FALSE(same);
                }
                runs += at != last;
                last = at;
                ++items;
                // A copy holds its own context, equal to the one it viewed.
                const DrawItem copy = item;
                CHECK(copy.context.owned());
                CHECK(copy.modelTransform().get() == item.modelTransform().get());
                CHECK(copy.viewIndex() == item.viewIndex());
                CHECK(copy.modelClipPlanes() == item.modelClipPlanes());
            }
        }
    }
    CHECK(items > 0);
    CHECK(runs < items);  // runs of items share one context
}

}  // namespace test_draw_item_records
