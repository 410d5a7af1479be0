// Mesh index lists shared between meshes of one shape (SharedIndexList): random changes, copies
// and moves against plain vectors; a shared source and every other reader keep their values
// through any change of one list. And through traversal: untrimmed surfaces tessellated on
// grids of one size share one triangle list, which is the grid's; a trimmed one has its own.

#include "PostedScene.h"
#include "RandomElements.h"
#include "phigs/Phigs.h"
#include "phigs/traverse/SharedIndexList.h"

#include <catch2/catch.hpp>

#include <memory>
#include <random>
#include <vector>

namespace test_shared_index_list {

using namespace phigs;
using phigs::testing::randomInt;

TEST_CASE("shared index lists: changes copy shared values first, readers keep theirs", "[traverse][random]") {
    using Vector = std::vector<std::uint32_t>;
    for (unsigned seed : {41u, 42u, 43u}) {
        std::mt19937 rng(seed);
        auto source = std::make_shared<const Vector>(Vector{1, 2, 3, 4, 5, 6});
        const Vector sourceValues = *source;
        std::vector<SharedIndexList> lists(4);
        std::vector<Vector> models(4);
        for (int op = 0; op < 3000; ++op) {
            const auto k = static_cast<std::size_t>(randomInt(rng, 0, 3));
            const auto other = static_cast<std::size_t>(randomInt(rng, 0, 3));
            SharedIndexList& list = lists[k];
            Vector& model = models[k];
            const auto value = static_cast<std::uint32_t>(randomInt(rng, 0, 99));
            switch (randomInt(rng, 0, 8)) {
                case 0:
                    list.push_back(value), model.push_back(value);
                    break;
                case 1: {
                    const auto at =
                        static_cast<std::ptrdiff_t>(randomInt(rng, 0, static_cast<int>(model.size())));
                    list.insert(list.begin() + at, {value, value + 1});
                    model.insert(model.begin() + at, {value, value + 1});
                    break;
                }
                case 2: {
                    const Vector more{value, 7, value};
                    list.insert(list.end(), more.begin(), more.end());
                    model.insert(model.end(), more.begin(), more.end());
                    break;
                }
                case 3:
                    list = lists[other], model = models[other];
                    break;
                case 4:
                    list = SharedIndexList::shared(source), model = sourceValues;
                    break;
                case 5:
                    if (k != other) list = std::move(lists[other]), model = models[other];
                    if (k != other) lists[other] = SharedIndexList(), models[other].clear();
                    break;
                case 6:
                    list.clear(), model.clear();
                    break;
                case 7:
                    list = Vector{value}, model = Vector{value};
                    break;
                default:
                    list.shrink_to_fit();
                    break;
            }
            for (std::size_t i = 0; i < lists.size(); ++i) {
                INFO("seed " << seed << ", operation " << op << ", list " << i);
                REQUIRE(lists[i] == models[i]);
                REQUIRE(lists[i].size() == models[i].size());
                for (std::size_t j = 0; j < models[i].size(); ++j) REQUIRE(lists[i][j] == models[i][j]);
            }
            REQUIRE(*source == sourceValues);
        }
    }
}

TEST_CASE("shared index lists: surfaces on grids of one size share their triangles", "[traverse][surface]") {
    std::mt19937 rng(4417);
    phigs::test::PostedScene scene;
    // Two segment counts per span: some surfaces fall on grids of one size.
    std::vector<Element> elements{ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, 3, 3}};
    for (int k = 0; k < 12; ++k) {
        NurbsSurfaceElement s{phigs::testing::randomSurface(rng), {}};
        if (k == 6)
            elements.push_back(ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, 2, 2});
        if (k % 4 == 3) s.trimLoops.push_back({phigs::testing::randomCurve(rng, false)});
        elements.push_back(s);
    }
    const DrawList& list = scene.draw(elements);
    // Each mesh with whether its stored surface (the one it shares) is trimmed.
    std::vector<std::pair<const MeshData*, bool>> meshes;
    const ElementArena& stored = scene.store->structure(1).elements;
    for (const DrawItem& item : list.items)
        if (const auto* m = primitiveIf<DrawMesh>(item.primitive))
            for (std::size_t i = 0; i < stored.size(); ++i)
                if (const auto* e = stored.get<NurbsSurfaceElement>(i); e && &e->surface == m->surface.get())
                    meshes.push_back({m->mesh.get(), !e->trimLoops.empty()});
    REQUIRE(meshes.size() >= 9);
    for (const auto& [a, trimmedA] : meshes) {
        for (const auto& [b, trimmedB] : meshes) {
            if (a == b) continue;
            if (trimmedA || trimmedB) {
                CHECK_FALSE(a->triangles.sharesWith(b->triangles));
                continue;
            }
            // Untrimmed grids: equal triangles mean one grid size, and then one shared list.
            if (a->triangles == b->triangles) {
                CHECK(a->triangles.sharesWith(b->triangles));
            }
        }
        // Every triangle indexes a position of its own mesh.
        for (std::uint32_t i : a->triangles) REQUIRE(i < a->positions.size());
    }
    // The same surface twice: one grid, so the triangles are shared at least there.
    const DrawList& twice = scene.draw({elements[0], elements[1], elements[1]});
    REQUIRE(twice.items.size() == 2);
    CHECK(primitiveAs<DrawMesh>(twice.items[0].primitive)
              .mesh->triangles.sharesWith(primitiveAs<DrawMesh>(twice.items[1].primitive).mesh->triangles));
}

}  // namespace test_shared_index_list
