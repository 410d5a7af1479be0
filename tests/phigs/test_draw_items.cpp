// DrawItems against a plain vector: random shared segments, pushes, resizes, clears and writes
// through indices and iterators; after each step both read the same, forwards, backwards and at
// random, and a list sharing segments with another never sees the other's writes.

#include "phigs/traverse/DrawItems.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

namespace test_draw_items {

using namespace phigs;

namespace {

DrawItem numbered(int n) {
    DrawItem item;
    item.context.edit().viewIndex = n;
    return item;
}

std::vector<int> numbers(const DrawItems& items) {
    std::vector<int> out;
    for (const DrawItem& item : items) out.push_back(item.viewIndex());
    return out;
}

}  // namespace

TEST_CASE("draw items read like a vector over random edits", "[traverse][random]") {
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        DrawItems items, other;
        std::vector<int> model, otherModel;
        int next = 1;
        for (int step = 0; step < 400; ++step) {
            INFO("seed " << seed << " step " << step);
            switch (pick(0, 7)) {
                case 0: {
                    // A segment shared with a second list, which then writes its own copy.
                    auto segment = std::make_shared<DrawSegment>();
                    for (int k = pick(0, 4); k > 0; --k) segment->items.push_back(numbered(next++));
                    items.appendSegment(segment);
                    other.appendSegment(segment);
                    for (const DrawItem& item : segment->items) {
                        model.push_back(item.viewIndex());
                        otherModel.push_back(item.viewIndex());
                    }
                    if (!other.empty()) {
                        const std::size_t at = other.size() - 1;
                        other[at].context.edit().viewIndex = -next, otherModel[at] = -next;
                        ++next;
                    }
                    break;
                }
                case 1:
                    items.push_back(numbered(next)), model.push_back(next++);
                    break;
                case 2: {
                    const auto count = static_cast<std::size_t>(pick(0, static_cast<int>(model.size()) + 2));
                    items.resize(count), model.resize(count, 0);
                    break;
                }
                case 3:
                    if (pick(0, 9) == 0) items.clear(), model.clear();
                    break;
                case 4:
                    // Writes through an iterator: every other item.
                    for (auto it = items.begin(); it < items.end(); it += 2) {
                        it->context.edit().viewIndex += 1000;
                        model[static_cast<std::size_t>(it - items.begin())] += 1000;
                    }
                    break;
                default:
                    if (!model.empty()) {
                        const auto at = static_cast<std::size_t>(pick(0, static_cast<int>(model.size()) - 1));
                        items.at(at).context.edit().viewIndex = next, model[at] = next++;
                    }
            }
            REQUIRE(items.size() == model.size());
            REQUIRE(numbers(items) == model);
            REQUIRE(numbers(other) == otherModel);
            std::vector<int> backwards;
            for (auto it = items.end(); it != items.begin();) backwards.push_back((--it)->viewIndex());
            std::reverse(backwards.begin(), backwards.end());
            REQUIRE(backwards == model);
            for (int probe = 0; probe < 3 && !model.empty(); ++probe) {
                const auto at = static_cast<std::ptrdiff_t>(pick(0, static_cast<int>(model.size()) - 1));
                const DrawItems& view = items;
                REQUIRE((view.begin() + at)->viewIndex() == model[static_cast<std::size_t>(at)]);
                REQUIRE(view.begin()[at].viewIndex() == model[static_cast<std::size_t>(at)]);
            }
        }
    }
}

TEST_CASE("items viewing a segment's storage keep their values once copied", "[traverse][random]") {
    for (unsigned seed : {5u, 6u, 7u, 8u}) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        // Items as traversal makes them: points and the path above them are views of the
        // segment's own storage.
        auto segment = std::make_shared<DrawSegment>();
        std::vector<DrawPathLevel> prefix;
        for (int k = pick(1, 3); k > 0; --k) prefix.push_back({pick(1, 9), pick(1, 9), pick(0, 9)});
        const int structureId = pick(1, 9);
        segment->source.set(prefix, structureId, 1);
        std::vector<std::vector<glm::dvec3>> points;
        std::vector<std::vector<DrawPathLevel>> paths;
        for (int n = pick(1, 40); n > 0; --n) {
            std::vector<glm::dvec3> p;
            for (int k = pick(0, 6); k > 0; --k)
                p.push_back(glm::dvec3(pick(-9, 9), pick(-9, 9), pick(-9, 9)));
            DrawItem item;
            item.primitive = DrawPolyline{
                ItemArray<glm::dvec3>::view(segment->points.add(p.data(), p.size()), p.size()), {}};
            const DrawPathLevel own{structureId, pick(1, 99), pick(0, 9)};
            item.source = DrawSource::view(&segment->source, own.elementNumber, own.pickId);
            segment->items.push_back(std::move(item));
            points.push_back(p);
            paths.push_back(prefix);
            paths.back().push_back(own);
        }
        DrawItems shared, writer;
        shared.appendSegment(segment);
        writer.appendSegment(segment);
        const std::size_t at = static_cast<std::size_t>(pick(0, static_cast<int>(points.size()) - 1));
        writer[at].context.edit().viewIndex = 7;  // writing copies the shared segment first
        DrawItem copied = shared[at];
        REQUIRE(std::get<DrawPolyline>(copied.primitive).points.owned() == !points[at].empty());
        segment.reset();
        shared.clear();  // the segment and its storage are gone; the copies must not need them
        REQUIRE(writer.size() == points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            INFO("seed " << seed << " item " << i);
            REQUIRE(std::get<DrawPolyline>(writer[i].primitive).points == points[i]);
            REQUIRE(writer[i].source.path() == paths[i]);
            REQUIRE(std::vector<DrawPathLevel>(writer[i].source.path()) == paths[i]);
        }
        REQUIRE(std::get<DrawPolyline>(copied.primitive).points == points[at]);
        REQUIRE(copied.source.path() == paths[at]);
    }
}

}  // namespace test_draw_items
