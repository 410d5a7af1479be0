#pragma once

#include "acsynt/Naca4.h"

#include <glm/vec3.hpp>

#include <string>
#include <variant>
#include <vector>

namespace acsynt {

/// The kinds of component an aircraft description names.
enum class ComponentKind { Fuselage, Wing, HorizontalTail, VerticalTail, Nacelle };

/// The keyword of a kind in the description file ("fuselage", "wing", "htail", "vtail", "nacelle").
const char* componentKindKeyword(ComponentKind kind);

/// Which part of the fuselage a station belongs to; stations run nose, then mid, then afterbody.
enum class FuselagePart { Nose, Mid, Afterbody };

/// One fuselage cross section at station x: a super-ellipse |y/a|^e + |(z-zc)/b|^e = 1 with
/// half width a, upper half height b above the centre and lower half height below it. All three
/// zero make a point section (a nose or tail tip).
struct FuselageStation {
    FuselagePart part = FuselagePart::Mid;
    double x = 0.0;
    double halfWidth = 0.0;
    double upperHeight = 0.0;
    double lowerHeight = 0.0;
    double zCentre = 0.0;
    double exponent = 2.0;
    int line = 0;  ///< line of the description file, for error messages
};

/// A fuselage lofted through its stations, closed around the circumference.
struct FuselageShape {
    std::vector<FuselageStation> stations;
};

/// A wing or tail: a straight-tapered panel from the root section (leading edge at `position`)
/// out to the tip, NACA sections blended linearly from root to tip.
struct LiftingSurfaceShape {
    Naca4Airfoil rootAirfoil;
    Naca4Airfoil tipAirfoil;
    glm::dvec3 position{0.0};  ///< root leading edge
    double rootChord = 0.0;
    double taper = 1.0;      ///< tip chord / root chord
    double span = 0.0;       ///< root to tip along the span direction (one side)
    double sweep = 0.0;      ///< leading-edge sweep, degrees
    double dihedral = 0.0;   ///< degrees; for a vertical tail the tilt from +z toward +y
    double incidence = 0.0;  ///< root incidence, degrees, leading edge up positive
    double twist = 0.0;      ///< tip incidence minus root incidence, degrees
    int sections = 0;        ///< spanwise sections lofted, evenly spaced
};

/// One station of a nacelle profile: radius at x behind the nacelle position.
struct NacelleStation {
    double x = 0.0;
    double radius = 0.0;
    int line = 0;
};

/// A nacelle: a body of revolution about an axis parallel to x through `position`.
struct NacelleShape {
    glm::dvec3 position{0.0};
    std::vector<NacelleStation> profile;
};

/// One component as the description file gives it.
struct ComponentDescription {
    std::string name;
    ComponentKind kind = ComponentKind::Fuselage;
    glm::dvec3 colour{1.0};
    int points = 0;          ///< points in each cross section
    std::string mirrorName;  ///< when set, a mirror image about y = 0 is built under this name
    std::variant<FuselageShape, LiftingSurfaceShape, NacelleShape> shape;
    int line = 0;  ///< line of the `component` keyword
};

/// A whole aircraft description file.
struct AircraftDescription {
    int version = 1;
    std::string name;
    std::vector<ComponentDescription> components;
};

}  // namespace acsynt
