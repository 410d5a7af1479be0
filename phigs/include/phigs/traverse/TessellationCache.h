#pragma once

#include "phigs/traverse/DrawList.h"

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace phigs {

/// Tessellations of curves, surfaces and meshes, keyed by the element's serial (which changes
/// whenever the element is inserted or replaced) and the parameters that shaped them. The same
/// key gives back the same shared pointers, so an edit re-tessellates only the elements it touched.
class TessellationCache {
public:
    TessellationCache() = default;
    TessellationCache(const TessellationCache&) = delete;  // last_ points into its own map
    TessellationCache& operator=(const TessellationCache&) = delete;

    struct Key {
        std::uint64_t serial = 0;
        int criteria = 0;
        double valueU = 0, valueV = 0;
        int isoStyle = 0, isoU = 0, isoV = 0;
        std::uint64_t colourGeneration =
            0;                              ///< meshes with indexed vertex colours depend on the colour table
        std::vector<double> levelPlanes{};  ///< level curves: their planes in modelling coordinates
        int isoPlacement = 0;               ///< 0 uniform, 1 non-uniform (at and between the knots)
        auto operator<=>(const Key&) const = default;
    };
    /// One continuous piece of a curve element as drawn: its exact curve, its polyline and the
    /// range drawn (equal ends: the whole curve).
    struct CurveRun {
        std::shared_ptr<const geom::Curve> curve;
        std::vector<glm::dvec3> points;
        double start = 0.0, end = 0.0;
    };
    struct Entry {
        std::shared_ptr<const MeshData> mesh;
        std::shared_ptr<const geom::Surface> surface;
        /// A curve's runs: one, or one per piece between the knots it breaks at (multiplicity
        /// degree + 1), so that no chord joins the ends of a jump.
        std::vector<CurveRun> curveRuns;
    };
    struct Counters {
        std::uint64_t surfacesTessellated = 0;
        std::uint64_t curvesTessellated = 0;
        std::uint64_t meshesBuilt = 0;  ///< triangle strips, quadrilateral meshes, cell arrays
        std::uint64_t hits = 0;
    };

    /// The cached entry for `key`, built with `build` (and counted under `kind`) when missing.
    enum class Kind { Surface, Curve, Mesh };
    template <class Build>
    const Entry& get(const Key& key, Kind kind, Build&& build) {
        if (const Entry* found = find(key)) return *found;
        return add(key, kind, build());
    }
    /// Forgets every entry not asked for since the previous sweep and held by no draw list
    /// (after each traversal). A sweep visits every entry, so it runs once enough entries were
    /// built or traversals passed to share its cost; until then an unused entry lingers.
    void prune();
    void clear() {
        entries_.clear();
        last_ = entries_.end();
        grids_.clear();
        builtSinceSweep_ = keptBySweep_ = prunesSinceSweep_ = 0;
    }

    /// The triangles of an untrimmed grid of `rows` x `columns` positions (two per cell, made by
    /// `build`), shared by every mesh on such a grid while one holds them.
    template <class Build>
    std::shared_ptr<const std::vector<std::uint32_t>> gridTriangles(std::uint32_t rows, std::uint32_t columns,
                                                                    Build&& build) {
        std::weak_ptr<const std::vector<std::uint32_t>>& slot = grids_[{rows, columns}];
        auto held = slot.lock();
        if (!held) slot = held = std::make_shared<const std::vector<std::uint32_t>>(build());
        return held;
    }

    const Counters& counters() const { return counters_; }
    void resetCounters() { counters_ = {}; }
    std::size_t size() const { return entries_.size(); }

private:
    const Entry* find(const Key& key);
    const Entry& add(const Key& key, Kind kind, Entry entry);

    struct Slot {
        Entry entry;
        bool used = true;
    };
    std::map<Key, Slot> entries_;  ///< ordered: a traversal asks in about serial order
    /// The entry found or added last (end: none): the next one asked for is mostly the one after.
    std::map<Key, Slot>::iterator last_ = entries_.end();
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::weak_ptr<const std::vector<std::uint32_t>>> grids_;
    Counters counters_;
    std::size_t builtSinceSweep_ = 0, keptBySweep_ = 0, prunesSinceSweep_ = 0;
    static constexpr std::size_t kSweepEvery = 16;
};

}  // namespace phigs
