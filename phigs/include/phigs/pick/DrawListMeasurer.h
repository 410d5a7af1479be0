#pragma once

#include "phigs/input/InputMeasurer.h"
#include "phigs/pick/Picker.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/traverse/WorkstationMapping.h"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace phigs {

/// The measurer of a workstation whose picture is a draw list: source positions (pixels from
/// the top left, y down) go through the inverse workstation transformation (WorkstationMapping)
/// to NPC, then for the locator and stroke through the inverse viewing of the view of highest
/// input priority (`DrawList::viewInputPriority`) whose clip limits hold them, and for pick
/// through the Picker.
class DrawListMeasurer : public InputMeasurer {
public:
    /// `display` is the workstation's current draw list (the caller keeps it alive and current).
    explicit DrawListMeasurer(const DrawList& display);
    /// The picture comes from `display` at each measure (e.g. a workstation's display(), which
    /// regenerates when its deferral mode says so).
    explicit DrawListMeasurer(std::function<const DrawList&()> display);

    /// The draw list a pick device sees, when traversal builds one per pick filter; by default
    /// every device picks on the display as it is (its pickable flags).
    void setPickListProvider(std::function<const DrawList&(const InputDevice&)> provider) {
        pickList_ = std::move(provider);
    }
    /// The source's surface in pixels (the rendered image or window). Default: one pixel per
    /// device coordinate of the display surface (`DrawList::displaySize`).
    using SurfaceSize = std::pair<std::uint32_t, std::uint32_t>;
    void setSurfaceSize(std::uint32_t width, std::uint32_t height) {
        surface_ = [width, height] { return SurfaceSize{width, height}; };
    }
    /// The surface size asked at each measure (a window the operator may resize).
    void setSurfaceSize(std::function<SurfaceSize()> size) { surface_ = std::move(size); }
    /// NPC z given to 2D locator and stroke positions (default 0, the back of NPC space).
    void setLocatorDepth(double npcZ) { locatorDepth_ = npcZ; }

    /// The workstation transformation of the current display on the source's surface.
    WorkstationMapping mapping() const { return mappingOf(display()); }
    /// Source pixels (y down) to NPC, through the inverse workstation transformation.
    glm::dvec3 toNpc(glm::dvec2 pixels) const;

    LocatorMeasure locate(glm::dvec2 deviceCoordinates) const override;
    StrokeMeasure stroke(const std::vector<glm::dvec2>& deviceCoordinates) const override;
    PickMeasure pick(glm::dvec2 deviceCoordinates, const InputDevice& device) const override;

    /// Items the last pick's echo highlights (empty when it hit nothing or echo is off).
    const std::vector<std::size_t>& lastEcho() const { return echo_; }
    const Picker& picker() const { return picker_; }

private:
    const DrawList& display() const { return display_(); }
    WorkstationMapping mappingOf(const DrawList& list) const;
    /// The view of highest priority whose clip limits hold every point (view 0 when none does).
    int viewFor(const DrawList& list, const std::vector<glm::dvec3>& npc) const;
    glm::dvec3 toWorld(const DrawList& list, int view, const glm::dvec3& npc) const;

    std::function<const DrawList&()> display_;
    std::function<const DrawList&(const InputDevice&)> pickList_;
    std::function<SurfaceSize()> surface_;  ///< empty: one pixel per device unit
    double locatorDepth_ = 0.0;
    Picker picker_;
    mutable std::vector<std::size_t> echo_;
};

}  // namespace phigs
