#pragma once
// A model with its mapped curves to and from IGES / STEP (geom_exchange): the exchange module's
// code, which the session reaches through acsynt::exchangeCalls().

#include "acsynt/Model.h"
#include "acsynt/session/ModelExchange.h"
#include "geom/exchange/CadModel.h"

#include <filesystem>
#include <vector>

namespace acsynt {

/// The model as an exchange model in metres: each component a named surface with its colour,
/// and the loops of each of the model's mappings ((u, w) and points) as curves on it, named
/// after the curve file (each character outside printable ASCII made '_').
geom::exchange::CadModel cadModelOf(const Model& model, const std::vector<MappingRecord>& mappings);

/// Reads an IGES or STEP file (geom::exchange::readCadFile, in metres) as a new model: each
/// surface a component (names made valid and unique, the kind guessed from the name), made a
/// polynomial bicubic (exact where it can be, else within kImportTolerance, with a warning), its
/// patch list built, closed round a direction that is periodic by construction; each curve set a
/// mapping of one part. The model is named after the file's model (or the file). Throws
/// geom::exchange::ExchangeError for a file that cannot be read or a model over the program's
/// limits (64 components, 8192 patches); nothing is returned half-read.
ImportedModel importCadModel(const std::filesystem::path& path);

}  // namespace acsynt
