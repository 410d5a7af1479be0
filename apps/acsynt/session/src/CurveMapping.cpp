#include "acsynt/session/CurveMapping.h"

#include "geom/GeometryError.h"
#include "geom/curvemap/FacingDomain.h"

#include <optional>

namespace acsynt {

namespace {

std::size_t walksOf(const geom::curvemap::MappedPart& part) {
    std::size_t walks = 0;
    for (const auto& loop : part.loops) walks += loop.boundaryWalks;
    return walks;
}

/// The first issue that says why a part was not mapped.
std::string reasonOf(const geom::curvemap::MappedPart& part) {
    return part.issues.empty() ? std::string("no loop came out") : part.issues.front();
}

bool missesSurface(const geom::curvemap::MappedPart& part) {
    for (const std::string& issue : part.issues)
        if (issue.find("misses the surface") != std::string::npos ||
            issue.find("is not closed") != std::string::npos)
            return true;
    return false;
}

}  // namespace

const char* outcomeName(PartOutcome outcome) {
    switch (outcome) {
        case PartOutcome::Mapped:
            return "MAPPED";
        case PartOutcome::Clipped:
            return "CLIPPED";
        case PartOutcome::Lost:
            break;
    }
    return "LOST";
}

std::string partsNotice(const std::vector<PartReport>& parts) {
    std::string clipped, lost;
    for (const PartReport& p : parts) {
        if (p.outcome == PartOutcome::Clipped) clipped += (clipped.empty() ? "" : ", ") + p.name;
        if (p.outcome != PartOutcome::Lost) continue;
        const std::string why = p.reason.find("misses the surface") != std::string::npos
                                    ? "MISSES THE SURFACE"
                                : p.reason.find("not closed") != std::string::npos ? "NOT CLOSED"
                                : p.reason.find("silhouette") != std::string::npos ? "LEAVES AT A SILHOUETTE"
                                                                                   : "NOT MAPPED";
        lost += (lost.empty() ? "" : ", ") + p.name + " (" + why + ")";
    }
    std::string out;
    if (!clipped.empty()) out += ", CLIPPED: " + clipped;
    if (!lost.empty()) out += "; LOST: " + lost;
    return out;
}

ComponentMapping mapOnComponent(const Component& component, const std::vector<geom::Curve>& curves,
                                const std::vector<std::string>& names,
                                const geom::curvemap::Placement& placement,
                                const geom::curvemap::MapOptions& options) {
    const geom::curvemap::CurveMapper mapper(component.surface, component.closedU, component.closedW);
    ComponentMapping out;
    out.result = mapper.map(curves, placement, options);
    // Parts the whole surface could not close: again on the sheet that faces the curve.
    std::vector<std::size_t> retry;
    for (std::size_t i = 0; i < out.result.parts.size(); ++i)
        if (out.result.parts[i].loops.empty() && !missesSurface(out.result.parts[i])) retry.push_back(i);
    std::string sheet;
    if (!retry.empty()) {
        const auto facing = geom::curvemap::facingDomain(component.surface, mapper.domain(),
                                                         placement.reference, out.result.frame.z);
        if (facing) {
            std::vector<geom::Curve> again;
            for (std::size_t i : retry) again.push_back(curves[i]);
            try {
                const geom::curvemap::CurveMapper sub(
                    geom::curvemap::subSurface(component.surface, mapper.domain(), *facing), false, false);
                geom::curvemap::MapResult clipped = sub.map(again, placement, options);
                sheet = "clipped at the edge of the sheet facing the curve (u " + std::to_string(facing->u0) +
                        " to " + std::to_string(facing->u1) + ", w " + std::to_string(facing->w0) + " to " +
                        std::to_string(facing->w1) + ")";
                for (std::size_t k = 0; k < retry.size(); ++k) {
                    geom::curvemap::MappedPart& part = clipped.parts[k];
                    if (part.loops.empty()) continue;
                    part.issues.insert(part.issues.begin(), sheet);
                    out.result.parts[retry[k]] = std::move(part);
                }
            } catch (const geom::GeometryError& e) {
                for (std::size_t i : retry)
                    out.result.parts[i].issues.push_back(std::string("the facing sheet: ") + e.what());
            }
        }
    }
    for (std::size_t i = 0; i < out.result.parts.size(); ++i) {
        const geom::curvemap::MappedPart& part = out.result.parts[i];
        PartReport r;
        r.name = i < names.size() && !names[i].empty() ? names[i] : "PART_" + std::to_string(i + 1);
        r.loops = part.loops.size();
        r.boundaryWalks = walksOf(part);
        if (r.loops == 0) {
            r.outcome = PartOutcome::Lost;
            r.reason = reasonOf(part);
        } else if (!sheet.empty() && !part.issues.empty() && part.issues.front() == sheet) {
            r.outcome = PartOutcome::Clipped;
            r.reason = sheet;
        } else if (r.boundaryWalks > 0) {
            r.outcome = PartOutcome::Clipped;
            r.reason = "clipped at the surface boundary";
        } else {
            r.outcome = PartOutcome::Mapped;
        }
        out.parts.push_back(std::move(r));
    }
    return out;
}

}  // namespace acsynt
