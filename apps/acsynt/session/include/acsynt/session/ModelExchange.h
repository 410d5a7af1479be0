#pragma once
// A model with its mapped curves to and from IGES / STEP (geom_exchange).

#include "acsynt/Model.h"
#include "acsynt/session/Session.h"
#include "geom/exchange/CadModel.h"

#include <filesystem>
#include <string>
#include <vector>

namespace acsynt {

/// Imported surfaces that are not polynomial bicubics (rational, other degrees) are made so
/// within this distance, in model units (metres): 10 micrometres.
inline constexpr double kImportTolerance = 1e-5;

/// The model as an exchange model in metres: each component a named surface with its colour,
/// and the loops of each of the model's mappings ((u, w) and points) as curves on it, named
/// after the curve file.
geom::exchange::CadModel cadModelOf(const Model& model, const std::vector<MappingRecord>& mappings);

/// A model read from an IGES or STEP file, with its mapped curves and what was changed or left out.
struct ImportedModel {
    Model model;
    std::vector<MappingRecord> mappings;
    std::vector<std::string> warnings;
};

/// Reads an IGES or STEP file (geom::exchange::readCadFile, in metres) as a new model: each
/// surface a component (names made valid and unique, the kind guessed from the name), made a
/// polynomial bicubic (exact where it can be, else within kImportTolerance, with a warning), its
/// patch list built, closed round a direction that is periodic by construction; each curve set a
/// mapping of one part. The model is named after the file's model (or the file). Throws
/// geom::exchange::ExchangeError for a file that cannot be read or a model over the program's
/// limits (64 components, 8192 patches); nothing is returned half-read.
ImportedModel importCadModel(const std::filesystem::path& path);

}  // namespace acsynt
