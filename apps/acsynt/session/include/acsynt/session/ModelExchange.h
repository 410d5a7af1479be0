#pragma once
// A model with its mapped curves to and from IGES / STEP: the calls of the exchange module
// (apps/acsynt/exchange, on OpenCASCADE), which the program loads on the first of them.

#include "acsynt/Model.h"
#include "acsynt/session/MappingRecord.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace acsynt {

/// Imported surfaces that are not polynomial bicubics (rational, other degrees) are made so
/// within this distance, in model units (metres): 10 micrometres.
inline constexpr double kImportTolerance = 1e-5;

/// A model read from an IGES or STEP file, with its mapped curves and what was changed or left out.
struct ImportedModel {
    Model model;
    std::vector<MappingRecord> mappings;
    std::vector<std::string> warnings;
};

/// The exchange module's entry points. Each throws geom::exchange::ExchangeError (a
/// std::runtime_error, "FILE: REASON") for a file that cannot be read or written.
struct ExchangeCalls {
    /// acsynt::importCadModel: a new model from an IGES or STEP file, all or nothing.
    ImportedModel (*importModel)(const std::filesystem::path& path);
    /// Writes the model with its mappings (acsynt::cadModelOf, then geom::exchange::writeCadFile)
    /// and gives the number of mapped curves written.
    std::size_t (*exportModel)(const Model& model, const std::vector<MappingRecord>& mappings,
                               const std::filesystem::path& path);
    /// geom::exchange::cadFormatOf: refuses a name that is not .igs/.iges/.stp/.step.
    void (*checkFileName)(const std::filesystem::path& path);
};

/// The exchange calls. OpenCASCADE's libraries are large (relocating them costs a tenth of a
/// short session), so the module is opened (dlopen) on the first call, not at the program's
/// start. It is looked for next to the program, then in the installed layout (lib/acsynt beside
/// bin), then at the build tree's path; std::runtime_error naming the module and the loader's
/// reason when it cannot be loaded.
const ExchangeCalls& exchangeCalls();

}  // namespace acsynt

/// The module's one exported symbol: its calls.
extern "C" const acsynt::ExchangeCalls* acsynt_exchange_calls();
