#pragma once

#include "acsynt/Model.h"
#include "acsynt/session/MappingRecord.h"

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace acsynt {

/// A model as the session holds it (its surfaces, reduced or not) and the curves mapped on it.
struct ModelState {
    Model model;
    std::vector<MappingRecord> mappings;
};

/// The version SAVE MODEL writes and READ MODEL reads (`acsynt-surfaces 1`).
inline constexpr int modelStateVersion = 1;
/// Limits of a model state file (each a ModelFileError at the line that breaks it).
inline constexpr std::size_t kModelStateMaxPoints = 1u << 22;    ///< control points, all components
inline constexpr std::size_t kModelStateMaxVertices = 1u << 22;  ///< mapped loop vertices, all mappings
inline constexpr double kModelStateMaxCoordinate = 1e9;          ///< largest coordinate, in model units

/// Whether a model state file holds `v` as a coordinate: finite and within kModelStateMaxCoordinate.
inline bool isSavableCoordinate(double v) {
    return std::abs(v) <= kModelStateMaxCoordinate;  // false for NaN
}

/// Writes `model` and those of `mappings` made on it (MappingRecord::model == model.name):
/// every number in hexadecimal floating point, so reading back gives the same bits.
void writeModelState(std::ostream& out, const Model& model, const std::vector<MappingRecord>& mappings);
/// True when `path` starts with the `acsynt-surfaces` heading (a file SAVE MODEL wrote).
bool isModelStateFile(const std::filesystem::path& path);
/// Reads a file writeModelState wrote: the model (patch lists rebuilt, no description) and its
/// mappings. Any fault throws ModelFileError naming the file, the line and the reason.
ModelState readModelState(const std::filesystem::path& path);
ModelState parseModelState(std::istream& in, const std::string& fileName);

}  // namespace acsynt
