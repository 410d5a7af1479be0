#pragma once
// Length unit names (private to geom_exchange).

#include <optional>
#include <string>

namespace geom::exchange {

/// The code OpenCASCADE's unit settings take ("M", "MM", "IN", ...) for a unit name any IGES or
/// STEP file may spell ("m", "metre", "millimetre", "INCH", ...); nullopt for an unknown name.
std::optional<std::string> occtUnitCode(const std::string& unitName);

}  // namespace geom::exchange
