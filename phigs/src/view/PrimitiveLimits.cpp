#include "phigs/view/PrimitiveLimits.h"

#include <algorithm>
#include <cmath>

namespace phigs {
namespace {

/// A scale factor of a nominal size as drawn: the size clamped to [min, max] (NaN as the least).
double clampedScale(double scale, double nominal, double min, double max) {
    const double size = std::isnan(scale) ? min : std::clamp(scale * nominal, min, max);
    return size / nominal;
}

}  // namespace

LineType PrimitiveLimits::lineType(LineType type) const {
    const int t = static_cast<int>(type);
    return t >= 1 && t <= lineTypes ? type : LineType::Solid;
}

MarkerType PrimitiveLimits::markerType(MarkerType type) const {
    const int t = static_cast<int>(type);
    return t >= 1 && t <= markerTypes ? type : MarkerType::Asterisk;
}

int PrimitiveLimits::styleIndex(InteriorStyle style, int index) const {
    return style != InteriorStyle::Hatch || (index >= 1 && index <= hatchStyles) ? index : 1;
}

double PrimitiveLimits::lineWidthScale(double scale) const {
    return clampedScale(scale, nominalLineWidth, minLineWidth, maxLineWidth);
}

double PrimitiveLimits::markerScale(double scale) const {
    return clampedScale(scale, nominalMarkerSize, minMarkerSize, maxMarkerSize);
}

}  // namespace phigs
