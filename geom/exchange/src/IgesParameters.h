#pragma once
// The parameters of an IGES file (ANSI Y14.26M) checked before OpenCASCADE reads it.

#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace geom::exchange {

/// The first parameter of an IGES file's global or parameter data section that is not a number
/// or a string, as "line N: ..." naming it, or a number OpenCASCADE would misread: a real beyond
/// +-1e100 or out of double's range, an integer beyond 32 bits. OpenCASCADE reads "nan", "inf",
/// "1.0E" or "+-1" there as 0 or a truncated number without a word. nullopt when every parameter
/// is a number, a Hollerith string or empty (a default). Delimiters as the global section sets
/// them; one pass, memory bounded by the largest entity.
std::optional<std::string> firstBadIgesParameter(std::istream& in);

/// The parameters of an IGES file's global section as written (strings without their "nH"): the
/// reader changes some (a unit flag 3 without a name becomes 1, inches).
std::vector<std::string> igesGlobalParameters(std::istream& in);

}  // namespace geom::exchange
