#pragma once

#include "phigs/core/Attributes.h"

namespace phigs {

/// The line, marker and hatch attributes a workstation can draw (its description's facilities),
/// and what it draws for the others: ISO 9592 draws a line or edge type it lacks as type 1, a
/// marker type it lacks as type 3, a hatch style it lacks as style 1, and a width or size as the
/// nearest one available.
struct PrimitiveLimits {
    int lineTypes = 4, markerTypes = 5;  ///< types 1 .. N
    /// Hatch styles 1 .. N (1 horizontal, 2 vertical, 3 +45°, 4 -45°, 5 grid, 6 diagonal grid),
    /// drawn alike by the raster shader and the vector painter.
    int hatchStyles = 6;
    /// Widths and sizes in device coordinates (pixels of a raster target).
    double nominalLineWidth = 1.0, minLineWidth = 1.0, maxLineWidth = 16.0;
    double nominalMarkerSize = 7.0, minMarkerSize = 1.0, maxMarkerSize = 64.0;

    LineType lineType(LineType type) const;
    MarkerType markerType(MarkerType type) const;
    /// An interior style index as drawn: a hatch style the workstation lacks as 1; the index of
    /// any other style (a pattern's) as it is.
    int styleIndex(InteriorStyle style, int index) const;
    /// A width scale factor as drawn: the width it asks for clamped to [min, max].
    double lineWidthScale(double scale) const;
    /// A marker size scale factor as drawn, as lineWidthScale.
    double markerScale(double scale) const;
};

}  // namespace phigs
