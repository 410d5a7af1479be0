#pragma once

// The reference model of test_store_random.cpp: the central structure store and the posting
// lists of the open workstations, each operation done in the most direct way, following ISO 9592
// as the NIST PHIGS validation tests (PVT module 02.01) read it. Every operation returns the
// error number it must raise (0: none) and changes nothing then; `warning` holds the warning it
// must log. ArchiveModel.h adds one archive file.

#include "phigs/Phigs.h"

#include <algorithm>
#include <climits>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace phigs::test {

using Contents = std::map<int, std::vector<Element>>;

inline const ExecuteStructureElement* executeOf(const Element& e) {
    return std::get_if<ExecuteStructureElement>(&e);
}

/// The execute edges (parent, child) of a set of structures, without repeats, for the cycle
/// checks: a few structures, so a sorted vector does.
struct Graph {
    std::vector<std::pair<int, int>> edges;

    void add(int parent, int child) {
        auto at = std::lower_bound(edges.begin(), edges.end(), std::make_pair(parent, child));
        if (at == edges.end() || *at != std::make_pair(parent, child)) edges.insert(at, {parent, child});
    }
    /// `to` executes what `from` executed, and `from` nothing.
    void moveChildren(int from, int to) {
        std::vector<std::pair<int, int>> old;
        old.swap(edges);
        for (auto [p, c] : old)
            if (p != to && p != from) add(p, c);
        for (auto [p, c] : old)
            if (p == from) add(to, c);
    }
    /// Every execute of `from` executes `to` instead.
    void redirect(int from, int to) {
        std::vector<std::pair<int, int>> old;
        old.swap(edges);
        for (auto [p, c] : old) add(p, c == from ? to : c);
    }
    bool reaches(int from, int to) const {
        std::vector<int> todo{from}, seen;
        while (!todo.empty()) {
            const int node = todo.back();
            todo.pop_back();
            if (node == to) return true;
            if (std::find(seen.begin(), seen.end(), node) != seen.end()) continue;
            seen.push_back(node);
            for (auto [p, c] : edges)
                if (p == node) todo.push_back(c);
        }
        return false;
    }
    /// Whether some structure executes itself, directly or not.
    bool cyclic() const {
        for (auto [p, c] : edges)
            if (reaches(c, p)) return true;
        return false;
    }
};

inline Graph graphOf(const Contents& contents) {
    Graph g;
    for (const auto& [id, elements] : contents)
        for (const auto& e : elements)
            if (auto x = executeOf(e)) g.add(id, x->structureId);
    return g;
}

/// The structure and everything it executes, directly or not (missing structures included).
inline std::set<int> networkOf(const Contents& contents, int id) {
    std::set<int> out;
    std::function<void(int)> visit = [&](int s) {
        if (!out.insert(s).second) return;
        if (auto it = contents.find(s); it != contents.end())
            for (const auto& e : it->second)
                if (auto x = executeOf(e)) visit(x->structureId);
    };
    visit(id);
    return out;
}

/// The depth cut of the path inquiries, then sorted without repeats.
inline std::vector<StructurePath> cutPaths(std::vector<StructurePath> paths, int depth, bool topFirst) {
    for (auto& p : paths)
        if (depth > 0 && static_cast<int>(p.size()) > depth) {
            if (topFirst)
                p.resize(static_cast<std::size_t>(depth));
            else
                p.erase(p.begin(), p.end() - depth);
        }
    std::sort(paths.begin(), paths.end());
    paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
    return paths;
}

/// Maximal paths down from `id`; a path has at least two references (PVT 02.01 SR5), so a
/// structure that executes nothing has none. Nothing when a cycle is reachable (an archive made
/// of structures archived at different times can hold one).
inline std::optional<std::vector<StructurePath>> descendantsOf(const Contents& contents, int id, int depth,
                                                               bool topFirst) {
    std::vector<StructurePath> out;
    bool cycle = false;
    std::function<void(int, StructurePath)> walk = [&](int s, StructurePath p) {
        for (const auto& ref : p) cycle = cycle || ref.structureId == s;
        if (cycle) return;
        bool leaf = true;
        if (auto it = contents.find(s); it != contents.end())
            for (std::size_t i = 0; i < it->second.size(); ++i)
                if (auto x = executeOf(it->second[i])) {
                    leaf = false;
                    StructurePath q = p;
                    q.push_back({s, static_cast<int>(i) + 1});
                    walk(x->structureId, q);
                }
        if (leaf && !p.empty()) {
            p.push_back({s, 0});
            out.push_back(p);
        }
    };
    walk(id, {});
    if (cycle) return std::nullopt;
    return cutPaths(std::move(out), depth, topFirst);
}

