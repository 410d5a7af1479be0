#include "phigs/store/StructurePaths.h"

#include "phigs/core/Error.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <set>
#include <string>

namespace phigs {
namespace {

// Sorted after the cut, so BottomFirst results are sorted too.
std::vector<StructurePath> truncateAndUnique(std::vector<StructurePath> paths, StructurePathOrder order,
                                             int depth) {
    if (depth > 0)
        for (auto& p : paths)
            if (static_cast<int>(p.size()) > depth) {
                if (order == StructurePathOrder::TopFirst)
                    p.resize(static_cast<std::size_t>(depth));
                else
                    p.erase(p.begin(), p.end() - depth);
            }
    std::sort(paths.begin(), paths.end());
    paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
    return paths;
}

// Only a hand-made archive can hold a cyclic network (the store refuses one).
void checkAcyclic(const StructurePath& path, int id, ErrorLog* log, const char* function) {
    for (const ElementRef& ref : path)
        if (ref.structureId == id)
            raise(log, errors::StructureCycle, function,
                  "structure " + std::to_string(id) + " executes itself through its descendants");
}

// Raises StructureCycle when a cycle is reachable from `id` through `edges` (children or
// parents): a cut walk may stop before it meets one, and the answer must not depend on the cut.
// Colours every structure once, so the check is linear in the network.
template <class Edges, class Next>
void checkReachableAcyclic(const Edges& edges, int id, Next next, ErrorLog* log, const char* function) {
    enum class Colour { OnPath, Done };
    std::map<int, Colour> colour;
    // (structure, index of the next edge to follow)
    std::vector<std::pair<int, std::size_t>> stack{{id, 0}};
    colour[id] = Colour::OnPath;
    while (!stack.empty()) {
        auto& [at, edge] = stack.back();
        const auto it = edges.find(at);
        if (it == edges.end() || edge == it->second.size()) {
            colour[at] = Colour::Done;
            stack.pop_back();
            continue;
        }
        const int to = next(it->second[edge++]);
        const auto seen = colour.find(to);
        if (seen == colour.end()) {
            colour[to] = Colour::OnPath;
            stack.emplace_back(to, 0);
        } else if (seen->second == Colour::OnPath) {
            raise(log, errors::StructureCycle, function,
                  "structure " + std::to_string(to) + " executes itself through its descendants");
        }
    }
}

// Counts the references an inquiry collects, so that an answer past kMaxPathReferences is
// refused before it exhausts memory or time.
class PathCollector {
public:
    PathCollector(ErrorLog* log, const char* function) : log_(log), function_(function) {}

    void add(StructurePath path) {
        collected_ += path.size();
        if (collected_ > kMaxPathReferences)
            raise(log_, errors::StorageOverflow, function_,
                  "more than " + std::to_string(kMaxPathReferences) + " path references");
        paths_.push_back(std::move(path));
    }
    std::vector<StructurePath> take() { return std::move(paths_); }
    ErrorLog* log() const { return log_; }
    const char* function() const { return function_; }

private:
    ErrorLog* log_;
    const char* function_;
    std::size_t collected_ = 0;
    std::vector<StructurePath> paths_;
};

// `cut`: the length at which a TopFirst answer is complete (0: none).
void collectDescendants(const ExecuteReferences& references, int id, StructurePath& path, std::size_t cut,
                        PathCollector& out) {
    if (path.size() > kMaxNetworkDepth)
        raise(out.log(), errors::NetworkTooDeep, out.function(),
              "more than " + std::to_string(kMaxNetworkDepth) + " levels");
    checkAcyclic(path, id, out.log(), out.function());
    if (cut > 0 && path.size() == cut) {
        out.add(path);
        return;
    }
    const auto it = references.find(id);
    if (it == references.end() || it->second.empty()) {
        path.push_back({id, 0});
        out.add(path);
        path.pop_back();
        return;
    }
    for (const auto& [elementNumber, child] : it->second) {
        path.push_back({id, elementNumber});
        collectDescendants(references, child, path, cut, out);
        path.pop_back();
    }
}

// The structures reachable from `id` through `edges` (children or parents), `id` among them.
template <class Edges, class Next>
std::set<int> reachable(const Edges& edges, int id, Next next) {
    std::set<int> seen{id};
    std::vector<int> todo{id};
    while (!todo.empty()) {
        const auto it = edges.find(todo.back());
        todo.pop_back();
        if (it == edges.end()) continue;
        for (const auto& edge : it->second)
            if (seen.insert(next(edge)).second) todo.push_back(next(edge));
    }
    return seen;
}

// Ancestor paths cut TopFirst at `depth` > 0, without the whole paths: from each structure
// nothing executes, down through ancestors of `id` only, each prefix complete at `depth`
// references or at `id`. Every prefix walked is part of an answer, so the answer bounds the work.
class TopPrefixes {
public:
    TopPrefixes(const ExecuteReferences& references, const std::set<int>& above, int id, std::size_t depth,
                PathCollector& out)
        : references_(references), above_(above), id_(id), depth_(depth), out_(out) {}

