#include "phigs/pick/PickBoundsTree.h"

#include "phigs/core/TransformUtilities.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace phigs {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::uint32_t leafSize = 4;

void grow(glm::dvec3& lo, glm::dvec3& hi, const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

template <typename Points>
void growAll(glm::dvec3& lo, glm::dvec3& hi, const Points& points) {
    for (const auto& p : points) grow(lo, hi, glm::dvec3(p));
}

}  // namespace

PickBoundsTree::PickBoundsTree() = default;
PickBoundsTree::~PickBoundsTree() = default;

void PickBoundsTree::clear() {
    items_.clear();
    keys_.clear();
    views_.clear();
    nodes_.clear();
    order_.clear();
    leafOf_.clear();
    parent_.clear();
    unbounded_.clear();
    boxes_.clear();
    list_ = nullptr;
    data_ = nullptr;
    generation_ = 0;
}

bool PickBoundsTree::unchanged(const DrawList& list) const {
    return list.generation != 0 && &list == list_ && list.items.segments().data() == data_ &&
           list.generation == generation_ && list.items.size() == items_.size();
}

PickBoundsTree::Key PickBoundsTree::keyOf(const DrawItem& item) const {
    Key key;
    key.pickable = item.pickable();
    if (!item.pickable()) return key;
    key.view = item.viewIndex();
    key.transform = item.modelTransform().get();
    if (const auto* mesh = primitiveIf<DrawMesh>(item.primitive)) {
        key.geometry = mesh->surface.get();
        key.mesh = mesh->mesh.get();
    }
    return key;
}

const PickBoundsTree::CachedBox& PickBoundsTree::cachedBox(const std::shared_ptr<const void>& geometry,
                                                           const std::vector<glm::dvec3>& pts) {
    auto it = boxes_.find(geometry.get());
    if (it != boxes_.end()) return it->second;
    CachedBox box{geometry, glm::dvec3(infinity), glm::dvec3(-infinity), pass_};
    growAll(box.lo, box.hi, pts);
    return boxes_.emplace(geometry.get(), std::move(box)).first->second;
}

bool PickBoundsTree::modellingBox(const DrawItem& item, glm::dvec3& lo, glm::dvec3& hi, glm::dvec3& surfaceLo,
                                  glm::dvec3& surfaceHi) {
    lo = glm::dvec3(infinity);
    hi = glm::dvec3(-infinity);
    bool bounded = true;
    visitPrimitive(
        [&](const auto& p) {
            using T = std::decay_t<decltype(p)>;
            if constexpr (kDrawsStrip<T>) {
                growAll(lo, hi, stripPoints(p));
            } else if constexpr (std::is_same_v<T, DrawFillArea>) {
                for (const auto& contour : p.contours) growAll(lo, hi, contour);
            } else if constexpr (std::is_same_v<T, DrawMesh>) {
                // The control net holds the surface (convex hull property, positive weights).
                if (p.surface) {
                    const CachedBox& b = cachedBox(p.surface, p.surface->points);
                    grow(lo, hi, b.lo);
                    grow(lo, hi, b.hi);
                    surfaceLo = b.lo;
                    surfaceHi = b.hi;
                }
                if (p.mesh) {
                    auto it = boxes_.find(p.mesh.get());
                    if (it == boxes_.end()) {
                        CachedBox b{p.mesh, glm::dvec3(infinity), glm::dvec3(-infinity), pass_};
                        growAll(b.lo, b.hi, p.mesh->positions);
                        it = boxes_.emplace(p.mesh.get(), std::move(b)).first;
                    }
                    grow(lo, hi, it->second.lo);
                    grow(lo, hi, it->second.hi);
                }
            } else if constexpr (std::is_same_v<T, DrawPolymarker> || std::is_same_v<T, DrawText>) {
                // Markers grow with the marker size and the surface's pixels, annotation text lives
                // in NPC: such items are tested at every pick.
                bounded = false;
            } else {
                static_assert(kUnhandledPrimitive<T>);
            }
        },
        item.primitive);
    return bounded;
}

