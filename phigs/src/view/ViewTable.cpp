#include "phigs/view/ViewTable.h"

#include <algorithm>
#include <cmath>

namespace phigs {

ViewTable::ViewTable(int capacity) : capacity_(capacity), views_(1), defined_(1, true), priority_{0} {
}

void ViewTable::set(int index, const ViewRepresentation& view, ErrorLog* log) {
    const char* function = "SET VIEW REPRESENTATION 3";
    if (index < 1) raise(log, errors::ViewIndexBelowOne, function, "view index " + std::to_string(index));
    if (index >= capacity_)
        raise(log, errors::ViewTableFull, function, "view index " + std::to_string(index));
    // Written so that a NaN fails them too.
    for (int i = 0; i < 3; ++i) {
        if (!(view.clipMin[i] <= view.clipMax[i]) || (i < 2 && view.clipMin[i] == view.clipMax[i]))
            raise(log, errors::InvalidClipLimits, function);
        if (!(view.clipMin[i] >= 0.0) || !(view.clipMax[i] <= 1.0))
            raise(log, errors::ClipLimitsOutsideNpc, function);
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(view.orientation[c][r]) || !std::isfinite(view.mapping[c][r]))
                raise(log, errors::NonFiniteValue, function,
                      "a view orientation or mapping entry is not finite");
    auto slot = static_cast<std::size_t>(index);
    if (views_.size() <= slot) {
        views_.resize(slot + 1);
        defined_.resize(slot + 1, false);
    }
    views_[slot] = view;
    if (!defined_[slot]) {
        defined_[slot] = true;
        // A new entry ranks below every entry defined before it.
        priority_.push_back(index);
    }
}

bool ViewTable::defined(int index) const {
    return index >= 0 && static_cast<std::size_t>(index) < defined_.size() &&
           defined_[static_cast<std::size_t>(index)];
}

const ViewRepresentation& ViewTable::get(int index) const {
    return defined(index) ? views_[static_cast<std::size_t>(index)] : views_[0];
}

std::vector<int> ViewTable::definedIndices() const {
    std::vector<int> out;
    for (std::size_t i = 0; i < defined_.size(); ++i)
        if (defined_[i]) out.push_back(static_cast<int>(i));
    return out;
}

std::vector<ViewRepresentation> ViewTable::entries() const {
    std::vector<ViewRepresentation> out;
    for (std::size_t i = 0; i < views_.size(); ++i) out.push_back(defined_[i] ? views_[i] : views_[0]);
    return out;
}

void ViewTable::setInputPriority(int index, int reference, bool higher, ErrorLog* log) {
    const char* function = "SET VIEW TRANSFORMATION INPUT PRIORITY";
    if (index < 0 || reference < 0) raise(log, errors::ViewIndexBelowZero, function);
    if (!defined(index) || !defined(reference))
        raise(log, errors::RepresentationNotDefined, function,
              "view " + std::to_string(defined(index) ? reference : index));
    if (index == reference) return;
    std::erase(priority_, index);
    auto at = std::find(priority_.begin(), priority_.end(), reference);
    priority_.insert(higher ? at : at + 1, index);
}

}  // namespace phigs
