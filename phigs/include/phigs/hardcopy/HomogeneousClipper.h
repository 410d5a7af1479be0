#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/vec4.hpp>

#include <vector>

namespace phigs::hardcopy {

/// A half space of homogeneous points: keeps h where dot(plane, h) >= offset.
struct HalfSpace {
    glm::dvec4 plane{0.0};
    double offset = 0.0;
};

/// A vertex being clipped: a homogeneous position, the distance along its line (nominal pixels)
/// and its place on the line (vertex k + t, for vertex colours), which clipping interpolates with
/// the position.
struct ClipVertex {
    glm::dvec4 h{0.0, 0.0, 0.0, 1.0};
    double distance = 0.0;
    double along = 0.0;
};

/// What a view shows, as half spaces of homogeneous NPC points: w > 0, depth in [0, 1] (the
/// raster's depth range), the view's front and back planes where it clips them, and x/y within
/// its clip limits (where it clips) and the workstation window.
std::vector<HalfSpace> viewVolume(const DrawView& view, const DrawList& list);

/// World half spaces of a model clipping volume (DrawItem::modelClipPlanes) for points (x, y, z, 1).
std::vector<HalfSpace> modelVolume(const std::vector<glm::dvec4>& planes);

/// Whether a point lies in every half space.
bool inside(const glm::dvec4& h, const std::vector<HalfSpace>& volume);

/// A closed polygon clipped to the half spaces (Sutherland-Hodgman); fewer than 3 vertices: gone.
/// A concave contour stays right under the even-odd rule (cut edges run along the boundary).
std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> polygon, const std::vector<HalfSpace>& volume);

/// An open polyline clipped to the half spaces: the runs that remain, in order.
std::vector<std::vector<ClipVertex>> clipPolyline(const std::vector<ClipVertex>& line,
                                                  const std::vector<HalfSpace>& volume);

}  // namespace phigs::hardcopy
