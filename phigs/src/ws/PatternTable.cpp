#include "phigs/ws/PatternTable.h"

#include "phigs/core/Error.h"
#include "phigs/view/WorkstationTables.h"
#include "phigs/ws/WorkstationErrors.h"

#include <string>

namespace phigs {

PatternRepresentation PatternRepresentation::indexed(int columns, int rows, const std::vector<int>& indices) {
    PatternRepresentation p{columns, rows, {}};
    for (int i : indices) p.colours.push_back(Colour::indexed(i));
    return p;
}

void PatternTable::set(int index, const PatternRepresentation& p, ErrorLog* log) {
    const char* function = "SET PATTERN REPRESENTATION";
    const std::string where = "pattern index " + std::to_string(index);
    if (index < 1) raise(log, errors::PatternIndexBelowOne, function, where);
    if (p.columns < 1 || p.rows < 1 ||
        p.colours.size() != static_cast<std::size_t>(p.columns) * static_cast<std::size_t>(p.rows))
        raise(log, errors::BadPatternDimensions, function,
              where + ": " + std::to_string(p.columns) + " x " + std::to_string(p.rows) + " with " +
                  std::to_string(p.colours.size()) + " colours");
    for (const Colour& c : p.colours) ColourTable::check(c, log, function);
    if (!entries_.contains(index) && static_cast<int>(entries_.size()) >= capacity_)
        raise(log, errors::BundleTableFull, function, where);
    entries_[index] = p;
}

const PatternRepresentation* PatternTable::find(int index) const {
    auto it = entries_.find(index);
    return it == entries_.end() ? nullptr : &it->second;
}

std::vector<int> PatternTable::definedIndices() const {
    std::vector<int> out;
    for (const auto& [i, p] : entries_) out.push_back(i);
    return out;
}

}  // namespace phigs
