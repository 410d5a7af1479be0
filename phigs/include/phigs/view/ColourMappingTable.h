#pragma once

#include "phigs/core/ColourModels.h"
#include "phigs/core/ErrorLog.h"

#include <glm/vec3.hpp>

#include <map>
#include <vector>

namespace phigs {

/// A colour mapping method (PHIGS PLUS, ISO/IEC 9592-4).
enum class ColourMappingMethod : int { True = 1, Pseudo = 2, PseudoN = 3 };

/// One entry of a colour mapping table. TRUE draws a colour as it is. PSEUDO takes the
/// components c of a colour in `model`, combines them with `weights` into v = clamp(w . c, 0, 1)
/// and draws colours[round(v (n - 1))] (given in `model`, drawn clamped to RGB). PSEUDO_N maps
/// each component c_i in `model` through its own list (lists[i][round(c_i (n_i - 1))]) and draws
/// the colour table entry whose index is the rounded sum of the three values.
struct ColourMapping {
    ColourMappingMethod method = ColourMappingMethod::True;
    ColourModel model = ColourModel::Rgb;    ///< PSEUDO and PSEUDO_N: the model of the data
    glm::dvec3 weights{0.0};                 ///< PSEUDO
    std::vector<glm::dvec3> colours;         ///< PSEUDO: the ramp, in `model`
    std::vector<std::vector<double>> lists;  ///< PSEUDO_N: one list per component of `model`
    bool operator==(const ColourMapping&) const = default;
};

class ColourTable;

/// The colour mapping table of a workstation: entry 0 predefined TRUE; an undefined index maps
/// as entry 0.
class ColourMappingTable {
public:
    static constexpr int kCapacity = 20;
    ColourMappingTable() { entries_[0] = ColourMapping{}; }
    /// SET COLOUR MAPPING REPRESENTATION: errors 121 (index < 0), 103 (a new entry beyond the
    /// capacity), 126 (method outside TRUE .. PSEUDO_N), 110 (a model that is none), 118 (a ramp
    /// colour component outside [0, 1]), -207 (a PSEUDO entry without colours or with a non-finite weight, a
    /// PSEUDO_N entry without three non-empty lists of finite values).
    void set(int index, const ColourMapping& mapping, ErrorLog* log, const char* function);
    const ColourMapping* find(int index) const;
    /// The entry traversal uses for `index`: entry 0 when it is not defined.
    const ColourMapping& get(int index) const;
    std::vector<int> definedIndices() const;
    /// Whether entry `index` draws every colour as it is (at once while every entry is TRUE).
    bool identity(int index) const { return allTrue_ || get(index).method == ColourMappingMethod::True; }
    /// The colour drawn for `rgb` under entry `index` (PSEUDO_N reads `colours`).
    glm::dvec3 map(int index, const glm::dvec3& rgb, const ColourTable& colours) const;
    bool operator==(const ColourMappingTable&) const = default;

private:
    std::map<int, ColourMapping> entries_;
    bool allTrue_ = true;
};

}  // namespace phigs
