#pragma once

#include "phigs/ws/WorkstationType.h"

#include <filesystem>
#include <optional>
#include <string_view>

namespace phigs::hardcopy {

/// The file formats of the vector hardcopy workstations.
enum class VectorFormat { Pdf, Svg, Eps };

/// The format a file name asks for by its extension (.pdf, .svg, .eps, any case); throws
/// std::invalid_argument naming the file for any other.
VectorFormat vectorFormatForFile(const std::filesystem::path& file);

/// The vector format of a workstation type (none for the raster types).
std::optional<VectorFormat> vectorFormatOf(WorkstationType type);

/// The workstation type of a vector format (the inverse of vectorFormatOf).
WorkstationType workstationTypeOf(VectorFormat format);

/// "PDF", "SVG" or "EPS".
std::string_view vectorFormatName(VectorFormat format);

}  // namespace phigs::hardcopy