PickItemBounds PickBoundsTree::boundsOf(const DrawList& list, const DrawItem& item) {
    PickItemBounds b;
    if (!item.pickable() || item.viewIndex() < 0 ||
        static_cast<std::size_t>(item.viewIndex()) >= list.views.size())
        return b;
    b.tested = true;
    b.toNpc = views_[static_cast<std::size_t>(item.viewIndex())] * item.modelTransform().get();
    b.fromNpc = glm::inverse(b.toNpc);
    b.lo = glm::dvec3(-infinity);
    b.hi = glm::dvec3(infinity);
    ++stats_.boxes;
    glm::dvec3 lo, hi;
    if (!modellingBox(item, lo, hi, b.surfaceLo, b.surfaceHi)) return b;
    // Rounding of the exact hit: a surface point may land a few ulps outside its net's box.
    if (b.surfaceLo.x <= b.surfaceHi.x) {
        const glm::dvec3 pad = 1e-9 * (glm::dvec3(1e-300) + glm::abs(b.surfaceLo) + glm::abs(b.surfaceHi));
        b.surfaceLo -= pad;
        b.surfaceHi += pad;
    }
    if (lo.x > hi.x) {  // no points at all: nothing to hit, but the exact test decides
        b.lo = b.hi = glm::dvec3(0.0);
        b.bounded = true;
        return b;
    }
    glm::dvec3 nlo(infinity), nhi(-infinity);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 c((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                           (corner & 4) ? hi.z : lo.z);
        const glm::dvec4 h = b.toNpc * glm::dvec4(c, 1.0);
        // A corner at or behind the eye of a perspective view: the box says nothing.
        if (!(h.w > 1e-300)) return b;
        grow(nlo, nhi, glm::dvec3(h) / h.w);
    }
    if (!allFinite(nlo) || !allFinite(nhi)) return b;
    // Rounding of the projection: a hit point on the surface may land a few ulps outside.
    const glm::dvec3 pad = 1e-9 * (glm::dvec3(1.0) + glm::abs(nlo) + glm::abs(nhi) + (nhi - nlo));
    b.lo = nlo - pad;
    b.hi = nhi + pad;
    // A fill area's depth comes from the plane fitted to its contours, which a contour that is
    // not quite planar may put in front of every vertex: no depth bound for those.
    if (holdsPrimitive<DrawFillArea>(item.primitive)) b.hi.z = infinity;
    b.bounded = true;
    return b;
}

void PickBoundsTree::update(const DrawList& list) {
    if (unchanged(list)) return;
    ++stats_.updates;
    // A changed view moves every item in it.
    std::vector<glm::dmat4> views;
    views.reserve(list.views.size());
    for (const DrawView& v : list.views) views.push_back(v.mapping * v.orientation);
    std::vector<bool> viewMoved(views.size(), true);
    for (std::size_t v = 0; v < views.size() && v < views_.size(); ++v) viewMoved[v] = views[v] != views_[v];
    views_ = std::move(views);

    const std::size_t n = list.items.size();
    const bool sameCount = n == items_.size() && !nodes_.empty();
    std::vector<std::size_t> changed;
    bool boundedness = false;  // an item moved in or out of the tree: rebuild
    items_.resize(n);
    keys_.resize(n);
    ++pass_;
    for (std::size_t i = 0; i < n; ++i) {
        const DrawItem& item = list.items[i];
        Key key = keyOf(item);
        for (const void* g : {key.geometry, key.mesh})
            if (g)
                if (auto it = boxes_.find(g); it != boxes_.end()) it->second.pass = pass_;
        const bool inView = key.view >= 0 && static_cast<std::size_t>(key.view) < viewMoved.size();
        // Items with shared geometry keep their box while key and view stay; inline points are
        // measured again (they may have changed under the same path).
        const bool keep = sameCount && key == keys_[i] &&
                          (!key.pickable || (inView && !viewMoved[static_cast<std::size_t>(key.view)] &&
                                             (key.geometry || key.mesh)));
        if (keep) continue;
        const PickItemBounds before = items_[i];
        items_[i] = boundsOf(list, item);
        keys_[i] = key;
        const PickItemBounds& after = items_[i];
        if (after.tested != before.tested || after.bounded != before.bounded) boundedness = true;
        if (after.lo != before.lo || after.hi != before.hi) changed.push_back(i);
    }
    if (!sameCount || boundedness || changed.size() * 4 > n) {
        rebuild();
    } else if (!changed.empty()) {
        refit(changed);
    }
    // Boxes of geometry this list no longer holds go (and with them the last hold on it).
    std::erase_if(boxes_, [&](const auto& e) { return e.second.pass != pass_; });
    list_ = &list;
    data_ = list.items.segments().data();
    generation_ = list.generation;
}

void PickBoundsTree::rebuild() {
    ++stats_.rebuilds;
    nodes_.clear();
    order_.clear();
    unbounded_.clear();
    leafOf_.assign(items_.size(), 0);
    for (std::size_t i = 0; i < items_.size(); ++i) {
        if (!items_[i].tested) continue;
        if (items_[i].bounded)
            order_.push_back(static_cast<std::uint32_t>(i));
        else
            unbounded_.push_back(i);
    }
    nodes_.reserve(2 * order_.size() / leafSize + 2);
    nodes_.emplace_back();
    parent_.assign(1, 0);
    if (order_.empty()) {
        nodes_[0].lo = glm::dvec2(infinity);
        nodes_[0].hi = glm::dvec2(-infinity);
        return;
    }
    build();
}