    void from(int structure) {
        if (path_.size() > kMaxNetworkDepth)
            raise(out_.log(), errors::NetworkTooDeep, out_.function(),
                  "more than " + std::to_string(kMaxNetworkDepth) + " levels");
        if (structure == id_) {
            path_.push_back({id_, 0});
            out_.add(path_);
            path_.pop_back();
            return;
        }
        const auto it = references_.find(structure);
        if (it == references_.end()) return;
        for (const auto& [elementNumber, child] : it->second) {
            if (!above_.contains(child)) continue;
            path_.push_back({structure, elementNumber});
            if (path_.size() == depth_)
                out_.add(path_);
            else
                from(child);
            path_.pop_back();
        }
    }

private:
    const ExecuteReferences& references_;
    const std::set<int>& above_;
    int id_;
    std::size_t depth_;
    PathCollector& out_;
    StructurePath path_;
};

// Descendant paths cut BottomFirst at `depth` > 0, the mirror of TopPrefixes: from each leaf
// below `id`, up through its descendants only, each suffix complete at `depth` references or
// at `id`.
class BottomSuffixes {
public:
    BottomSuffixes(const std::map<int, std::vector<ElementRef>>& parents, int id, std::size_t depth,
                   PathCollector& out)
        : parents_(parents), id_(id), depth_(depth), out_(out) {}

    void fromLeaf(int leaf) {
        reversed_.push_back({leaf, 0});
        up(leaf);
        reversed_.pop_back();
    }

private:
    void up(int structure) {
        if (reversed_.size() > kMaxNetworkDepth)
            raise(out_.log(), errors::NetworkTooDeep, out_.function(),
                  "more than " + std::to_string(kMaxNetworkDepth) + " levels");
        if (reversed_.size() == depth_ || structure == id_) {
            out_.add(StructurePath(reversed_.rbegin(), reversed_.rend()));
            return;
        }
        const auto it = parents_.find(structure);
        if (it == parents_.end()) return;
        for (const ElementRef& ref : it->second) {
            reversed_.push_back(ref);
            up(ref.structureId);
            reversed_.pop_back();
        }
    }

