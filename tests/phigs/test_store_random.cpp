// A randomized comparison of the structure store against a small reference model that does
// the same operations in the most direct way; every inquiry must agree after every operation.

#include "ErrorNumber.h"
#include "phigs/store/StructureStore.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <set>

using namespace phigs;
using phigs::test::errorOf;

namespace {

struct Model {
    std::map<int, std::vector<Element>> structures;
    std::optional<int> open;
    int pointer = 0;
    bool replace = false;

    static const ExecuteStructureElement* exec(const Element& e) {
        return std::get_if<ExecuteStructureElement>(&e);
    }

    std::map<int, std::set<int>> graph() const {
        std::map<int, std::set<int>> g;
        for (const auto& [id, elements] : structures) {
            g[id];
            for (const auto& e : elements)
                if (auto x = exec(e)) g[id].insert(x->structureId);
        }
        return g;
    }
    static bool reaches(const std::map<int, std::set<int>>& g, int from, int to, std::set<int>& seen) {
        if (from == to) return true;
        if (!seen.insert(from).second) return false;
        auto it = g.find(from);
        if (it == g.end()) return false;
        for (int c : it->second)
            if (reaches(g, c, to, seen)) return true;
        return false;
    }
    static bool cyclic(const std::map<int, std::set<int>>& g) {
        for (const auto& [id, children] : g)
            for (int c : children) {
                std::set<int> seen;
                if (reaches(g, c, id, seen)) return true;
            }
        return false;
    }
    bool wouldCycle(int parent, int child) const {
        std::set<int> seen;
        return reaches(graph(), child, parent, seen);
    }
    std::vector<Element>& current() { return structures.at(*open); }
    int count() { return static_cast<int>(current().size()); }

    // Each returns the error number the operation must raise (0: none) and applies it otherwise.
    int openStructure(int id) {
        if (open) return 6;
        structures[id];
        open = id;
        pointer = static_cast<int>(structures[id].size());
        return 0;
    }
    int closeStructure() {
        if (!open) return 5;
        open.reset();
        pointer = 0;
        return 0;
    }
    int insert(const Element& e) {
        if (!open) return 5;
        if (auto x = exec(e)) {
            if (wouldCycle(*open, x->structureId)) return errors::StructureCycle;
            structures[x->structureId];
        }
        if (replace && pointer > 0) {
            current()[pointer - 1] = e;
        } else {
            current().insert(current().begin() + pointer, e);
            ++pointer;
        }
        return 0;
    }
    int setPointer(int p) {
        if (!open) return 5;
        pointer = std::clamp(p, 0, count());
        return 0;
    }
    int offsetPointer(int d) {
        if (!open) return 5;
        pointer = std::clamp(pointer + d, 0, count());
        return 0;
    }
    int labelPosition(int from, int value) {  // 1-based position of the first label after `from`, or 0
        for (int n = from + 1; n <= count(); ++n) {
            auto l = std::get_if<LabelElement>(&current()[n - 1]);
            if (l && l->label == value) return n;
        }
        return 0;
    }
    int pointerAtLabel(int value) {
        if (!open) return 5;
        int n = labelPosition(pointer, value);
        if (!n) return 205;
        pointer = n;
        return 0;
    }
    int deleteElement() {
        if (!open) return 5;
        if (pointer > 0) {
            current().erase(current().begin() + pointer - 1);
            --pointer;
        }
        return 0;
    }
    int deleteRange(int a, int b) {
        if (!open) return 5;
        int low = std::max(1, std::clamp(std::min(a, b), 0, count()));
        int high = std::clamp(std::max(a, b), 0, count());
        if (high >= low) current().erase(current().begin() + low - 1, current().begin() + high);
        pointer = low - 1;
        return 0;
    }
    int deleteBetweenLabels(int l1, int l2) {
        if (!open) return 5;
        int a = labelPosition(pointer, l1);
        int b = a ? labelPosition(a, l2) : 0;
        if (!b) return 206;
        current().erase(current().begin() + a, current().begin() + b - 1);
        pointer = a;
        return 0;
    }
    int copyAll(int id) {
        if (!open) return 5;
        if (!structures.contains(id)) return 201;
        std::vector<Element> copies = structures.at(id);
        for (const auto& e : copies)
            if (auto x = exec(e); x && wouldCycle(*open, x->structureId)) return errors::StructureCycle;
        current().insert(current().begin() + pointer, copies.begin(), copies.end());
        pointer += static_cast<int>(copies.size());
        return 0;
    }
    int emptyStructure(int id) {
        if (structures.contains(id)) structures[id].clear();
        if (open == id) pointer = 0;
        return 0;
    }
    void deleteOne(int id) {
        if (!structures.contains(id)) return;
        for (auto& [sid, elements] : structures)
            for (int i = static_cast<int>(elements.size()) - 1; i >= 0; --i)
                if (auto x = exec(elements[i]); x && x->structureId == id) {
                    elements.erase(elements.begin() + i);
                    if (open == sid && i < pointer) --pointer;
                }
        if (open == id) {
            structures[id].clear();
            pointer = 0;
        } else {
            structures.erase(id);
        }
    }
    int deleteStructure(int id) {
        deleteOne(id);
        return 0;
    }
    std::set<int> network(int id) const {
        std::set<int> out;
        std::function<void(int)> visit = [&](int s) {
            if (!out.insert(s).second) return;
            if (auto it = structures.find(s); it != structures.end())
                for (const auto& e : it->second)
                    if (auto x = exec(e)) visit(x->structureId);
        };
        visit(id);
        return out;
    }
    int deleteNetwork(int id, bool keep) {
        if (!structures.contains(id)) return 201;
        std::set<int> members = network(id), doomed;
        if (!keep) {
            doomed = members;
        } else {
            doomed = {id};
            auto g = graph();
            for (bool grew = true; grew;) {
                grew = false;
                for (int m : members) {
                    if (doomed.contains(m)) continue;
                    bool all = true;
                    for (const auto& [p, children] : g)
                        if (children.contains(m) && !doomed.contains(p)) all = false;
                    if (all) doomed.insert(m), grew = true;
                }
            }
        }
        for (int m : doomed) deleteOne(m);
        return 0;
    }
    int deleteAll() {
        structures.clear();
        if (open) structures[*open], pointer = 0;
        return 0;
    }
    bool referenced(int id) const {
        for (const auto& [sid, elements] : structures)
            for (const auto& e : elements)
                if (auto x = exec(e); x && x->structureId == id) return true;
        return false;
    }
    int changeIdentifier(int from, int to) {
        if (!structures.contains(from)) return 201;
        if (from == to) return 0;
        auto g = graph();
        g[to] = g[from];
        g[from].clear();
        if (cyclic(g)) return errors::StructureCycle;
        std::vector<Element> moved = structures[from];
        structures[from].clear();
        structures[to] = moved;
        if (open == to) pointer = static_cast<int>(moved.size());
        if (open == from) pointer = 0;
        if (open != from && !referenced(from)) structures.erase(from);
        return 0;
    }
    int changeReferences(int from, int to) {
        if (from == to) return 0;
        auto g = graph();
        g[to];
        for (auto& [id, children] : g)
            if (children.erase(from)) children.insert(to);
        if (cyclic(g)) return errors::StructureCycle;
        structures[to];
        for (auto& [id, elements] : structures)
            for (auto& e : elements)
                if (auto x = exec(e); x && x->structureId == from) e = ExecuteStructureElement{to};
        return 0;
    }
    int changeBoth(int from, int to) {
        if (!structures.contains(from)) return 201;
        if (from == to) return 0;
        auto g = graph();
        g[to] = g[from];
        g.erase(from);
        for (auto& [id, children] : g)
            if (children.erase(from)) children.insert(to);
        if (cyclic(g)) return errors::StructureCycle;
        changeIdentifier(from, to);
        changeReferences(from, to);
        if (open != from) structures.erase(from);
        return 0;
    }

