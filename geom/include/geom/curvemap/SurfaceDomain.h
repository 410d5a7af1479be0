#pragma once

#include "geom/Surface.h"

#include <glm/vec2.hpp>

#include <optional>

namespace geom::curvemap {

/// The (u, w) parameter rectangle of a surface and which directions close on themselves (a
/// fuselage is closed around): in a closed direction the seam is no boundary and parameters
/// are periodic, so loops there are kept continuous ("unwrapped") across the seam.
struct SurfaceDomain {
    double u0 = 0.0, u1 = 1.0, w0 = 0.0, w1 = 1.0;
    bool closedU = false, closedW = false;

    double periodU() const { return u1 - u0; }
    double periodW() const { return w1 - w0; }
    /// The same surface point with closed coordinates brought into [u0, u1) / [w0, w1).
    glm::dvec2 wrap(const glm::dvec2& uv) const;
    /// The representative of uv (closed coordinates shifted by whole periods) nearest to `near`.
    glm::dvec2 unwrapNear(const glm::dvec2& uv, const glm::dvec2& near) const;
};

/// True when S(start, v) == S(end, v) along the whole opposite direction (checked at 17
/// parameters against `tolerance` times the surface's size): the u (or v) direction closes.
bool closesInU(const Surface& surface, double tolerance = 1e-9);
bool closesInV(const Surface& surface, double tolerance = 1e-9);

/// The domain of a surface; closedness is detected unless given.
SurfaceDomain surfaceDomain(const Surface& surface, std::optional<bool> closedU = {},
                            std::optional<bool> closedW = {});

}  // namespace geom::curvemap
