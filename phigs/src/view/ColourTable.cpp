#include "phigs/view/WorkstationTables.h"

namespace phigs {

ColourTable::ColourTable(int capacity) : capacity_(capacity) {
    const glm::dvec3 rgb[] = {{0, 0, 0}, {1, 1, 1}, {1, 0, 0}, {0, 1, 0},
                              {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    for (int i = 0; i < 8; ++i) entries_[i] = Colour::fromRgb(rgb[i]);
}

void ColourTable::set(int index, const glm::dvec3& rgb, ErrorLog* log, ColourModel model) {
    const char* function = "SET COLOUR REPRESENTATION";
    if (index < 0) raise(log, errors::ColourIndexBelowZero, function, "index " + std::to_string(index));
    if (index >= capacity_) raise(log, errors::BundleTableFull, function, "index " + std::to_string(index));
    for (int i = 0; i < 3; ++i)
        if (!(rgb[i] >= 0.0 && rgb[i] <= 1.0))
            raise(log, errors::BadColour, function, "component " + std::to_string(i));
    entries_[index] = Colour::inModel(model, rgb);
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
    const Colour c = given(index);
    return clampedRgb(c.model, c.rgb);
}

Colour ColourTable::given(int index) const {
    auto it = entries_.find(index);
    return it != entries_.end() ? it->second : entries_.at(1);
}

std::vector<int> ColourTable::definedIndices() const {
    std::vector<int> out;
    for (const auto& [i, c] : entries_) out.push_back(i);
    return out;
}

}  // namespace phigs