    std::vector<StructurePath> descendants(int id, int depth, bool topFirst) const {
        std::vector<StructurePath> out;
        std::function<void(int, StructurePath)> walk = [&](int s, StructurePath p) {
            bool leaf = true;
            if (auto it = structures.find(s); it != structures.end())
                for (std::size_t i = 0; i < it->second.size(); ++i)
                    if (auto x = exec(it->second[i])) {
                        leaf = false;
                        StructurePath q = p;
                        q.push_back({s, static_cast<int>(i) + 1});
                        walk(x->structureId, q);
                    }
            if (leaf) {
                p.push_back({s, 0});
                out.push_back(p);
            }
        };
        walk(id, {});
        std::sort(out.begin(), out.end());
        for (auto& p : out)
            if (depth > 0 && static_cast<int>(p.size()) > depth) {
                if (topFirst)
                    p.resize(static_cast<std::size_t>(depth));
                else
                    p.erase(p.begin(), p.end() - depth);
            }
        std::vector<StructurePath> unique;
        for (auto& p : out)
            if (std::find(unique.begin(), unique.end(), p) == unique.end()) unique.push_back(p);
        return unique;
    }
};

void compare(const StructureStore& store, const Model& model) {
    std::vector<int> ids;
    for (const auto& [id, e] : model.structures) ids.push_back(id);
    REQUIRE(store.structureIds() == ids);
    REQUIRE(store.isStructureOpen() == model.open.has_value());
    if (model.open) {
        REQUIRE(store.openStructureId() == *model.open);
        REQUIRE(store.elementPointer() == model.pointer);
    }
    for (const auto& [id, elements] : model.structures) {
        REQUIRE(store.elementCount(id) == static_cast<int>(elements.size()));
        REQUIRE(store.structureStatus(id) ==
                (elements.empty() ? StructureStatus::Empty : StructureStatus::NotEmpty));
        for (std::size_t i = 0; i < elements.size(); ++i)
            REQUIRE(store.elementAt(id, static_cast<int>(i) + 1) == elements[i]);
    }
}

}  // namespace

