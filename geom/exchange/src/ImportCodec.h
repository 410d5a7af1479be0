#pragma once
// A read's result as bytes, to pass from the reading child process (private to geom_exchange).

#include "geom/exchange/CadFile.h"

#include <string>

namespace geom::exchange {

/// The import as bytes (the same program reads them back: native doubles and sizes).
std::string encodeImport(const CadImport& import);
/// The import back; std::runtime_error for bytes that are not a whole encoding.
CadImport decodeImport(const std::string& bytes);

}  // namespace geom::exchange
