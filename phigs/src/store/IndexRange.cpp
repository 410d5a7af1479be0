#include "phigs/store/IndexRange.h"

#include "phigs/core/Error.h"

namespace phigs {

IndexRange indexRangeError(const Element& e) {
    if (const auto* c = std::get_if<ColourAttribute>(&e))
        return !c->colour.direct && c->colour.index < 0
                   ? IndexRange{errors::ColourIndexBelowZero, c->colour.index}
                   : IndexRange{};
    const auto* a = std::get_if<IndexAttribute>(&e);
    if (a == nullptr) return {};
    using T = ElementType;
    switch (a->type) {
        case T::PolylineIndex:
        case T::PolymarkerIndex:
        case T::TextIndex:
        case T::InteriorIndex:
        case T::EdgeIndex:
            return a->value < 1 ? IndexRange{errors::BundleIndexBelowOne, a->value} : IndexRange{};
        case T::ViewIndex:
            return a->value < 0 ? IndexRange{errors::ViewIndexBelowZero, a->value} : IndexRange{};
        case T::DepthCueIndex:
            return a->value < 0 ? IndexRange{errors::DepthCueIndexBelowZero, a->value} : IndexRange{};
        case T::ColourMappingIndex:
            return a->value < 0 ? IndexRange{errors::ColourMappingIndexBelowZero, a->value} : IndexRange{};
        default:
            return {};
    }
}

}  // namespace phigs
