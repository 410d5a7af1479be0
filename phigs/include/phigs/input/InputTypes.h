#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace phigs {

/// The six PHIGS logical input device classes.
enum class InputClass { Locator, Stroke, Valuator, Choice, Pick, String };

/// How the application obtains a device's measure.
enum class OperatingMode { Request, Sample, Event };

enum class EchoSwitch { NoEcho, Echo };

/// Outcome of a REQUEST (or the status part of a choice or pick measure): OK, or NONE when the
/// operator broke the request or picked nothing.
enum class InputStatus { None, Ok };

/// Order of a pick path: the root structure first, or the picked structure first.
enum class PathOrder { TopFirst, BottomFirst };

/// Echo volume in device coordinates: x, y in pixels as input sources give them (from the top
/// left, y down), z in [0, 1].
struct EchoVolume {
    double xmin = 0, xmax = 0, ymin = 0, ymax = 0, zmin = 0, zmax = 1;
    bool operator==(const EchoVolume&) const = default;
};

/// One level of a pick path.
struct PickPathItem {
    int structureId = 0;
    int elementNumber = 0;  ///< 1-based, as PHIGS numbers elements
    int pickId = 0;
    bool operator==(const PickPathItem&) const = default;
};

/// The exact surface hit behind a pick of a B-spline surface, in the surface's own modelling
/// coordinates (apply the item's modelling transform for world coordinates).
struct SurfacePickDetail {
    glm::dvec3 point{0.0};   ///< S(uv)
    glm::dvec3 normal{0.0};  ///< unit normal Su x Sv at uv
    glm::dvec2 uv{0.0};
    std::size_t bezierPiece = 0;  ///< index of the Bézier piece (u span slow, v span fast)
};

struct LocatorMeasure {
    int viewIndex = 0;
    glm::dvec3 position{0.0};  ///< world coordinates
};
struct StrokeMeasure {
    int viewIndex = 0;
    std::vector<glm::dvec3> points;  ///< world coordinates
};
struct ValuatorMeasure {
    double value = 0.0;
};
struct ChoiceMeasure {
    InputStatus status = InputStatus::None;
    int choice = 0;  ///< 1-based alternative
};
struct PickMeasure {
    InputStatus status = InputStatus::None;
    std::vector<PickPathItem> path;
    std::optional<SurfacePickDetail> surface;
};
struct StringMeasure {
    std::string text;
};

/// The measure of any device; the alternative matches the device's InputClass.
using Measure =
    std::variant<LocatorMeasure, StrokeMeasure, ValuatorMeasure, ChoiceMeasure, PickMeasure, StringMeasure>;

/// The InputClass a measure belongs to.
InputClass classOf(const Measure& measure);

/// Upper-case PHIGS name of a class ("LOCATOR", ...), for messages.
const char* nameOf(InputClass inputClass);

/// One entry of the input queue.
struct EventReport {
    int workstation = 0;
    InputClass inputClass = InputClass::Locator;
    int device = 0;
    Measure measure;
    /// True while more events from the same trigger follow this one in the queue.
    bool moreSimultaneous = false;
};

}  // namespace phigs
