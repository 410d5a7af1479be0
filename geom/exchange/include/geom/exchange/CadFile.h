#pragma once
// IGES and STEP files of named B-spline surfaces, through OpenCASCADE's data exchange.

#include "geom/exchange/CadModel.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace geom::exchange {

enum class CadFormat { Iges, Step };

/// The format a file name asks for: .igs/.iges or .stp/.step (any case); ExchangeError otherwise.
CadFormat cadFormatOf(const std::filesystem::path& path);

/// Writes the model as IGES (each patch a B-spline surface 128 under a 144 bounded by its own
/// boundary, each surface a named 402 group) or STEP (AP214: the model an assembly, each surface
/// a named product of advanced faces on B-spline surfaces, one per patch). Patches are the
/// Bézier pieces of the surface (extractBezier), exact. Each SurfaceCurves is a named entity
/// "SURFACE/NAME" of trimmed faces on the whole surface (periodic where the surface is periodic
/// by construction), one per outer loop with its holes inside, bounded by degree-1 edges: the
/// loop's points in space and its (u, v) as the curve on the surface (IGES 142 with two 126).
/// Lengths are written in model.unit, reals with 17 significant digits. Throws ExchangeError
/// naming the file and the cause (an unknown unit or extension, an invalid surface or loop, a
/// file that cannot be written); nothing is written then, unless the file itself fails midway.
void writeCadFile(const CadModel& model, const std::filesystem::path& path);

/// Limits and target unit of a read.
struct CadReadOptions {
    std::string unit = "M";                             ///< lengths are converted to this unit
    std::uintmax_t maxFileBytes = 256u * 1024 * 1024;   ///< larger files are refused unread
    std::size_t maxFaces = 100000;                      ///< more faces are refused before conversion
    std::size_t maxPoles = 4000000;                     ///< control points of all surfaces together
    std::size_t maxMemoryBytes = std::size_t(4) << 30;  ///< memory the reader may take
    int maxSeconds = 300;                               ///< time the reader may take
};

/// What a read gives: the model and what was left out or changed, one line each.
struct CadImport {
    CadModel model;
    std::string fileUnit;  ///< the length unit the file declared (its own spelling)
    std::vector<std::string> warnings;
};

/// Reads the B-spline surfaces of an IGES or STEP file. Each named group or product of faces
/// becomes one surface when its faces tile a parameter grid on one surface (joinPatches: a file
/// written by writeCadFile gives its surfaces back), else one surface per face ("NAME_k"); a name
/// met again (a part placed twice in an assembly) gets "_2", "_3", ..., names being unique. Other
/// surface types are converted to B-splines by OpenCASCADE (faces it cannot convert, and faces
/// trimmed inside their surface, are left out with a warning). Entities named "SURFACE/NAME"
/// made of trimmed faces with degree-1 edges come back as that surface's SurfaceCurves (each
/// face's outer loop counter-clockwise in (u, v), its holes clockwise). OpenCASCADE reads in a
/// child process (fork) held to the options' memory and time: a reader that crashes, loops or
/// runs out of memory on a corrupt file is stopped. Throws ExchangeError for a missing, empty,
/// oversized, truncated or corrupt file, an unknown length unit, or a file with no surface that
/// can be converted.
CadImport readCadFile(const std::filesystem::path& path, const CadReadOptions& options = {});

}  // namespace geom::exchange
