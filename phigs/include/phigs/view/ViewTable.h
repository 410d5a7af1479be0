#pragma once

#include "phigs/core/ErrorLog.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace phigs {

/// One view table entry (SET VIEW REPRESENTATION 3).
struct ViewRepresentation {
    glm::dmat4 orientation{1.0};  ///< world -> VRC
    glm::dmat4 mapping{1.0};      ///< VRC -> NPC
    glm::dvec3 clipMin{0.0}, clipMax{1.0};
    bool clipXY = true, clipBack = true, clipFront = true;
};

/// A workstation's view table: entry 0 is the identity view and cannot be changed; entries
/// are defined up to `capacity`; the view transformation input priority orders the entries.
class ViewTable {
public:
    explicit ViewTable(int capacity = 32);

    int capacity() const { return capacity_; }
    /// SET VIEW REPRESENTATION 3: errors 115 (index < 1), 150 (beyond capacity), 153, 154 (NaN
    /// clip limits too), -208 (a matrix entry NaN or infinite).
    void set(int index, const ViewRepresentation& view, ErrorLog* log);
    /// The entry, or entry 0 when `index` is not defined (as traversal must use it).
    const ViewRepresentation& get(int index) const;
    bool defined(int index) const;
    /// Defined indices in ascending order.
    std::vector<int> definedIndices() const;
    /// Every entry 0 .. highest defined index, undefined ones as entry 0.
    std::vector<ViewRepresentation> entries() const;

    /// SET VIEW TRANSFORMATION INPUT PRIORITY: moves `index` just above or below `reference`.
    void setInputPriority(int index, int reference, bool higher, ErrorLog* log);
    /// Defined indices from highest to lowest input priority.
    const std::vector<int>& inputPriority() const { return priority_; }

private:
    int capacity_;
    std::vector<ViewRepresentation> views_;
    std::vector<bool> defined_;
    std::vector<int> priority_;
};

}  // namespace phigs
