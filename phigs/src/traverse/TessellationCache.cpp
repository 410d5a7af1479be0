#include "phigs/traverse/TessellationCache.h"

#include <algorithm>

namespace phigs {

const TessellationCache::Entry* TessellationCache::find(const Key& key) {
    // A traversal asks in about serial order: the entry after the last one is tried first.
    auto it = last_ != entries_.end() ? std::next(last_) : entries_.end();
    if (it == entries_.end() || !(it->first == key)) it = entries_.find(key);
    if (it == entries_.end()) return nullptr;
    last_ = it;
    ++counters_.hits;
    it->second.used = true;
    return &it->second.entry;
}

const TessellationCache::Entry& TessellationCache::add(const Key& key, Kind kind, Entry entry) {
    ++builtSinceSweep_;
    switch (kind) {
        case Kind::Surface:
            ++counters_.surfacesTessellated;
            break;
        case Kind::Curve:
            ++counters_.curvesTessellated;
            break;
        case Kind::Mesh:
            ++counters_.meshesBuilt;
            break;
    }
    last_ = entries_.emplace(key, Slot{std::move(entry), true}).first;
    return last_->second.entry;
}

void TessellationCache::prune() {
    if (++prunesSinceSweep_ < kSweepEvery && builtSinceSweep_ * 8 <= keptBySweep_ + 64) return;
    builtSinceSweep_ = prunesSinceSweep_ = 0;
    last_ = entries_.end();  // it may go below
    for (auto it = entries_.begin(); it != entries_.end();) {
        const Entry& e = it->second.entry;
        // Entries still held by a draw list or a reused subtree stay, so their pointers stay valid
        // keys. A surface is the store's own (held by its element too): its mesh tells.
        bool held = e.mesh.use_count() > 1 ||
                    std::any_of(e.curveRuns.begin(), e.curveRuns.end(),
                                [](const CurveRun& run) { return run.curve.use_count() > 1; });
        if (!it->second.used && !held) {
            it = entries_.erase(it);
        } else {
            it->second.used = false;
            ++it;
        }
    }
    keptBySweep_ = entries_.size();
    std::erase_if(grids_, [](const auto& grid) { return grid.second.expired(); });
}

}  // namespace phigs