    const std::map<int, std::vector<ElementRef>>& parents_;
    int id_;
    std::size_t depth_;
    PathCollector& out_;
    StructurePath reversed_;
};

}  // namespace

ExecuteReferences executeReferences(const std::map<int, std::vector<Element>>& contents) {
    ExecuteReferences references;
    for (const auto& [id, elements] : contents) {
        auto& refs = references[id];
        for (std::size_t i = 0; i < elements.size(); ++i)
            if (const auto* x = std::get_if<ExecuteStructureElement>(&elements[i]))
                refs.emplace_back(static_cast<int>(i) + 1, x->structureId);
    }
    return references;
}

std::vector<StructurePath> ancestorPaths(const ExecuteReferences& references, int id,
                                         StructurePathOrder order, int depth, ErrorLog* log,
                                         const char* function) {
    if (depth < 0) raise(log, errors::NegativePathDepth, function, "depth " + std::to_string(depth));
    // parents[child]: every (parent, element number) executing it.
    std::map<int, std::vector<ElementRef>> parents;
    for (const auto& [parent, refs] : references)
        for (const auto& [elementNumber, child] : refs) parents[child].push_back({parent, elementNumber});
    // A path is at least two references (ISO 9592 defect 066, NIST PVT 02.01 SR5): a structure
    // that nothing executes has no paths to ancestors.
    if (!parents.contains(id)) return {};
    checkReachableAcyclic(
        parents, id, [](const ElementRef& r) { return r.structureId; }, log, function);
    PathCollector out(log, function);
    if (order == StructurePathOrder::TopFirst && depth > 0) {
        const std::set<int> above = reachable(parents, id, [](const ElementRef& r) { return r.structureId; });
        TopPrefixes prefixes(references, above, id, static_cast<std::size_t>(depth), out);
        for (int structure : above)
            if (!parents.contains(structure)) prefixes.from(structure);
        return truncateAndUnique(out.take(), order, depth);
    }
    // A BottomFirst answer is complete once it holds `depth` references.
    const std::size_t cut = order == StructurePathOrder::BottomFirst ? static_cast<std::size_t>(depth) : 0;
    // Walk upward, building paths bottom-up, then reverse each to top-first.
    std::vector<StructurePath> partial{{ElementRef{id, 0}}};
    while (!partial.empty()) {
        StructurePath p = std::move(partial.back());
        partial.pop_back();
        auto it = parents.find(p.back().structureId);
        if (it == parents.end() || (cut > 0 && p.size() == cut)) {
            std::reverse(p.begin(), p.end());
            out.add(std::move(p));
            continue;
        }
        for (auto ref = it->second.rbegin(); ref != it->second.rend(); ++ref) {
            checkAcyclic(p, ref->structureId, log, function);
            StructurePath longer = p;
            longer.push_back(*ref);
            partial.push_back(std::move(longer));
        }
    }
    return truncateAndUnique(out.take(), order, depth);
}

std::vector<StructurePath> descendantPaths(const ExecuteReferences& references, int id,
                                           StructurePathOrder order, int depth, ErrorLog* log,
                                           const char* function) {
    if (depth < 0) raise(log, errors::NegativePathDepth, function, "depth " + std::to_string(depth));
    // As for ancestors: a structure that executes nothing has no paths to descendants.
    const auto it = references.find(id);
    if (it == references.end() || it->second.empty()) return {};
    checkReachableAcyclic(
        references, id, [](const std::pair<int, int>& r) { return r.second; }, log, function);
    PathCollector out(log, function);
    if (order == StructurePathOrder::BottomFirst && depth > 0) {
        const std::set<int> below =
            reachable(references, id, [](const std::pair<int, int>& r) { return r.second; });
        std::map<int, std::vector<ElementRef>> parents;
        for (int parent : below)
            if (const auto refs = references.find(parent); refs != references.end())
                for (const auto& [elementNumber, child] : refs->second)
                    parents[child].push_back({parent, elementNumber});
        BottomSuffixes suffixes(parents, id, static_cast<std::size_t>(depth), out);
        for (int structure : below)
            if (const auto refs = references.find(structure);
                refs == references.end() || refs->second.empty())
                suffixes.fromLeaf(structure);
        return truncateAndUnique(out.take(), order, depth);
    }
    const std::size_t cut = order == StructurePathOrder::TopFirst ? static_cast<std::size_t>(depth) : 0;
    StructurePath path;
    collectDescendants(references, id, path, cut, out);
    return truncateAndUnique(out.take(), order, depth);
}

}  // namespace phigs
