#include "phigs/ws/Realization.h"

#include <algorithm>

namespace phigs {
namespace {

Colour realizedColour(const Colour& colour, const ColourTable& table) {
    if (colour.direct) return Colour::fromRgb(clampedRgb(colour.model, colour.rgb));  // drawn as RGB
    if (table.defined(colour.index)) return colour;
    return Colour::indexed(1);
}

}  // namespace

PolylineBundle realized(const PolylineBundle& b, const WorkstationDescription& d, const ColourTable& c) {
    PolylineBundle r = b;
    r.width = d.primitives.lineWidthScale(b.width);
    r.colour = realizedColour(b.colour, c);
    return r;
}

PolymarkerBundle realized(const PolymarkerBundle& b, const WorkstationDescription& d, const ColourTable& c) {
    PolymarkerBundle r = b;
    r.scale = d.primitives.markerScale(b.scale);
    r.colour = realizedColour(b.colour, c);
    return r;
}

TextBundle realized(const TextBundle& b, const WorkstationDescription& d, const ColourTable& c) {
    TextBundle r = b;
    r.precision = 2;  // STROKE: every font is a stroke font here
    r.expansion = std::clamp(b.expansion, d.minCharExpansion, d.maxCharExpansion);
    r.colour = realizedColour(b.colour, c);
    return r;
}

InteriorBundle realized(const InteriorBundle& b, const WorkstationDescription&, const ColourTable& c) {
    InteriorBundle r = b;
    r.colour = realizedColour(b.colour, c);
    r.backColour = realizedColour(b.backColour, c);
    r.properties.specularColour = realizedColour(b.properties.specularColour, c);
    r.backProperties.specularColour = realizedColour(b.backProperties.specularColour, c);
    return r;
}

EdgeBundle realized(const EdgeBundle& b, const WorkstationDescription& d, const ColourTable& c) {
    EdgeBundle r = b;
    r.width = d.primitives.lineWidthScale(b.width);
    r.colour = realizedColour(b.colour, c);
    return r;
}

PatternRepresentation realized(const PatternRepresentation& p, const ColourTable& c) {
    PatternRepresentation r = p;
    for (Colour& colour : r.colours) colour = realizedColour(colour, c);
    return r;
}

}  // namespace phigs
