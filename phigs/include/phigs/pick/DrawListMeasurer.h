#pragma once

#include "phigs/input/InputMeasurer.h"
#include "phigs/input/ViewInputPriority.h"
#include "phigs/pick/Picker.h"
#include "phigs/traverse/DrawList.h"

#include <functional>
#include <vector>

namespace phigs {

/// The measurer of a workstation whose picture is a draw list: device positions (pixels from
/// the top left, y down) go through the inverse workstation transformation to NPC, then for
/// the locator and stroke through the inverse viewing of the view of highest input priority
/// whose clip limits hold them, and for pick through the Picker.
class DrawListMeasurer : public InputMeasurer {
public:
    /// `display` is the workstation's current draw list (the caller keeps it alive and current).
    explicit DrawListMeasurer(const DrawList& display);

    /// The draw list a pick device sees, when traversal builds one per pick filter; by default
    /// every device picks on `display` as it is (its pickable flags).
    void setPickListProvider(std::function<const DrawList&(const InputDevice&)> provider) {
        pickList_ = std::move(provider);
    }
    /// Height of the display surface in pixels, to flip y (default: the viewport's top).
    void setDisplayHeight(double pixels) { displayHeight_ = pixels; }
    /// NPC z given to 2D locator and stroke positions (default 0, the back of NPC space).
    void setLocatorDepth(double npcZ) { locatorDepth_ = npcZ; }
    ViewInputPriority& viewPriority() { return priority_; }

    /// Device pixels (y down) to NPC, through the inverse workstation transformation.
    glm::dvec3 toNpc(glm::dvec2 pixels) const;

    LocatorMeasure locate(glm::dvec2 deviceCoordinates) const override;
    StrokeMeasure stroke(const std::vector<glm::dvec2>& deviceCoordinates) const override;
    PickMeasure pick(glm::dvec2 deviceCoordinates, const InputDevice& device) const override;

    /// Items the last pick's echo highlights (empty when it hit nothing or echo is off).
    const std::vector<std::size_t>& lastEcho() const { return echo_; }
    const Picker& picker() const { return picker_; }

private:
    /// The view of highest priority whose clip limits hold every point (view 0 when none does).
    int viewFor(const std::vector<glm::dvec3>& npc) const;
    glm::dvec3 toWorld(int view, const glm::dvec3& npc) const;

    const DrawList& display_;
    std::function<const DrawList&(const InputDevice&)> pickList_;
    double displayHeight_ = -1.0;
    double locatorDepth_ = 0.0;
    ViewInputPriority priority_;
    Picker picker_;
    mutable std::vector<std::size_t> echo_;
};

}  // namespace phigs
