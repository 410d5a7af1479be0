#pragma once

#include "phigs/traverse/DrawPath.h"
#include "phigs/traverse/ItemArray.h"
#include "phigs/traverse/ItemRef.h"

#include <cstdint>
#include <vector>

namespace phigs {

/// Where a draw item came from: the whole path from the posted root (top first), and the
/// version of the primitive's own structure (a renderer may cache per element and version).
/// What the items of one segment share (the levels above their structure, the structure and
/// its version) is a view of the segment's record, or a copy of its own; the element number
/// and pick id are the item's.
class DrawSource {
public:
    /// What the items of one structure's segment share about where they came from.
    struct Shared {
        std::vector<DrawPathLevel> prefix;  ///< the levels above the structure's own
        int structureId = 0;
        std::uint64_t structureVersion = 0;
        bool placed = false;  ///< false: no path at all (the default source)

        /// Sets every field, keeping the prefix's storage.
        void set(const std::vector<DrawPathLevel>& above, int structure, std::uint64_t version) {
            prefix.assign(above.begin(), above.end());
            structureId = structure, structureVersion = version, placed = true;
        }
    };

    /// No path, version 0.
    DrawSource() = default;
    /// A source of its own: `path` (empty, or with path.back() the primitive's own element).
    DrawSource(const std::vector<DrawPathLevel>& path, std::uint64_t structureVersion = 0) {  // NOLINT
        if (path.empty() && structureVersion == 0) return;
        Shared own;
        if (!path.empty()) {
            own.set({path.begin(), path.end() - 1}, path.back().structureId, structureVersion);
            elementNumber_ = path.back().elementNumber, pickId_ = path.back().pickId;
        } else {
            own.structureVersion = structureVersion;
        }
        shared_ = ItemRef<Shared>(std::move(own));
    }
    /// The item at `elementNumber` (with `pickId`) of the structure `shared` tells, a view of
    /// `shared`, which must outlive it (a segment's record).
    static DrawSource view(const Shared* shared, int elementNumber, int pickId) {
        DrawSource s;
        s.shared_ = ItemRef<Shared>::view(shared);
        s.elementNumber_ = elementNumber, s.pickId_ = pickId;
        return s;
    }

    /// The path, path.back() the primitive's own element: a view of this source, valid while it is.
    DrawPath path() const {
        const Shared& s = *shared_;
        if (!s.placed) return {};
        return DrawPath::below(ItemArray<DrawPathLevel>::view(s.prefix.data(), s.prefix.size()),
                               {s.structureId, elementNumber_, pickId_});
    }
    std::uint64_t structureVersion() const { return shared_->structureVersion; }
    /// Whether the shared part is a copy of its own (false: a view of a segment's record).
    bool owned() const { return shared_.owned(); }

private:
    // 16 bytes: a draw item holds one.
    ItemRef<Shared> shared_;
    std::int32_t elementNumber_ = 0, pickId_ = 0;
};

}  // namespace phigs