/// Builds the tree over order_ from the root down: each node splits its items at the median
/// centre along the longer side of their centres' box, down to leaves of a few items.
void PickBoundsTree::build() {
    struct Range {
        std::uint32_t node, begin, end;
    };
    std::vector<Range> stack{{0, 0, static_cast<std::uint32_t>(order_.size())}};
    while (!stack.empty()) {
        const Range r = stack.back();
        stack.pop_back();
        glm::dvec2 lo(infinity), hi(-infinity), clo(infinity), chi(-infinity);
        for (std::uint32_t s = r.begin; s < r.end; ++s) {
            const PickItemBounds& b = items_[order_[s]];
            lo = glm::min(lo, glm::dvec2(b.lo));
            hi = glm::max(hi, glm::dvec2(b.hi));
            const glm::dvec2 c = 0.5 * (glm::dvec2(b.lo) + glm::dvec2(b.hi));
            clo = glm::min(clo, c);
            chi = glm::max(chi, c);
        }
        nodes_[r.node].lo = lo;
        nodes_[r.node].hi = hi;
        if (r.end - r.begin <= leafSize) {
            nodes_[r.node].first = r.begin;
            nodes_[r.node].count = r.end - r.begin;
            for (std::uint32_t s = r.begin; s < r.end; ++s) leafOf_[order_[s]] = r.node;
            continue;
        }
        const int axis = (chi.x - clo.x) >= (chi.y - clo.y) ? 0 : 1;
        const std::uint32_t mid = r.begin + (r.end - r.begin) / 2;
        std::nth_element(order_.begin() + r.begin, order_.begin() + mid, order_.begin() + r.end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             return items_[a].lo[axis] + items_[a].hi[axis] <
                                    items_[b].lo[axis] + items_[b].hi[axis];
                         });
        const auto left = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        nodes_.emplace_back();
        parent_.push_back(r.node);
        parent_.push_back(r.node);
        nodes_[r.node].first = left;
        nodes_[r.node].count = 0;
        stack.push_back({left, r.begin, mid});
        stack.push_back({left + 1, mid, r.end});
    }
}

void PickBoundsTree::refit(const std::vector<std::size_t>& changed) {
    ++stats_.refits;
    for (std::size_t i : changed) {
        if (!items_[i].tested || !items_[i].bounded) continue;
        std::uint32_t node = leafOf_[i];
        while (true) {
            Node& n = nodes_[node];
            glm::dvec2 lo(infinity), hi(-infinity);
            if (n.count > 0) {
                for (std::uint32_t s = n.first; s < n.first + n.count; ++s) {
                    lo = glm::min(lo, glm::dvec2(items_[order_[s]].lo));
                    hi = glm::max(hi, glm::dvec2(items_[order_[s]].hi));
                }
            } else {
                lo = glm::min(nodes_[n.first].lo, nodes_[n.first + 1].lo);
                hi = glm::max(nodes_[n.first].hi, nodes_[n.first + 1].hi);
            }
            if (lo == n.lo && hi == n.hi && node != leafOf_[i]) break;
            n.lo = lo;
            n.hi = hi;
            if (node == 0) break;
            node = parent_[node];
        }
    }
}

void PickBoundsTree::query(glm::dvec2 npc, double half, std::vector<std::size_t>& out) const {
    const glm::dvec2 qlo = npc - glm::dvec2(half), qhi = npc + glm::dvec2(half);
    auto meets = [&](const glm::dvec2& lo, const glm::dvec2& hi) {
        return !(hi.x < qlo.x || lo.x > qhi.x || hi.y < qlo.y || lo.y > qhi.y);
    };
    if (!nodes_.empty() && !order_.empty()) {
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& n = nodes_[stack[--top]];
            if (!meets(n.lo, n.hi)) continue;
            if (n.count > 0) {
                for (std::uint32_t s = n.first; s < n.first + n.count; ++s) {
                    const PickItemBounds& b = items_[order_[s]];
                    if (meets(glm::dvec2(b.lo), glm::dvec2(b.hi))) out.push_back(order_[s]);
                }
            } else {
                stack[top++] = n.first;
                stack[top++] = n.first + 1;
            }
        }
    }
    out.insert(out.end(), unbounded_.begin(), unbounded_.end());
}

}  // namespace phigs
