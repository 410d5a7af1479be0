// The compact element storage (ElementArena) against a plain reference: a vector of Element
// values with their serials. Random edit sequences (inserts anywhere, replaces by the same or
// another payload family, deleted ranges, clears, moves between arenas) of elements of every
// payload family; after every operation every element, serial, family and type must agree and
// the arena's layout must be consistent (no overlap, aligned, bytes accounted for; every stored
// point list a view of the pool, none overlapping, points accounted for). Point lists are empty,
// short or hundreds long. Long runs grow and compact the arena and its point pool many times. And through the
// store: random editing (insert and replace mode, pointer moves, labels, deleted ranges, copies of whole
// structures) against a vector model of the structures, checking contents, pointer and serials after every
// operation. A held point pool (what a draw list keeps) must show its points unchanged through
// any later edit, and a draw list's polylines view the stored points and outlive their structure.
// A held surface (boxed payload) keeps its value through any later edit, without a copy; a
// serial past the slots' 48 bits is refused with the arena unchanged.

#include "RandomElements.h"
#include "phigs/Phigs.h"
#include "phigs/store/ElementArena.h"
#include "phigs/store/StructureStore.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace test_element_arena {

using namespace phigs;
using phigs::testing::randomElement;
using phigs::testing::randomInt;

namespace {

struct Reference {
    Element value;
    std::uint64_t serial = 0;
};

/// What differs between the arena and the reference, or an empty string.
std::string difference(const ElementArena& arena, const std::vector<Reference>& reference) {
    if (arena.size() != reference.size())
        return "size " + std::to_string(arena.size()) + ", reference " + std::to_string(reference.size());
    if (arena.empty() != reference.empty()) return "empty() disagrees";
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const Reference& r = reference[i];
        const std::string at = " of element " + std::to_string(i);
        if (arena.serial(i) != r.serial) return "serial" + at;
        if (arena.family(i) != r.value.index()) return "family" + at;
        if (!(arena.element(i) == r.value)) return "value" + at;
        if (arena.type(i) != elementType(r.value)) return "type" + at;
        if ((arena.get<LabelElement>(i) != nullptr) != std::holds_alternative<LabelElement>(r.value))
            return "get<LabelElement>" + at;
        if (const auto* p = arena.get<PolylineElement>(i); p && !(*p == std::get<PolylineElement>(r.value)))
            return "get<PolylineElement>" + at;
        const std::size_t visited =
            arena.visit(i, [](const auto& payload) -> std::size_t { return Element(payload).index(); });
        if (visited != r.value.index()) return "visit" + at;
    }
    return arena.checkLayout();
}

/// A visitor that forgets one payload: visit() must not accept it.
struct ForgetsLabels {
    template <class T>
    requires(!std::is_same_v<T, LabelElement>) int operator()(const T&) const { return 0; }
};
struct TakesAll {
    template <class T>
    int operator()(const T&) const {
        return 0;
    }
};
static_assert(!ElementVisitor<ForgetsLabels>, "a visitor forgetting a payload must not compile");
static_assert(ElementVisitor<TakesAll>);
template <class F>
constexpr bool arenaVisits = requires(const ElementArena& a, F f) {
    a.visit(0, f);
};
static_assert(!arenaVisits<ForgetsLabels>);
static_assert(arenaVisits<TakesAll>);

