#pragma once

#include "geom/Surface.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace geom::exchange {

/// A closed loop drawn on a surface: the same vertices in the surface's (u, v) and in model
/// space, first vertex repeated at the end; the region it bounds lies on its left in (u, v).
struct SurfaceLoop {
    std::vector<glm::dvec2> uv;
    std::vector<glm::dvec3> points;
};

/// Loops drawn on one surface (a mapped curve), written as trimmed faces on that surface.
struct SurfaceCurves {
    std::string name;  ///< e.g. the curve file; the entity is named "SURFACE/NAME"
    std::vector<SurfaceLoop> loops;
};

/// A named surface: one product (STEP) or group (IGES), each non-empty knot span pair a face.
struct CadSurface {
    std::string name;
    Surface surface;
    std::optional<glm::dvec3> colour;  ///< RGB in [0, 1]
    std::vector<SurfaceCurves> curves;
};

/// A model as exchanged: named surfaces in model units (`unit` says which).
struct CadModel {
    std::string name;
    std::string unit = "M";  ///< an IGES/STEP length unit name: "M", "MM", "CM", "KM", "IN", "FT", ...
    std::vector<CadSurface> surfaces;
};

/// Metres per unit for the length unit names IGES and STEP files use (M, MM, CM, KM, UM, IN, FT,
/// MI, MIL, UIN and the spelled-out forms "metre", "millimetre", "inch", "foot", ... any case);
/// nullopt for a name the program does not know.
std::optional<double> metresPerUnit(const std::string& unitName);

}  // namespace geom::exchange
