#include "phigs/view/WorkstationTables.h"

namespace phigs {

ColourTable::ColourTable(int capacity) : capacity_(capacity) {
    entries_ = {{0, {0, 0, 0}}, {1, {1, 1, 1}}, {2, {1, 0, 0}}, {3, {0, 1, 0}},
                {4, {0, 0, 1}}, {5, {1, 1, 0}}, {6, {0, 1, 1}}, {7, {1, 0, 1}}};
}

void ColourTable::set(int index, const glm::dvec3& rgb, ErrorLog* log) {
    const char* function = "SET COLOUR REPRESENTATION";
    if (index < 0) raise(log, errors::ColourIndexBelowZero, function, "index " + std::to_string(index));
    if (index >= capacity_) raise(log, errors::BundleTableFull, function, "index " + std::to_string(index));
    for (int i = 0; i < 3; ++i)
        if (!(rgb[i] >= 0.0 && rgb[i] <= 1.0))
            raise(log, errors::BadColour, function, "component " + std::to_string(i));
    entries_[index] = rgb;
}

void ColourTable::check(const Colour& colour, ErrorLog* log, const char* function) {
    if (!colour.direct) {
        if (colour.index < 0)
            raise(log, errors::ColourIndexBelowZero, function,
                  "colour index " + std::to_string(colour.index));
        return;
    }
    for (int i = 0; i < 3; ++i)
        if (!(colour.rgb[i] >= 0.0 && colour.rgb[i] <= 1.0))
            raise(log, errors::BadDirectColour, function, "direct colour component " + std::to_string(i));
}

glm::dvec3 ColourTable::get(int index) const {
    auto it = entries_.find(index);
    return it != entries_.end() ? it->second : entries_.at(1);
}

std::vector<int> ColourTable::definedIndices() const {
    std::vector<int> out;
    for (const auto& [i, c] : entries_) out.push_back(i);
    return out;
}

}  // namespace phigs