/// One random edit of `arena` and `reference` alike; `other` takes part in moves.
void edit(std::mt19937& rng, ElementArena& arena, std::vector<Reference>& reference, ElementArena& other,
          std::vector<Reference>& otherReference, std::uint64_t& serial, bool grow) {
    // Growing: more inserts than elements deleted, long ranges and clears rare.
    const std::size_t maxSize = grow ? 600 : 40;
    int op = randomInt(rng, 0, 99);
    if (grow && op >= 90 && randomInt(rng, 0, 19) > 0) op = randomInt(rng, 0, 49);
    const auto size = static_cast<int>(reference.size());
    auto position = [&](int count) { return static_cast<std::size_t>(randomInt(rng, 0, count)); };
    if (op < 50 && reference.size() < maxSize) {  // insert anywhere, the end most often
        const std::size_t at = op < 25 ? reference.size() : position(size);
        Element e = randomElement(rng, 1, 50);
        reference.insert(reference.begin() + static_cast<std::ptrdiff_t>(at), {e, ++serial});
        arena.insert(at, std::move(e), serial);
    } else if (op < 70 && size > 0) {  // replace, by the same family or another one
        const std::size_t at = position(size - 1);
        Element e = randomElement(rng, 1, 50);
        if (op < 60) {
            while (e.index() != reference[at].value.index()) e = randomElement(rng, 1, 50);
        }
        reference[at] = {e, ++serial};
        arena.replace(at, std::move(e), serial);
    } else if (op < 95 && size > 0) {  // delete a range, usually a short one
        const std::size_t first = position(size - 1);
        const std::size_t last = std::min<std::size_t>(
            reference.size(), first + 1 + (op < 90 ? position(grow ? 1 : 3) : position(size)));
        reference.erase(reference.begin() + static_cast<std::ptrdiff_t>(first),
                        reference.begin() + static_cast<std::ptrdiff_t>(last));
        arena.erase(first, last);
    } else if (op < 97) {  // exchange with the other arena, or move it over
        if (op == 95) {
            arena.swap(other);
        } else {
            other = std::move(arena);
            arena = ElementArena();
            otherReference = std::move(reference);
            reference.clear();
            arena.swap(other);
        }
        std::swap(reference, otherReference);
    } else if (op == 99) {
        arena.clear();
        reference.clear();
    }
}

}  // namespace

TEST_CASE("element arena: random edits agree with a vector of elements", "[store][random]") {
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
        std::mt19937 rng(seed);
        ElementArena arena, other;
        std::vector<Reference> reference, otherReference;
        std::uint64_t serial = 0;
        std::size_t largest = 0, relocations = 0, repools = 0;
        // Small arenas first (every edit checked against the whole reference), then large ones
        // that grow and compact the arena many times.
        for (int op = 0; op < 8000; ++op) {
            const std::size_t deadBefore = arena.deadBytes(), poolDeadBefore = arena.poolDead();
            edit(rng, arena, reference, other, otherReference, serial, op >= 4000);
            largest = std::max(largest, reference.size());
            relocations += arena.deadBytes() < deadBefore && !arena.empty();
            repools += arena.poolDead() < poolDeadBefore && !arena.empty();
            std::string broken = difference(arena, reference);
            if (broken.empty()) broken = difference(other, otherReference);
            INFO("seed " << seed << ", operation " << op);
            REQUIRE(broken == "");
        }
        // The runs reach sizes that grow the arena many times, and compact it.
        CHECK(largest > 200);
        CHECK(relocations > 10);
        CHECK(repools > 10);
    }
}

TEST_CASE("element arena: point lists live in the pool, reused and compacted", "[store][random]") {
    std::mt19937 rng(7);
    ElementArena arena;
    std::vector<Reference> reference;
    std::uint64_t serial = 0;
    auto polyline = [&](int count) { return PolylineElement{testing::randomPoints(rng, count), false}; };
    for (int i = 0; i < 3000; ++i) {
        Element e = polyline(testing::randomPointCount(rng));
        reference.push_back({e, ++serial});
        arena.insert(arena.size(), std::move(e), serial);
    }
    REQUIRE(difference(arena, reference) == "");
    // Stored lists view the pool; a copy out of the arena owns its points.
    const auto* stored = arena.get<PolylineElement>(0);
    CHECK_FALSE(stored->points.ownsPoints());
    CHECK(std::get<PolylineElement>(arena.element(0)).points.ownsPoints() == !stored->points.empty());
    // Replacing lists by the same family with other lengths, then deleting most: the pool's
    // dead points are counted, and it is compacted to the live ones.
    for (int i = 0; i < 3000; i += 2) {
        Element e = polyline(randomInt(rng, 0, 1) ? 0 : randomInt(rng, 1, 50));
        reference[static_cast<std::size_t>(i)] = {e, ++serial};
        arena.replace(static_cast<std::size_t>(i), std::move(e), serial);
        INFO("replacement " << i);
        REQUIRE(arena.checkLayout() == "");
    }
    REQUIRE(difference(arena, reference) == "");
    const std::size_t pooled = arena.poolCapacity();
    reference.erase(reference.begin() + 100, reference.end());
    arena.erase(100, arena.size());
    REQUIRE(difference(arena, reference) == "");
    CHECK(arena.poolCapacity() < pooled / 4);
    CHECK(arena.poolDead() == 0);
    // A list longer than the whole pool grows it in one step.
    Element big = polyline(100000);
    reference.insert(reference.begin() + 50, {big, ++serial});
    arena.insert(50, std::move(big), serial);
    REQUIRE(difference(arena, reference) == "");
}