/// Maximal paths from a root down to `id`; none when nothing executes `id`; nothing when a
/// cycle is reachable upward.
inline std::optional<std::vector<StructurePath>> ancestorsOf(const Contents& contents, int id, int depth,
                                                             bool topFirst) {
    std::vector<StructurePath> out;
    bool cycle = false;
    std::function<void(StructurePath)> climb = [&](StructurePath up) {  // bottom first
        bool root = true;
        for (const auto& [parent, elements] : contents)
            for (std::size_t i = 0; i < elements.size() && !cycle; ++i)
                if (auto x = executeOf(elements[i]); x && x->structureId == up.back().structureId) {
                    root = false;
                    for (const auto& ref : up) cycle = cycle || ref.structureId == parent;
                    if (cycle) return;
                    StructurePath longer = up;
                    longer.push_back({parent, static_cast<int>(i) + 1});
                    climb(longer);
                }
        if (root && up.size() > 1) out.emplace_back(up.rbegin(), up.rend());
    };
    climb({{id, 0}});
    if (cycle) return std::nullopt;
    return cutPaths(std::move(out), depth, topFirst);
}

/// The structure store with its open structure, element pointer and edit mode, and the posting
/// lists of the workstations (in posting order).
struct StoreModel {
    Contents structures;
    std::optional<int> open;
    int pointer = 0;
    bool replace = false;
    std::map<int, std::vector<PostedStructure>> posted;
    int warning = 0;

    std::vector<Element>& current() { return structures.at(*open); }
    int count() { return static_cast<int>(current().size()); }
    bool wouldCycle(int parent, int child) const { return graphOf(structures).reaches(child, parent); }
    bool referenced(int id) const {
        for (const auto& [sid, elements] : structures)
            for (const auto& e : elements)
                if (auto x = executeOf(e); x && x->structureId == id) return true;
        return false;
    }
    bool isPosted(int id) const {
        for (const auto& [ws, list] : posted)
            for (const auto& p : list)
                if (p.structureId == id) return true;
        return false;
    }
    void unpostEverywhere(int id) {
        for (auto& [ws, list] : posted)
            std::erase_if(list, [&](const PostedStructure& p) { return p.structureId == id; });
    }

