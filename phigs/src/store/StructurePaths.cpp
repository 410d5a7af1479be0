#include "phigs/store/StructurePaths.h"

#include "phigs/core/Error.h"

#include <algorithm>
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

void collectDescendants(const ExecuteReferences& references, int id, StructurePath& path,
                        std::vector<StructurePath>& out, ErrorLog* log, const char* function) {
    if (path.size() > kMaxNetworkDepth)
        raise(log, errors::NetworkTooDeep, function,
              "more than " + std::to_string(kMaxNetworkDepth) + " levels");
    checkAcyclic(path, id, log, function);
    const auto it = references.find(id);
    if (it == references.end() || it->second.empty()) {
        path.push_back({id, 0});
        out.push_back(path);
        path.pop_back();
        return;
    }
    for (const auto& [elementNumber, child] : it->second) {
        path.push_back({id, elementNumber});
        collectDescendants(references, child, path, out, log, function);
        path.pop_back();
    }
}

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
    std::vector<StructurePath> out;
    // Walk upward, building paths bottom-up, then reverse each to top-first.
    std::vector<StructurePath> partial{{ElementRef{id, 0}}};
    while (!partial.empty()) {
        StructurePath p = std::move(partial.back());
        partial.pop_back();
        auto it = parents.find(p.back().structureId);
        if (it == parents.end()) {
            std::reverse(p.begin(), p.end());
            out.push_back(std::move(p));
            continue;
        }
        for (auto ref = it->second.rbegin(); ref != it->second.rend(); ++ref) {
            checkAcyclic(p, ref->structureId, log, function);
            StructurePath longer = p;
            longer.push_back(*ref);
            partial.push_back(std::move(longer));
        }
    }
    return truncateAndUnique(std::move(out), order, depth);
}

std::vector<StructurePath> descendantPaths(const ExecuteReferences& references, int id,
                                           StructurePathOrder order, int depth, ErrorLog* log,
                                           const char* function) {
    if (depth < 0) raise(log, errors::NegativePathDepth, function, "depth " + std::to_string(depth));
    // As for ancestors: a structure that executes nothing has no paths to descendants.
    const auto it = references.find(id);
    if (it == references.end() || it->second.empty()) return {};
    std::vector<StructurePath> out;
    StructurePath path;
    collectDescendants(references, id, path, out, log, function);
    return truncateAndUnique(std::move(out), order, depth);
}

}  // namespace phigs