TEST_CASE("element arena: a held point pool keeps the points its lists showed", "[store][random]") {
    // A reader (a draw list) views stored points and holds the pool; random edits that grow,
    // compact, clear and move the arena afterwards must leave every held view as it was.
    for (unsigned seed : {21u, 22u, 23u}) {
        std::mt19937 rng(seed);
        ElementArena arena, other;
        std::vector<Reference> reference, otherReference;
        std::uint64_t serial = 0;
        struct Held {
            std::shared_ptr<const void> pool;
            const glm::dvec3* data;
            std::vector<glm::dvec3> points;
        };
        std::vector<Held> held;
        std::size_t released = 0;
        for (int op = 0; op < 6000; ++op) {
            edit(rng, arena, reference, other, otherReference, serial, op % 2000 >= 1000);
            // Hold the pool of a stored list (polyline or polymarker) from a random place on.
            const std::size_t from = static_cast<std::size_t>(randomInt(rng, 0, 999));
            const bool hold = randomInt(rng, 0, 2) == 0;
            for (std::size_t k = 0; hold && k < arena.size(); ++k) {
                const std::size_t at = (from + k) % arena.size();
                const PointList* list = nullptr;
                if (const auto* p = arena.get<PolylineElement>(at)) list = &p->points;
                if (const auto* p = arena.get<PolymarkerElement>(at)) list = &p->points;
                if (list && !list->empty()) {
                    held.push_back({arena.pointPool(), list->data(), list->toVector()});
                    break;
                }
            }
            if (held.size() > 40) {  // drop one: its pool may go now
                held.erase(held.begin() + randomInt(rng, 0, static_cast<int>(held.size()) - 1));
                ++released;
            }
            for (std::size_t h = 0; h < held.size(); ++h) {
                INFO("seed " << seed << ", operation " << op << ", held view " << h);
                REQUIRE(held[h].pool);
                REQUIRE(std::equal(held[h].points.begin(), held[h].points.end(), held[h].data));
            }
            REQUIRE(difference(arena, reference) == "");
        }
        CHECK(released > 200);
    }
}

TEST_CASE("element arena: a draw list keeps its points after their structure changes", "[store][traverse]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.openStructure(1);
    for (int i = 0; i < 200; ++i) store.insert(polyline3({{i, 0, 0}, {i, 1, 0}, {i, 1, 1}}));
    store.insert(polymarker3({{0, 0, 7}}));
    store.closeStructure();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    ws.postStructure(1, 0.5);
    const DrawList before = ws.display();
    REQUIRE(before.items.size() == 201);
    // Traversal views the stored points instead of copying them.
    const auto& first = std::get<DrawPolyline>(before.items[0].primitive);
    CHECK(first.points.data() == store.structure(1).elements.get<PolylineElement>(0)->points.data());
    // Every point list replaced (the pool grows and is compacted), then the structure deleted.
    store.openStructure(1);
    store.setEditMode(EditMode::Replace);
    for (int i = 1; i <= 200; ++i) {
        store.setElementPointer(i);
        store.insert(polyline3({{-i, 5, 5}, {-i, 6, 6}}));
    }
    store.closeStructure();
    CHECK(std::get<DrawPolyline>(ws.display().items[7].primitive).points[0].x == -8);
    store.deleteStructure(1);
    ws.display();
    for (std::size_t i = 0; i < 200; ++i) {
        const auto& points = std::get<DrawPolyline>(before.items[i].primitive).points;
        INFO("item " << i);
        REQUIRE(points.size() == 3);
        CHECK(points[0] == glm::dvec3(i, 0, 0));
        CHECK(points[2] == glm::dvec3(i, 1, 1));
    }
    CHECK(std::get<DrawPolymarker>(before.items[200].primitive).points[0] == glm::dvec3(0, 0, 7));
}

