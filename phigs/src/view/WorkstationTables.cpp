#include "phigs/view/WorkstationTables.h"

#include "phigs/view/RealizedLighting.h"

namespace phigs {

namespace {

/// The RGB of a light or depth cue colour as given: an index through the table, a direct colour
/// converted from its model (unclamped: REALIZED clamps).
glm::vec3 currentRgb(const ColourTable& table, const Colour& c) {
    return glm::vec3(c.direct ? toRgb(c.model, c.rgb) : table.get(c.index));
}

Colour given(const std::map<int, Colour>& colours, int index, const glm::vec3& rgb) {
    const auto found = colours.find(index);
    return found != colours.end() ? found->second : Colour::fromRgb(glm::dvec3(rgb));
}

}  // namespace

std::optional<Light> WorkstationTables::drawnLight(int index) const {
    const auto found = lights.find(index);
    if (found == lights.end()) return std::nullopt;
    Light l = found->second;
    if (const auto c = lightColours.find(index); c != lightColours.end())
        l.colour = currentRgb(colours, c->second);
    return realized(l);
}

std::optional<DepthCue> WorkstationTables::drawnDepthCue(int index) const {
    const auto found = depthCues.find(index);
    if (found == depthCues.end()) return std::nullopt;
    DepthCue d = found->second;
    if (const auto c = depthCueColours.find(index); c != depthCueColours.end())
        d.colour = currentRgb(colours, c->second);
    return realized(d);
}

Colour WorkstationTables::givenLightColour(int index) const {
    const auto found = lights.find(index);
    return given(lightColours, index, found != lights.end() ? found->second.colour : glm::vec3(1.0f));
}

Colour WorkstationTables::givenDepthCueColour(int index) const {
    const auto found = depthCues.find(index);
    return given(depthCueColours, index, found != depthCues.end() ? found->second.colour : glm::vec3(0.0f));
}

}  // namespace phigs
