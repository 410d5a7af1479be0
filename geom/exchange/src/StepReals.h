#pragma once
// The reals of a STEP file (ISO 10303-21) checked before OpenCASCADE reads it.

#include <cmath>
#include <istream>
#include <optional>
#include <string>

namespace geom::exchange {

/// Reals beyond this are infinite to OpenCASCADE (Precision::Infinite is 2e100); a coordinate
/// that large sends its shape healing into searches that do not end.
inline constexpr double kStepRealLimit = 1e100;

/// Whether a real strtod read (rangeError: it set ERANGE) lies beyond +-kStepRealLimit or out of
/// double's range; an underflow is not. STEP's and IGES's checks share it and its wording.
inline bool beyondRealLimit(double value, bool rangeError) {
    return rangeError ? std::abs(value) > 1.0 : !(std::abs(value) <= kStepRealLimit);
}
inline constexpr const char* kBeyondRealLimit =
    "is out of range (beyond 1e100, which OpenCASCADE treats as infinite)";

/// The first number of a STEP file's text (a real, or an integer, which OpenCASCADE also reads
/// as a real) beyond +-kStepRealLimit or out of double's range, or longer than 4096 characters,
/// as "line N: ..." naming it; nullopt when every number is within. Strings and comments are
/// skipped; one pass, bounded memory.
std::optional<std::string> firstOutOfRangeStepReal(std::istream& in);

}  // namespace geom::exchange
