#pragma once

#include "phigs/input/InputQueue.h"
#include "phigs/input/InputSource.h"
#include "phigs/input/WorkstationInput.h"
#include "phigs/pick/DrawListMeasurer.h"
#include "phigs/ws/Workstation.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace phigs {

/// The input side of a model workstation: its logical input devices fed by one source and
/// measured on its picture. The locator and stroke map through the displayed draw list (view
/// input priority from the workstation's view table); each pick device picks on a traversal
/// of the workstation's networks with that device's pick filter (the workstation's own filters
/// otherwise), kept while the workstation's content stamp and the filters stay the same.
class WorkstationInteraction {
public:
    WorkstationInteraction(Workstation& workstation, InputSource& source, InputQueue& queue,
                           DeviceCounts counts = {});
    WorkstationInteraction(const WorkstationInteraction&) = delete;
    WorkstationInteraction& operator=(const WorkstationInteraction&) = delete;

    WorkstationInput& input() { return *input_; }
    const DrawListMeasurer& measurer() const { return measurer_; }
    DrawListMeasurer& measurer() { return measurer_; }
    Workstation& workstation() { return workstation_; }
    /// The source's surface in pixels (the size of the rendered image or window); by default the
    /// workstation's drawable as its output reports it at each measure (one pixel per device
    /// unit of the display surface when it has none, or while the drawable is empty).
    void setSurfaceSize(std::uint32_t width, std::uint32_t height) {
        measurer_.setSurfaceSize(width, height);
    }
    /// The surface size asked at each measure, e.g. a window display's current size:
    /// `followSurface([&] { return std::pair{display.width(), display.height()}; })`.
    void followSurface(std::function<DrawListMeasurer::SurfaceSize()> size) {
        measurer_.setSurfaceSize(std::move(size));
    }
    /// The paths of the items the last pick's echo highlights (empty when it hit nothing or the
    /// device's echo is off): hand them to the display (vk::WorkstationDisplay::setEcho).
    std::vector<std::vector<DrawPathLevel>> lastEcho() const;
    /// Pick traversals made so far (a pick on an unchanged picture makes none).
    std::uint64_t pickTraversals() const { return traversals_; }

private:
    const DrawList& pickList(const InputDevice& device);

    Workstation& workstation_;
    DrawListMeasurer measurer_;
    /// One pick device's last traversal and what it was made from.
    struct PickList {
        DrawList list;
        TraversalFilters filters;
        std::uint64_t stamp = 0;  ///< Workstation::contentStamp() when traversed
        bool made = false;
    };
    std::map<int, PickList> pickLists_;  ///< by pick device number
    std::uint64_t traversals_ = 0;
    const DrawList* lastPickList_ = nullptr;  ///< the list the last pick was measured on
    std::unique_ptr<WorkstationInput> input_;
};

}  // namespace phigs
