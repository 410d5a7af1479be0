#include "phigs/pick/SpatialSearch.h"

#include "phigs/pick/LocusDistance.h"
#include "phigs/traverse/Traverser.h"

#include <algorithm>
#include <set>
#include <string>

namespace phigs {

namespace {

void checkStart(const StructureStore& store, const SpatialSearchQuery& q, const char* function) {
    auto fail = [&](std::size_t level, const std::string& why) {
        throw Error(errors::PathNotFound, function,
                    "start path level " + std::to_string(level + 1) + ": " + why);
    };
    if (q.start.empty()) throw Error(errors::PathNotFound, function, "empty start path");
    for (std::size_t i = 0; i < q.start.size(); ++i) {
        const ElementRef& r = q.start[i];
        if (!store.exists(r.structureId))
            fail(i, "structure " + std::to_string(r.structureId) + " does not exist");
        const int count = store.elementCount(r.structureId);
        const bool last = i + 1 == q.start.size();
        if (r.elementNumber < (last ? 0 : 1) || r.elementNumber > count)
            fail(i, "element " + std::to_string(r.elementNumber) + " not in structure " +
                        std::to_string(r.structureId));
        if (last) break;
        const auto* e =
            store.structure(r.structureId)
                .elements.get<ExecuteStructureElement>(static_cast<std::size_t>(r.elementNumber - 1));
        if (!e || e->structureId != q.start[i + 1].structureId)
            fail(i, "element " + std::to_string(r.elementNumber) + " does not execute structure " +
                        std::to_string(q.start[i + 1].structureId));
    }
    if (q.ceiling < 1 || q.ceiling > static_cast<int>(q.start.size()))
        throw Error(errors::CeilingOutOfRange, function,
                    "ceiling " + std::to_string(q.ceiling) + " outside 1.." + std::to_string(q.start.size()));
}

// In the search: after the start position in traversal order (a path below the start element
// was traversed in the setup), and inside the ceiling's structure.
bool searched(const std::vector<DrawPathLevel>& path, const SpatialSearchQuery& q) {
    const std::size_t fixed = static_cast<std::size_t>(q.ceiling - 1);
    if (path.size() <= fixed) return false;
    for (std::size_t i = 0; i < fixed; ++i)
        if (path[i].elementNumber != q.start[i].elementNumber) return false;
    for (std::size_t i = 0; i < path.size() && i < q.start.size(); ++i)
        if (path[i].elementNumber != q.start[i].elementNumber)
            return path[i].elementNumber > q.start[i].elementNumber;
    return false;
}

// The name set at a primitive: the names added and removed before each level's element.
std::set<int> namesAt(const StructureStore& store, const std::vector<DrawPathLevel>& path) {
    std::set<int> names;
    for (const DrawPathLevel& level : path) {
        const Structure& s = store.structure(level.structureId);
        for (int k = 1; k < level.elementNumber; ++k)
            if (const auto* n = s.elements.get<NameSetElement>(static_cast<std::size_t>(k - 1)))
                for (int name : n->names) n->add ? void(names.insert(name)) : void(names.erase(name));
    }
    return names;
}

bool passes(const std::set<int>& names, const SpatialSearchQuery& q) {
    return std::all_of(q.normal.begin(), q.normal.end(),
                       [&](const NameSetFilter& f) { return f.accepts(names); }) &&
           std::none_of(q.inverted.begin(), q.inverted.end(),
                        [&](const NameSetFilter& f) { return f.accepts(names); });
}

}  // namespace

StructurePath incrementalSpatialSearch(const StructureStore& store, const SpatialSearchQuery& query,
                                       const char* function) {
    checkStart(store, query, function);
    Traverser traverser;
    traverser.setIncremental(false);
    const DrawList list = traverser.traverse(store, {query.start.front().structureId}, WorkstationTables{});
    const double reach = std::max(query.distance, 0.0);
    for (const DrawItem& item : list.items) {
        const auto& path = item.source.path();
        if (!searched(path, query) || !(locusDistance(item, query.point, query.modelClip) <= reach)) continue;
        if (!passes(namesAt(store, path), query)) continue;
        StructurePath found;
        for (const DrawPathLevel& level : path) found.push_back({level.structureId, level.elementNumber});
        return found;
    }
    return {};
}

}  // namespace phigs