TEST_CASE("element arena: deletions give the space back", "[store]") {
    ElementArena arena;
    std::uint64_t serial = 0;
    for (int i = 0; i < 20000; ++i)
        arena.insert(arena.size(), PolylineElement{{{i, 0, 0}, {i, 1, 0}}, false}, ++serial);
    const std::size_t full = arena.capacityBytes();
    arena.erase(0, 19000);
    // Most of the arena is dead: it was compacted to the live payloads.
    CHECK(arena.capacityBytes() < full / 4);
    CHECK(arena.deadBytes() == 0);
    CHECK(arena.checkLayout() == "");
    CHECK(arena.get<PolylineElement>(0)->points[0].x == 19000);
    arena.erase(0, arena.size());
    CHECK(arena.capacityBytes() == 0);
}

namespace {

/// The store's editing functions on one structure against a vector model of its elements.
struct EditModel {
    std::map<int, std::vector<Element>> structures;
    int pointer = 0;
};

std::string storeDifference(const StructureStore& store, const EditModel& model) {
    if (store.elementPointer() != model.pointer)
        return "pointer " + std::to_string(store.elementPointer()) + ", model " +
               std::to_string(model.pointer);
    for (const auto& [id, elements] : model.structures) {
        const Structure& s = store.structure(id);
        if (s.elements.size() != elements.size()) return "size of " + std::to_string(id);
        for (std::size_t i = 0; i < elements.size(); ++i)
            if (!(store.elementAt(id, static_cast<int>(i) + 1) == elements[i]))
                return "element " + std::to_string(i + 1) + " of " + std::to_string(id);
        if (std::string layout = s.elements.checkLayout(); !layout.empty()) return layout;
    }
    return {};
}

}  // namespace

TEST_CASE("element arena: store editing agrees with a vector model", "[store][random]") {
    for (unsigned seed : {11u, 12u, 13u}) {
        std::mt19937 rng(seed);
        StructureStore store;
        EditModel model;
        for (int id : {1, 2, 3}) {
            store.emptyStructure(id);
            model.structures[id];
        }
        int open = 1;
        store.openStructure(open);
        model.pointer = 0;
        for (int op = 0; op < 4000; ++op) {
            auto& elements = model.structures[open];
            const int count = static_cast<int>(elements.size());
            const int choice = randomInt(rng, 0, 99);
            // Labels 1..4 and executes are left out of the random elements (no networks here).
            auto element = [&] {
                Element e = randomElement(rng, 100, 100);
                while (std::holds_alternative<ExecuteStructureElement>(e)) e = randomElement(rng, 100, 100);
                if (randomInt(rng, 0, 5) == 0) e = label(randomInt(rng, 1, 4));
                return e;
            };
            if (choice < 45) {
                Element e = element();
                const bool replace = randomInt(rng, 0, 3) == 0;
                store.setEditMode(replace ? EditMode::Replace : EditMode::Insert);
                if (replace && model.pointer > 0) {
                    elements[static_cast<std::size_t>(model.pointer - 1)] = e;
                } else {
                    elements.insert(elements.begin() + model.pointer, e);
                    ++model.pointer;
                }
                store.insert(std::move(e));
            } else if (choice < 60) {
                const int to = randomInt(rng, -2, count + 2);
                store.setElementPointer(to);
                model.pointer = std::clamp(to, 0, count);
            } else if (choice < 68) {
                const int by = randomInt(rng, -3, 3);
                store.offsetElementPointer(by);
                model.pointer = std::clamp(model.pointer + by, 0, count);
            } else if (choice < 76) {
                store.deleteElement();
                if (model.pointer > 0) elements.erase(elements.begin() + --model.pointer);
            } else if (choice < 84) {
                const int a = randomInt(rng, -1, count + 1), b = randomInt(rng, -1, count + 1);
                store.deleteElementRange(a, b);
                int low = std::clamp(std::min(a, b), 0, count), high = std::clamp(std::max(a, b), 0, count);
                if (low == 0) low = 1;
                if (high >= low) {
                    elements.erase(elements.begin() + (low - 1), elements.begin() + high);
                    model.pointer = low - 1;
                }
            } else if (choice < 90) {
                const int l = randomInt(rng, 1, 4);
                auto it =
                    std::find_if(elements.begin() + model.pointer, elements.end(), [&](const Element& e) {
                        return std::holds_alternative<LabelElement>(e) &&
                               std::get<LabelElement>(e).label == l;
                    });
                if (it == elements.end()) {
                    CHECK_THROWS(store.setElementPointerAtLabel(l));
                } else {
                    store.setElementPointerAtLabel(l);
                    model.pointer = static_cast<int>(it - elements.begin()) + 1;
                }
            } else if (choice < 94) {
                const int from = randomInt(rng, 1, 4);  // 4 does not exist: nothing to copy
                std::vector<Element> copies;
                if (auto it = model.structures.find(from); it != model.structures.end()) copies = it->second;
                if (copies.size() + elements.size() < 400) {
                    store.copyAllElementsFromStructure(from);
                    elements.insert(elements.begin() + model.pointer, copies.begin(), copies.end());
                    model.pointer += static_cast<int>(copies.size());
                }
            } else if (choice < 97) {
                store.closeStructure();
                open = randomInt(rng, 1, 3);
                store.openStructure(open);
                model.pointer = static_cast<int>(model.structures[open].size());
            } else {
                store.emptyStructure(open);
                elements.clear();
                model.pointer = 0;
            }
            INFO("seed " << seed << ", operation " << op << ", choice " << choice);
            REQUIRE(storeDifference(store, model) == "");
            // Serials are unique across the store.
            std::map<std::uint64_t, int> seen;
            for (int id : {1, 2, 3}) {
                const Structure& s = store.structure(id);
                for (std::size_t i = 0; i < s.elements.size(); ++i)
                    REQUIRE(seen[s.elements.serial(i)]++ == 0);
            }
        }
    }
}