    int openStructure(int id) {
        if (open) return errors::NotStructureClosed;
        structures[id];
        open = id;
        pointer = count();
        return 0;
    }
    int closeStructure() {
        if (!open) return errors::NotStructureOpen;
        open.reset();
        pointer = 0;
        return 0;
    }
    int insert(const Element& e, bool valid) {
        if (!open) return errors::NotStructureOpen;
        if (!valid) return errors::InvalidElementData;
        if (auto x = executeOf(e)) {
            if (wouldCycle(*open, x->structureId)) return errors::StructureCycle;
            structures[x->structureId];
        }
        if (replace && pointer > 0) {
            current()[static_cast<std::size_t>(pointer - 1)] = e;
        } else {
            current().insert(current().begin() + pointer, e);
            ++pointer;
        }
        return 0;
    }
    int setPointer(int p) {
        if (!open) return errors::NotStructureOpen;
        pointer = std::clamp(p, 0, count());
        return 0;
    }
    int offsetPointer(int d) {
        if (!open) return errors::NotStructureOpen;
        pointer = static_cast<int>(std::clamp<long long>(static_cast<long long>(pointer) + d, 0, count()));
        return 0;
    }
    int labelPosition(int from, int value) {  // the first label `value` after position `from`, or 0
        for (int n = from + 1; n <= count(); ++n) {
            auto l = std::get_if<LabelElement>(&current()[static_cast<std::size_t>(n - 1)]);
            if (l && l->label == value) return n;
        }
        return 0;
    }
    int pointerAtLabel(int value) {
        if (!open) return errors::NotStructureOpen;
        int n = labelPosition(pointer, value);
        if (!n) return errors::LabelNotFound;
        pointer = n;
        return 0;
    }
    int deleteElement() {
        if (!open) return errors::NotStructureOpen;
        if (pointer > 0) {
            current().erase(current().begin() + pointer - 1);
            --pointer;
        }
        return 0;
    }
    int deleteRange(int a, int b) {
        if (!open) return errors::NotStructureOpen;
        int low = std::max(1, std::clamp(std::min(a, b), 0, count()));
        int high = std::clamp(std::max(a, b), 0, count());
        if (high < low) return 0;  // nothing deleted: the pointer stays (ISO 9592)
        current().erase(current().begin() + low - 1, current().begin() + high);
        pointer = low - 1;
        return 0;
    }
    int deleteBetweenLabels(int l1, int l2) {
        if (!open) return errors::NotStructureOpen;
        int a = labelPosition(pointer, l1);
        int b = a ? labelPosition(a, l2) : 0;
        if (!b) return errors::LabelsNotFound;
        current().erase(current().begin() + a, current().begin() + b - 1);
        pointer = a;
        return 0;
    }
    int copyAll(int id) {
        if (!open) return errors::NotStructureOpen;
        if (!structures.contains(id)) return 0;  // nothing to copy (ISO 9592)
        std::vector<Element> copies = structures.at(id);
        for (const auto& e : copies)
            if (auto x = executeOf(e); x && wouldCycle(*open, x->structureId)) return errors::StructureCycle;
        current().insert(current().begin() + pointer, copies.begin(), copies.end());
        pointer += static_cast<int>(copies.size());
        return 0;
    }
    int emptyStructure(int id) {
        structures[id].clear();  // creates a missing one (ISO 9592)
        if (open == id) pointer = 0;
        return 0;
    }
    void deleteOne(int id) {
        if (!structures.contains(id)) return;
        for (auto& [sid, elements] : structures)
            for (int i = static_cast<int>(elements.size()) - 1; i >= 0; --i)
                if (auto x = executeOf(elements[static_cast<std::size_t>(i)]); x && x->structureId == id) {
                    elements.erase(elements.begin() + i);
                    if (open == sid && i < pointer) --pointer;
                }
        unpostEverywhere(id);
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
    int deleteNetwork(int id, bool keep) {
        if (!structures.contains(id)) return 0;  // an empty network (ISO 9592)
        std::set<int> members = networkOf(structures, id), doomed;
        if (!keep) {
            doomed = members;
        } else {  // PVT 02.01.02.02: every member all of whose ancestor paths pass through `id`
            doomed = {id};
            const Graph g = graphOf(structures);
            for (bool grew = true; grew;) {
                grew = false;
                for (int m : members) {
                    if (doomed.contains(m)) continue;
                    bool all = true;
                    for (auto [p, c] : g.edges)
                        if (c == m && !doomed.contains(p)) all = false;
                    if (all) doomed.insert(m), grew = true;
                }
            }
        }
        for (int m : doomed) deleteOne(m);
        return 0;
    }
    int deleteAll() {
        structures.clear();
        for (auto& [ws, list] : posted) list.clear();
        if (open) structures[*open], pointer = 0;
        return 0;
    }

    // CHANGE STRUCTURE IDENTIFIER (PVT 02.01.03.01): a missing original counts as empty; the
    // original stays, empty, while open, referenced or posted.
    int changeIdentifier(int from, int to) {
        if (from == to) {
            structures[from];
            return 0;
        }
        Graph g = graphOf(structures);
        g.moveChildren(from, to);
        if (g.cyclic()) return errors::StructureCycle;
        std::vector<Element> moved;
        if (structures.contains(from)) moved = structures[from], structures[from].clear();
        structures[to] = moved;
        for (const auto& e : moved)
            if (auto x = executeOf(e)) structures[x->structureId];
        if (open == to) pointer = static_cast<int>(moved.size());
        if (open == from) pointer = 0;
        if (open != from && !referenced(from) && !isPosted(from)) structures.erase(from);
        return 0;
    }
    // CHANGE STRUCTURE REFERENCES (PVT 02.01.03.02): executes and postings of the original move to
    // the result, which keeps its own posting; nothing to move, nothing changes.
    int changeReferences(int from, int to) {
        if (from == to) return 0;
        Graph g = graphOf(structures);
        g.redirect(from, to);
        if (g.cyclic()) return errors::StructureCycle;
        if (!referenced(from) && !isPosted(from)) return 0;
        structures[to];
        for (auto& [id, elements] : structures)
            for (auto& e : elements)
                if (auto x = executeOf(e); x && x->structureId == from) e = ExecuteStructureElement{to};
        for (auto& [ws, list] : posted) {
            auto it = std::find_if(list.begin(), list.end(), [&](auto& p) { return p.structureId == from; });
            if (it == list.end()) continue;
            const double priority = it->priority;
            list.erase(it);
            if (std::none_of(list.begin(), list.end(), [&](auto& p) { return p.structureId == to; }))
                list.push_back({to, priority});
        }
        return 0;
    }
    int changeBoth(int from, int to) {
        if (from == to) {
            structures[from];
            return 0;
        }
        Graph g = graphOf(structures);
        g.moveChildren(from, to);
        g.redirect(from, to);
        if (g.cyclic()) return errors::StructureCycle;
        changeIdentifier(from, to);
        changeReferences(from, to);
        if (open != from) structures.erase(from);
        return 0;
    }

    int post(int ws, int id, double priority) {
        if (!(priority >= 0.0 && priority <= 1.0)) return errors::BadDisplayPriority;
        structures[id];
        auto& list = posted[ws];
        std::erase_if(list, [&](const PostedStructure& p) { return p.structureId == id; });
        list.push_back({id, priority});
        return 0;
    }
    int unpost(int ws, int id) {
        std::erase_if(posted[ws], [&](const PostedStructure& p) { return p.structureId == id; });
        return 0;
    }
    int unpostAll(int ws) {
        posted[ws].clear();
        return 0;
    }
    /// INQUIRE POSTED STRUCTURES: ascending priority, equal ones in posting order.
    std::vector<PostedStructure> postedOrder(int ws) const {
        std::vector<PostedStructure> order =
            posted.count(ws) ? posted.at(ws) : std::vector<PostedStructure>{};
        std::stable_sort(order.begin(), order.end(),
                         [](auto& a, auto& b) { return a.priority < b.priority; });
        return order;
    }
};

}  // namespace phigs::test
