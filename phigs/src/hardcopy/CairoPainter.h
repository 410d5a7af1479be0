#pragma once

// Private to phigs_hardcopy: the only code that includes cairo.

#include "phigs/hardcopy/VectorPicture.h"

#include <cairo.h>

namespace phigs::hardcopy {

/// The record step: one VectorPicture as cairo calls on the current page of a cairo context.
/// `opaque` paints every fill opaque (PostScript has no transparency, and cairo would fall back
/// to a raster image for it).
class CairoPainter {
public:
    CairoPainter(cairo_t* cairo, bool opaque) : cr_(cairo), opaque_(opaque) {}

    /// Paints the picture and empties `picture.ops`, each operation's points given back as soon as
    /// cairo has recorded it.
    void paint(VectorPicture& picture);

    void operator()(const VectorFill& fill);
    void operator()(const VectorHatch& hatch);
    void operator()(const VectorStroke& stroke);
    void operator()(const VectorCircle& circle);

private:
    void useClip(int clip);
    /// The contours as the current path, each closed only where the path is `stroked`.
    void contours(const std::vector<std::vector<glm::dvec2>>& contours, bool stroked);
    /// Fills [begin, end) of `ops`, opaque convex VectorFills of one style, as one path.
    void fillRun(const std::vector<VectorOp>& ops, std::size_t begin, std::size_t end);
    void colour(glm::vec3 rgb, float opacity = 1.0f);
    /// A PATTERN fill's source: its cells as a repeating image, nearest cell, mapped by its matrix.
    void patternSource(const PagePattern& pattern, float opacity);

    cairo_t* cr_;
    bool opaque_;
    const VectorPicture* picture_ = nullptr;
    int clip_ = -1;
};

}  // namespace phigs::hardcopy