TEST_CASE("100,000 random store operations agree with a reference model", "[store][random]") {
    std::mt19937 rng(20261201);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    StructureStore store;
    Model model;
    std::map<int, int> outcomes;
    const int operations = 100000;
    for (int op = 0; op < operations; ++op) {
        int kind = pick(0, 99);
        int a = pick(1, 8), b = pick(1, 8);
        int expected = 0, actual = 0;
        auto run = [&](auto&& onStore, int modelResult) {
            expected = modelResult;
            actual = errorOf(onStore);
        };
        if (kind < 8) {
            run([&] { store.openStructure(a); }, model.openStructure(a));
        } else if (kind < 14) {
            run([&] { store.closeStructure(); }, model.closeStructure());
        } else if (kind < 40) {
            Element e;
            switch (pick(0, 3)) {
                case 0:
                    e = label(pick(0, 4));
                    break;
                case 1:
                    e = polyline3({{double(pick(0, 9)), 0, 0}, {1, 1, 1}});
                    break;
                case 2:
                    e = executeStructure(b);
                    break;
                default:
                    e = pickId(pick(0, 3));
                    break;
            }
            run([&] { store.insert(e); }, model.insert(e));
        } else if (kind < 45) {
            bool replace = pick(0, 1) == 1;
            store.setEditMode(replace ? EditMode::Replace : EditMode::Insert);
            model.replace = replace;
        } else if (kind < 52) {
            int p = pick(-2, 20);
            run([&] { store.setElementPointer(p); }, model.setPointer(p));
        } else if (kind < 56) {
            int d = pick(-5, 5);
            run([&] { store.offsetElementPointer(d); }, model.offsetPointer(d));
        } else if (kind < 61) {
            int l = pick(0, 4);
            run([&] { store.setElementPointerAtLabel(l); }, model.pointerAtLabel(l));
        } else if (kind < 67) {
            run([&] { store.deleteElement(); }, model.deleteElement());
        } else if (kind < 70) {
            int x = pick(-1, 12), y = pick(-1, 12);
            run([&] { store.deleteElementRange(x, y); }, model.deleteRange(x, y));
        } else if (kind < 73) {
            int x = pick(0, 4), y = pick(0, 4);
            run([&] { store.deleteElementsBetweenLabels(x, y); }, model.deleteBetweenLabels(x, y));
        } else if (kind < 76) {
            run([&] { store.copyAllElementsFromStructure(a); }, model.copyAll(a));
        } else if (kind < 79) {
            run([&] { store.emptyStructure(a); }, model.emptyStructure(a));
        } else if (kind < 83) {
            run([&] { store.deleteStructure(a); }, model.deleteStructure(a));
        } else if (kind < 86) {
            bool keep = pick(0, 1) == 1;
            run(
                [&] {
                    store.deleteStructureNetwork(a,
                                                 keep ? ReferenceHandling::Keep : ReferenceHandling::Delete);
                },
                model.deleteNetwork(a, keep));
        } else if (kind < 87) {
            run([&] { store.deleteAllStructures(); }, model.deleteAll());
        } else if (kind < 91) {
            run([&] { store.changeStructureIdentifier(a, b); }, model.changeIdentifier(a, b));
        } else if (kind < 95) {
            run([&] { store.changeStructureReferences(a, b); }, model.changeReferences(a, b));
        } else {
            run([&] { store.changeStructureIdentifierAndReferences(a, b); }, model.changeBoth(a, b));
        }
        INFO("operation " << op << " kind " << kind << " a " << a << " b " << b);
        REQUIRE(actual == expected);
        ++outcomes[actual];
        compare(store, model);
        if (op % 50 == 0 && model.structures.contains(a)) {
            int depth = pick(0, 3);
            bool top = pick(0, 1) == 1;
            REQUIRE(store.pathsToDescendants(
                        a, top ? StructurePathOrder::TopFirst : StructurePathOrder::BottomFirst, depth) ==
                    model.descendants(a, depth, top));
            int start = pick(-1, 12);
            auto found = store.elementSearch(a, start, SearchDirection::Forward, {ElementType::Label}, {});
            int expectedAt = 0;
            const auto& elements = model.structures.at(a);
            for (int n = std::max(std::min(start, static_cast<int>(elements.size())), 1);
                 n <= static_cast<int>(elements.size()); ++n)
                if (std::holds_alternative<LabelElement>(elements[static_cast<std::size_t>(n - 1)])) {
                    expectedAt = n;
                    break;
                }
            REQUIRE(found.found == (expectedAt != 0));
            if (found.found) REQUIRE(found.elementNumber == expectedAt);
        }
    }
    // the run exercised the refusals as well as the successes
    CHECK(outcomes[0] > operations / 2);
    CHECK(outcomes[5] > 0);
    CHECK(outcomes[6] > 0);
    CHECK(outcomes[205] > 0);
    CHECK(outcomes[206] > 0);
    CHECK(outcomes[errors::StructureCycle] > 0);
}
