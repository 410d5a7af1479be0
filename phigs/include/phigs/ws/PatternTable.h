#pragma once

#include "phigs/core/ErrorLog.h"
#include "phigs/store/Element.h"

#include <map>
#include <vector>

namespace phigs {

/// One pattern table entry: columns x rows general colours (PHIGS PLUS: indices into the colour
/// table or direct RGB), row by row.
struct PatternRepresentation {
    int columns = 1, rows = 1;
    std::vector<Colour> colours{Colour::indexed(1)};
    bool operator==(const PatternRepresentation&) const = default;
    /// A pattern of colour indices (SET PATTERN REPRESENTATION).
    static PatternRepresentation indexed(int columns, int rows, const std::vector<int>& indices);
};

/// A workstation's pattern table (SET PATTERN REPRESENTATION): entries 1 .. capacity.
class PatternTable {
public:
    explicit PatternTable(int capacity = 32) : capacity_(capacity) {}
    /// Errors 112 (index < 1), 116 (a dimension < 1 or an array of another size), 113 (a colour
    /// index < 0), 136 (a direct colour component outside [0, 1]), 103 (a new entry beyond the
    /// capacity); nothing changes on error.
    void set(int index, const PatternRepresentation& pattern, ErrorLog* log);
    /// The entry, or null when `index` is not defined.
    const PatternRepresentation* find(int index) const;
    std::vector<int> definedIndices() const;

private:
    int capacity_;
    std::map<int, PatternRepresentation> entries_;
};

}  // namespace phigs
