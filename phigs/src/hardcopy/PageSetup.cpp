#include "phigs/hardcopy/PageSetup.h"

#include <algorithm>

namespace phigs::hardcopy {

glm::dvec2 PageSetup::pageSize() const {
    const double shorter = std::min(paper.x, paper.y), longer = std::max(paper.x, paper.y);
    return orientation == PageOrientation::Landscape ? glm::dvec2(longer, shorter)
                                                     : glm::dvec2(shorter, longer);
}

}  // namespace phigs::hardcopy
