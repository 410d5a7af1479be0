// ItemVector against a plain vector: random items that view shared storage or own copies and
// meshes, writes through indices, resizes and clears; the items read the same as the model, and
// every clear lets go of every mesh an item held (the sanitizer builds see any leaked copy).

#include "phigs/traverse/ItemVector.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace test_item_vector {

using namespace phigs;

namespace {

/// Whether the item's primitive is a view of storage that is not permanent (what the test made).
bool viewsTransient(const DrawItem& item) {
    if (const auto* line = std::get_if<DrawPolyline>(&item.primitive))
        return !line->points.owned() && line->points.size() > 0;
    if (const auto* fill = std::get_if<ItemRef<DrawFillArea>>(&item.primitive))
        return !fill->owned() && !fill->sameRecord(ItemRef<DrawFillArea>{});
    if (const auto* text = std::get_if<ItemRef<DrawText>>(&item.primitive))
        return !text->owned() && !text->sameRecord(ItemRef<DrawText>{});
    return false;
}

}  // namespace

TEST_CASE("item vector: clearing lets go of exactly what the items own", "[traverse][random]") {
    const std::vector<glm::dvec3> points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    DrawFillArea fill;
    fill.contours = {points};
    DrawText text;
    text.text = "T";
    const DrawColouredPolyline coloured{DrawPolyline{ItemArray<glm::dvec3>(points), {}},
                                        {std::vector<glm::vec3>(3, glm::vec3(0, 1, 0)), true}};
    const glm::dmat4 transform(2.0);
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        auto mesh = std::make_shared<const MeshData>();
        ItemVector items;
        std::vector<int> model;
        auto item = [&](int n) {
            DrawItem i;
            i.context.edit().viewIndex = n;
            switch (pick(0, 8)) {
                case 0:
                    i.primitive = DrawPolyline{ItemArray<glm::dvec3>::view(points.data(), 3), {}};
                    break;
                case 1:
                    i.primitive = DrawPolyline{ItemArray<glm::dvec3>(points), {}};
                    break;
                case 2:
                    i.primitive = DrawMesh{mesh, nullptr, {}, {}, {}};
                    break;
                case 3:
                    i.primitive = ItemRef<DrawFillArea>::view(&fill);
                    break;
                case 4:
                    i.primitive = fill;  // a copy of its own
                    break;
                case 5:
                    i.primitive = ItemRef<DrawText>::view(&text);
                    break;
                case 6:
                    i.primitive = ItemRef<DrawColouredPolyline>::view(&coloured);
                    break;
                case 7:
                    i.primitive = coloured;  // a copy of its own, colours and points included
                    break;
                default:
                    i.primitive = text;
                    break;
            }
            if (pick(0, 3) == 0) i.context.edit().modelTransform = ItemRef<glm::dmat4>(transform);
            return i;
        };
        for (int step = 0; step < 600; ++step) {
            INFO("seed " << seed << " step " << step);
            switch (pick(0, 9)) {
                case 0:
                    items.clear(), model.clear();
                    REQUIRE(mesh.use_count() == 1);
                    break;
                case 1: {
                    const auto count = static_cast<std::size_t>(pick(0, 12));
                    items.resize(count), model.resize(count, 0);
                    break;
                }
                case 2:
                    if (!items.empty()) {
                        const auto at = static_cast<std::size_t>(pick(0, int(items.size()) - 1));
                        items[at] = item(step);  // a write: clearing must now destroy everything
                        model[at] = step;
                    }
                    break;
                case 8:
                    // Appending one of its own items, whether or not the storage must grow.
                    if (!items.empty()) {
                        const auto at = static_cast<std::size_t>(pick(0, int(items.size()) - 1));
                        items.push_back(std::as_const(items)[at]), model.push_back(model[at]);
                        break;
                    }
                    [[fallthrough]];
                case 3: {
                    DrawItem copy = item(step);
                    const bool owns = ItemVector::ownsSomething(copy);
                    items.emplaceKnown(owns, std::move(copy)), model.push_back(step);
                    break;
                }
                default:
                    items.push_back(item(step)), model.push_back(step);
                    break;
            }
            REQUIRE(items.size() == model.size());
            for (std::size_t i = 0; i < model.size(); ++i)
                REQUIRE(std::as_const(items)[i].viewIndex() == model[i]);
        }
        const ItemVector copy(items);
        // A copy holds its own of whatever the original owned or viewed in transient storage
        // (permanent views, like the defaults, it shares).
        for (std::size_t i = 0; i < copy.size(); ++i) {
            const DrawItem& original = std::as_const(items)[i];
            if (ItemVector::ownsSomething(original) || viewsTransient(original))
                CHECK(ItemVector::ownsSomething(std::as_const(copy)[i]));
        }
        items.clear();
        CHECK(mesh.use_count() ==
              1 + static_cast<long>(std::count_if(copy.begin(), copy.end(), [](const DrawItem& i) {
                  return holdsPrimitive<DrawMesh>(i.primitive);
              })));
    }
}

TEST_CASE("item refs: a copy of a view owns its value, a copy of a permanent view shares it", "[traverse]") {
    glm::dmat4 record(2.0);
    const auto view = ItemRef<glm::dmat4>::view(&record);
    const ItemRef<glm::dmat4> copied = view;
    CHECK(copied.owned());
    CHECK(!copied.sameRecord(view));
    CHECK(copied.get() == record);

    const auto permanent = ItemRef<glm::dmat4>::permanent(&record);
    ItemRef<glm::dmat4> shared = permanent;
    CHECK(!shared.owned());
    CHECK(shared.sameRecord(permanent));
    shared.edit()[0][0] = 5.0;  // an edit makes a copy of its own first
    CHECK(shared.owned());
    CHECK(record[0][0] == 2.0);

    // Default items copy without allocating: their transform and source stay shared.
    const DrawItem item;
    const DrawItem copy = item;  // NOLINT: the copy is what is tested
    CHECK(!copy.modelTransform().owned());
    CHECK(copy.modelTransform().sameRecord(item.modelTransform()));
    CHECK(!copy.source.owned());
}

}  // namespace test_item_vector
