#pragma once

#include "phigs/core/ErrorLog.h"
#include "phigs/store/Element.h"
#include "phigs/store/StructureStore.h"

#include <map>
#include <utility>
#include <vector>

namespace phigs {

/// Each structure's EXECUTE STRUCTURE elements as (element number, executed structure id), in
/// element order: all the path inquiries need of a network, in the store or in an archive.
using ExecuteReferences = std::map<int, std::vector<std::pair<int, int>>>;

/// The most references (structure, element number) a path inquiry collects, counted before
/// duplicates are removed; past it the inquiry raises StorageOverflow (900) rather than grow
/// without bound: a network of n chained diamonds has 2^n paths.
inline constexpr std::size_t kMaxPathReferences = std::size_t{1} << 22;

/// The execute references of a set of structures (an archive's contents).
ExecuteReferences executeReferences(const std::map<int, std::vector<Element>>& contents);

/// PATHS TO ANCESTORS: every path from a structure that nothing executes down to `id`, written
/// top first and ending (id, 0); cut to its last (BottomFirst) or first (TopFirst) `depth`
/// references when depth > 0; sorted, duplicates removed. A path has at least two references,
/// so a structure that nothing executes has none. A cyclic network (only a hand-made archive
/// can hold one) raises StructureCycle naming `function`; more than kMaxPathReferences
/// collected raises StorageOverflow. A BottomFirst cut stops the walk at `depth`, so the
/// answer's size, not the network's, bounds the work.
std::vector<StructurePath> ancestorPaths(const ExecuteReferences& references, int id,
                                         StructurePathOrder order, int depth, ErrorLog* log,
                                         const char* function);

/// PATHS TO DESCENDANTS: every path from `id` down to a structure that executes nothing, as
/// (structure, element number) references ending (leaf, 0), none when `id` executes nothing;
/// cut, sorted and checked as above (a TopFirst cut stops the walk at `depth`), and
/// NetworkTooDeep beyond kMaxNetworkDepth levels.
std::vector<StructurePath> descendantPaths(const ExecuteReferences& references, int id,
                                           StructurePathOrder order, int depth, ErrorLog* log,
                                           const char* function);

}  // namespace phigs
