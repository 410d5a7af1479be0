#pragma once

#include "phigs/input/InputDevice.h"
#include "phigs/input/InputTypes.h"

#include <glm/vec2.hpp>

#include <vector>

namespace phigs {

/// Turns device-coordinate positions into measures: the workstation's inverse viewing for the
/// locator (honouring view transformation input priority) and its pick traversal for pick.
class InputMeasurer {
public:
    virtual ~InputMeasurer() = default;
    virtual LocatorMeasure locate(glm::dvec2 deviceCoordinates) const = 0;
    /// A stroke through the points, all in the one view of highest input priority holding them.
    virtual StrokeMeasure stroke(const std::vector<glm::dvec2>& deviceCoordinates) const = 0;
    /// A pick at the position with the device's aperture, filter, path order and depth.
    virtual PickMeasure pick(glm::dvec2 deviceCoordinates, const InputDevice& device) const = 0;
};

}  // namespace phigs
