#include "geom/BezierPatchTree.h"

#include "geom/Bezier.h"
#include "geom/BezierExtraction.h"
#include "geom/ControlNet.h"

#include <algorithm>
#include <span>

namespace geom {

BezierPatchTree::BezierPatchTree(const Surface& surface)
    : degreeU_(surface.degreeU), degreeV_(surface.degreeV) {
    validate(surface, "BezierPatchTree");
    const std::vector<BezierSurfacePiece> pieces = extractBezier(surface);
    patches_.reserve(pieces.size());
    BoundingBox all;
    for (const BezierSurfacePiece& piece : pieces) {
        Patch patch;
        patch.net = homogeneousNet(piece.surface, false).data;
        patch.box = boundingBox(piece.surface);
        patch.u0 = piece.u0;
        patch.u1 = piece.u1;
        patch.v0 = piece.v0;
        patch.v1 = piece.v1;
        all.add(patch.box);
        patches_.push_back(std::move(patch));
    }
    scale_ = std::max(all.diagonal(), 1e-300);
    // Pieces come u span slow, v span fast: a grid of spansU x spansV.
    std::size_t spansV = 1;
    while (spansV < pieces.size() && pieces[spansV].spanU == pieces[0].spanU) ++spansV;
    const std::size_t spansU = pieces.size() / spansV;
    for (std::size_t i = 0; i < spansU; ++i) breaksU_.push_back(patches_[i * spansV].u0);
    breaksU_.push_back(patches_.back().u1);
    for (std::size_t j = 0; j < spansV; ++j) breaksV_.push_back(patches_[j].v0);
    breaksV_.push_back(patches_.back().v1);
    nodes_.reserve(2 * pieces.size());
    build(0, spansU, 0, spansV, spansV);
}

BezierPatchTree::PatchPoint BezierPatchTree::evaluate(std::size_t index, double u, double v,
                                                      int order) const {
    const Patch& patch = patches_[index];
    const std::size_t pu = static_cast<std::size_t>(degreeU_) + 1,
                      qv = static_cast<std::size_t>(degreeV_) + 1;
    thread_local std::vector<double> bs, dbs, ddbs, bt, dbt, ddbt;
    bs.resize(pu);
    dbs.resize(pu);
    ddbs.resize(pu);
    bt.resize(qv);
    dbt.resize(qv);
    ddbt.resize(qv);
    const double du = 1.0 / (patch.u1 - patch.u0), dv = 1.0 / (patch.v1 - patch.v0);
    const double s = std::clamp((u - patch.u0) * du, 0.0, 1.0), t = std::clamp((v - patch.v0) * dv, 0.0, 1.0);
    const bool first = order >= 1, second = order >= 2;
    bernsteinBasis(degreeU_, s, bs, first ? std::span<double>(dbs) : std::span<double>(),
                   second ? std::span<double>(ddbs) : std::span<double>());
    bernsteinBasis(degreeV_, t, bt, first ? std::span<double>(dbt) : std::span<double>(),
                   second ? std::span<double>(ddbt) : std::span<double>());
    glm::dvec4 h(0.0), hu(0.0), hv(0.0), huu(0.0), huv(0.0), hvv(0.0);
    for (std::size_t i = 0; i < pu; ++i) {
        glm::dvec4 row(0.0), rowd(0.0), rowdd(0.0);
        const glm::dvec4* net = patch.net.data() + i * qv;
        for (std::size_t j = 0; j < qv; ++j) {
            row += bt[j] * net[j];
            if (first) rowd += dbt[j] * net[j];
            if (second) rowdd += ddbt[j] * net[j];
        }
        h += bs[i] * row;
        if (first) {
            hu += dbs[i] * row;
            hv += bs[i] * rowd;
        }
        if (second) {
            huu += ddbs[i] * row;
            huv += dbs[i] * rowd;
            hvv += bs[i] * rowdd;
        }
    }
    PatchPoint r{};
    r.point = glm::dvec3(h) / h.w;
    if (!first) return r;
    hu *= du;
    hv *= dv;
    huu *= du * du;
    huv *= du * dv;
    hvv *= dv * dv;
    const double w = h.w;
    r.su = (glm::dvec3(hu) - hu.w * r.point) / w;
    r.sv = (glm::dvec3(hv) - hv.w * r.point) / w;
    if (!second) return r;
    r.suu = (glm::dvec3(huu) - 2.0 * hu.w * r.su - huu.w * r.point) / w;
    r.suv = (glm::dvec3(huv) - hu.w * r.sv - hv.w * r.su - huv.w * r.point) / w;
    r.svv = (glm::dvec3(hvv) - 2.0 * hv.w * r.sv - hvv.w * r.point) / w;
    return r;
}

std::size_t BezierPatchTree::patchAt(double u, double v) const {
    auto interval = [](const std::vector<double>& breaks, double x) -> std::size_t {
        const auto it = std::upper_bound(breaks.begin() + 1, breaks.end() - 1, x);
        return static_cast<std::size_t>(it - breaks.begin()) - 1;
    };
    return interval(breaksU_, u) * (breaksV_.size() - 1) + interval(breaksV_, v);
}

int BezierPatchTree::build(std::size_t iu0, std::size_t iu1, std::size_t iv0, std::size_t iv1,
                           std::size_t countV) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    if (iu1 - iu0 == 1 && iv1 - iv0 == 1) {
        const std::size_t patch = iu0 * countV + iv0;
        nodes_[static_cast<std::size_t>(index)].patch = static_cast<int>(patch);
        nodes_[static_cast<std::size_t>(index)].box = patches_[patch].box;
        return index;
    }
    int a, b;
    if (iu1 - iu0 >= iv1 - iv0) {
        const std::size_t mid = (iu0 + iu1) / 2;
        a = build(iu0, mid, iv0, iv1, countV);
        b = build(mid, iu1, iv0, iv1, countV);
    } else {
        const std::size_t mid = (iv0 + iv1) / 2;
        a = build(iu0, iu1, iv0, mid, countV);
        b = build(iu0, iu1, mid, iv1, countV);
    }
    Node& node = nodes_[static_cast<std::size_t>(index)];
    node.first = a;
    node.second = b;
    node.box = nodes_[static_cast<std::size_t>(a)].box;
    node.box.add(nodes_[static_cast<std::size_t>(b)].box);
    return index;
}

}  // namespace geom
