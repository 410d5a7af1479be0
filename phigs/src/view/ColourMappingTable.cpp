#include "phigs/view/ColourMappingTable.h"

#include "phigs/core/TransformUtilities.h"

#include "phigs/view/WorkstationTables.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace phigs {

namespace {

// ISO 9592-1 error 110 (errors::ColourModelNotAvailable lives in ws/, which includes view/).
constexpr int kColourModelNotAvailable = 110;

void checkData(const ColourMapping& m, ErrorLog* log, const char* function) {
    if (m.method != ColourMappingMethod::True && !isColourModel(static_cast<int>(m.model)))
        raise(log, kColourModelNotAvailable, function,
              "colour model " + std::to_string(static_cast<int>(m.model)));
    if (m.method == ColourMappingMethod::Pseudo) {
        if (!allFinite(m.weights))
            raise(log, errors::BadColourMappingData, function, "a weight is not finite");
        if (m.colours.empty()) raise(log, errors::BadColourMappingData, function, "PSEUDO without colours");
        for (std::size_t i = 0; i < m.colours.size(); ++i)
            for (int k = 0; k < 3; ++k)
                if (!(m.colours[i][k] >= 0.0 && m.colours[i][k] <= 1.0))
                    raise(log, errors::BadColour, function,
                          "colour " + std::to_string(i) + " component " + std::to_string(k));
    } else if (m.method == ColourMappingMethod::PseudoN) {
        if (m.lists.size() != 3)
            raise(log, errors::BadColourMappingData, function,
                  "PSEUDO_N has " + std::to_string(m.lists.size()) + " lists, a colour model needs 3");
        for (std::size_t i = 0; i < m.lists.size(); ++i) {
            if (m.lists[i].empty())
                raise(log, errors::BadColourMappingData, function, "list " + std::to_string(i) + " is empty");
            for (double v : m.lists[i])
                if (!std::isfinite(v))
                    raise(log, errors::BadColourMappingData, function,
                          "list " + std::to_string(i) + " holds a value that is not finite");
        }
    }
}

std::size_t slot(double value, std::size_t count) {
    const double v = std::clamp(value, 0.0, 1.0) * static_cast<double>(count - 1);
    return std::min(count - 1, static_cast<std::size_t>(std::lround(v)));
}

}  // namespace

void ColourMappingTable::set(int index, const ColourMapping& mapping, ErrorLog* log, const char* function) {
    const std::string where = "index " + std::to_string(index);
    if (index < 0) raise(log, errors::ColourMappingIndexBelowZero, function, where);
    if (!entries_.contains(index) && static_cast<int>(entries_.size()) >= kCapacity)
        raise(log, errors::BundleTableFull, function, where);
    const int method = static_cast<int>(mapping.method);
    if (method < 1 || method > 3)
        raise(log, errors::ColourMappingMethodNotAvailable, function, "method " + std::to_string(method));
    checkData(mapping, log, function);
    ColourMapping kept = mapping;  // only the data of its method
    if (kept.method != ColourMappingMethod::Pseudo) kept.weights = glm::dvec3(0.0), kept.colours.clear();
    if (kept.method != ColourMappingMethod::PseudoN) kept.lists.clear();
    if (kept.method == ColourMappingMethod::True) kept.model = ColourModel::Rgb;
    entries_[index] = std::move(kept);
    allTrue_ = std::all_of(entries_.begin(), entries_.end(),
                           [](const auto& e) { return e.second.method == ColourMappingMethod::True; });
}

const ColourMapping* ColourMappingTable::find(int index) const {
    auto it = entries_.find(index);
    return it != entries_.end() ? &it->second : nullptr;
}

const ColourMapping& ColourMappingTable::get(int index) const {
    const ColourMapping* m = find(index);
    return m ? *m : entries_.at(0);
}

std::vector<int> ColourMappingTable::definedIndices() const {
    std::vector<int> out;
    for (const auto& [i, m] : entries_) out.push_back(i);
    return out;
}

glm::dvec3 ColourMappingTable::map(int index, const glm::dvec3& rgb, const ColourTable& colours) const {
    const ColourMapping& m = get(index);
    if (m.method == ColourMappingMethod::True) return rgb;
    const glm::dvec3 c = fromRgb(m.model, rgb);
    switch (m.method) {
        case ColourMappingMethod::Pseudo:
            return clampedRgb(m.model, m.colours[slot(glm::dot(m.weights, c), m.colours.size())]);
        case ColourMappingMethod::PseudoN: {
            double sum = 0.0;
            for (int k = 0; k < 3; ++k) sum += m.lists[k][slot(c[k], m.lists[k].size())];
            const double rounded = std::round(sum);
            return colours.get(rounded >= 0.0 && rounded < 1e9 ? static_cast<int>(rounded) : 1);
        }
        case ColourMappingMethod::True:
            break;
    }
    return rgb;
}

}  // namespace phigs
