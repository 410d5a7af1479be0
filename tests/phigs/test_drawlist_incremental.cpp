// The incremental draw list against a full traversal: random networks, random edits (elements
// inserted, replaced and deleted anywhere, filters, light and depth cue tables, postings), and
// after each one the draw list of a workstation that reuses unchanged subtrees must equal item
// for item the one of a workstation that walks everything. Unchanged parts must be shared, not
// copied: a second display with nothing changed holds the very same segments.

#include "RandomElements.h"

#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <random>
#include <string>

namespace test_drawlist_incremental {

using namespace phigs;

namespace {

constexpr int kStructures = 8;

/// Everything an item draws with, light sets and depth cues resolved to their values (each
/// traverser numbers them its own way), meshes by content (each has its own cache).
struct ItemView {
    std::size_t kind;
    std::vector<DrawPathLevel> path;
    std::uint64_t version;
    glm::dmat4 transform;
    int view;
    bool highlighted, pickable;
    std::vector<Light> lights;
    DepthCue cue;
    bool cued;
    std::vector<glm::dvec4> clip;
    std::vector<glm::dvec3> points;
    std::vector<glm::vec3> colours;
    std::size_t meshPositions, meshTriangles;
    std::string text{};
    bool operator==(const ItemView&) const = default;
};

ItemView view(const DrawList& list, const DrawItem& item) {
    ItemView v{item.primitive.index(),
               item.source.path(),
               item.source.structureVersion(),
               item.modelTransform().get(),
               item.viewIndex(),
               item.highlighted(),
               item.pickable(),
               {},
               {},
               item.depthCue() >= 0,
               item.modelClipPlanes(),
               {},
               {},
               0,
               0};
    if (item.lightSet() >= 0) v.lights = list.lightSets.at(static_cast<std::size_t>(item.lightSet()));
    if (item.depthCue() >= 0) v.cue = list.depthCues.at(static_cast<std::size_t>(item.depthCue()));
    if (auto p = std::get_if<DrawPolyline>(&item.primitive)) v.points = p->points;
    if (auto p = primitiveIf<DrawColouredPolyline>(item.primitive)) {
        v.points = p->line.points;
        v.colours = p->colours.values;
        v.colours.push_back(glm::vec3(p->colours.interpolated ? 1.0f : 0.0f));
    }
    if (auto p = std::get_if<DrawPolymarker>(&item.primitive)) v.points = p->points;
    if (auto c = primitiveIf<DrawCurve>(item.primitive)) v.points = c->points;
    if (auto f = primitiveIf<DrawFillArea>(item.primitive))
        for (const auto& contour : f->contours)
            v.points.insert(v.points.end(), contour.begin(), contour.end());
    if (auto t = primitiveIf<DrawText>(item.primitive)) v.text = t->text;
    if (auto m = primitiveIf<DrawMesh>(item.primitive))
        v.meshPositions = m->mesh->positions.size(), v.meshTriangles = m->mesh->triangles.size();
    return v;
}

struct Twin {
    Phigs phigs;
    Workstation* incremental = nullptr;
    Workstation* full = nullptr;
    Twin() {
        phigs.open();
        incremental = &phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        full = &phigs.openWorkstation(2, WorkstationType::OffscreenImage);
        full->traverser().setIncremental(false);
    }
    template <class F>
    void both(F f) {
        f(*incremental), f(*full);
    }
};

/// A random element, now and then a polyline set with vertex colours (coloured polylines are
/// held out of line, in their segment).
Element randomElement(std::mt19937& rng, int id) {
    if (testing::randomInt(rng, 0, 15) > 0) return testing::randomElement(rng, id, kStructures);
    PolylineSetWithDataElement e;
    e.polylines = {testing::randomPoints(rng, 3), testing::randomPoints(rng, 2)};
    e.vertexColours = {{Colour::indexed(1), Colour::fromRgb({0.5, 0.25, 1}), Colour::indexed(3)},
                       {Colour::indexed(2), Colour::indexed(4)}};
    return e;
}

void insertSome(StructureStore& store, std::mt19937& rng, int id, int count) {
    store.openStructure(id);
    for (int k = 0; k < count; ++k) {
        try {
            store.insert(randomElement(rng, id));
        } catch (const Error&) {
            // a refused element (a cycle) changes nothing
        }
    }
    store.closeStructure();
}

void editOnce(Twin& t, std::mt19937& rng) {
    StructureStore& store = t.phigs.store();
    const int id = testing::randomInt(rng, 1, kStructures);
    switch (testing::randomInt(rng, 0, 9)) {
        case 0: {
            NameSetFilter f{{testing::randomInt(rng, 1, 3)}, {}};
            t.both([&](Workstation& ws) { ws.setHighlightingFilter(f); });
            break;
        }
        case 1: {
            NameSetFilter f{{testing::randomInt(rng, 1, 3)}, {testing::randomInt(rng, 1, 3)}};
            t.both([&](Workstation& ws) { ws.setInvisibilityFilter(f); });
            break;
        }
        case 2: {
            Light light;
            light.type = LightType::Directional;
            light.colour = glm::vec3(testing::randomReal(rng) * 0.5 + 0.5);
            int index = testing::randomInt(rng, 1, 4);
            t.both([&](Workstation& ws) { ws.setLightSourceRepresentation(index, light); });
            break;
        }
        case 3: {
            DepthCue cue{true, 1.0, 0.0, 1.0f, static_cast<float>(testing::randomInt(rng, 0, 4)) / 4, {}};
            int index = testing::randomInt(rng, 1, 3);
            t.both([&](Workstation& ws) { ws.setDepthCueRepresentation(index, cue); });
            break;
        }
        case 4: {
            double priority = testing::randomInt(rng, 0, 4) / 4.0;
            bool post = testing::randomInt(rng, 0, 2) > 0;
            t.both([&](Workstation& ws) { post ? ws.postStructure(id, priority) : ws.unpostStructure(id); });
            break;
        }
        case 5: {
            store.openStructure(id);
            store.setElementPointer(testing::randomInt(rng, 0, store.elementPointer()));
            store.deleteElement();
            store.closeStructure();
            break;
        }
        case 6: {
            store.openStructure(id);
            store.setEditMode(EditMode::Replace);
            store.setElementPointer(testing::randomInt(rng, 1, std::max(1, store.elementPointer())));
            try {
                store.insert(randomElement(rng, id));
            } catch (const Error&) {
            }
            store.setEditMode(EditMode::Insert);
            store.closeStructure();
            break;
        }
        default:
            insertSome(store, rng, id, testing::randomInt(rng, 1, 3));
    }
}

}  // namespace

TEST_CASE("incremental draw lists equal full traversals over random edits", "[traverse][random]") {
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
        std::mt19937 rng(seed);
        Twin t;
        StructureStore& store = t.phigs.store();
        for (int id = kStructures; id >= 1; --id) insertSome(store, rng, id, testing::randomInt(rng, 2, 8));
        t.both([](Workstation& ws) { ws.postStructure(1, 0.5), ws.postStructure(2, 0.25); });
        std::uint64_t reused = 0;
        for (int step = 0; step < 300; ++step) {
            INFO("seed " << seed << " step " << step);
            editOnce(t, rng);
            const DrawList& a = t.incremental->display();
            reused += t.incremental->traverser().elementsReused();
            const DrawList& b = t.full->display();
            REQUIRE(a.items.size() == b.items.size());
            for (std::size_t i = 0; i < a.items.size(); ++i)
                REQUIRE(view(a, a.items[i]) == view(b, b.items[i]));
            // Nothing changed: a new traversal shares every segment of the previous draw list.
            std::vector<DrawItems::SegmentPtr> before = a.items.segments();
            t.incremental->redrawAllStructures();
            const auto& after = t.incremental->display().items.segments();
            std::size_t shared = 0;
            for (std::size_t k = 0; k < std::min(before.size(), after.size()); ++k)
                shared += before[k] == after[k];
            CHECK(after.size() == before.size());
            CHECK(shared + t.incremental->traverser().elementsTraversed() >= after.size());
        }
        CHECK(reused > 0);  // the edits left subtrees to reuse
    }
}

}  // namespace test_drawlist_incremental