TEST_CASE("element arena: a held surface keeps its value through any edit", "[store][random]") {
    // A reader (a draw list) holds a stored surface's box; random edits that replace, delete,
    // compact, clear and move the arena afterwards must leave every held surface as it was.
    for (unsigned seed : {31u, 32u}) {
        std::mt19937 rng(seed);
        ElementArena arena, other;
        std::vector<Reference> reference, otherReference;
        std::uint64_t serial = 0;
        std::vector<std::pair<std::shared_ptr<const NurbsSurfaceElement>, NurbsSurfaceElement>> held;
        std::size_t shared = 0;
        for (int op = 0; op < 4000; ++op) {
            edit(rng, arena, reference, other, otherReference, serial, op % 2000 >= 1000);
            if (arena.empty()) continue;
            const auto at = static_cast<std::size_t>(randomInt(rng, 0, static_cast<int>(arena.size()) - 1));
            auto box = arena.shared<NurbsSurfaceElement>(at);
            const auto* surface = arena.get<NurbsSurfaceElement>(at);
            REQUIRE((box == nullptr) == (surface == nullptr));
            if (box) {
                REQUIRE(box.get() == surface);  // the stored payload itself
                held.emplace_back(box, *box);
                ++shared;
            }
            if (held.size() > 30)
                held.erase(held.begin() + randomInt(rng, 0, static_cast<int>(held.size()) - 1));
            for (std::size_t h = 0; h < held.size(); ++h) {
                INFO("seed " << seed << ", operation " << op << ", held surface " << h);
                REQUIRE(*held[h].first == held[h].second);
            }
            REQUIRE(difference(arena, reference) == "");
        }
        CHECK(shared > 50);
    }
}

TEST_CASE("element arena: a serial past 48 bits is refused, the arena unchanged", "[store]") {
    ElementArena arena;
    arena.insert(0, label(1), 7);
    const std::uint64_t limit = std::uint64_t{1} << 48;
    arena.insert(1, label(2), limit - 1);
    CHECK(arena.serial(1) == limit - 1);
    CHECK_THROWS_WITH(arena.insert(0, label(3), limit), Catch::Contains("serials exhausted"));
    CHECK_THROWS_WITH(arena.replace(0, label(3), limit + 5), Catch::Contains("serials exhausted"));
    REQUIRE(arena.size() == 2);
    CHECK(arena.serial(0) == 7);
    CHECK(arena.get<LabelElement>(0)->label == 1);
    CHECK(arena.checkLayout() == "");
}

}  // namespace test_element_arena
