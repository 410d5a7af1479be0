#pragma once

#include <glm/vec2.hpp>

namespace phigs::hardcopy {

enum class PageOrientation { Portrait, Landscape };

/// The paper of a vector hardcopy and how the picture sits on it: the display surface is fitted
/// isotropically into the page less its margins and centred there. Paper and nominal pixel must
/// be finite and positive, the margin finite (std::invalid_argument when the picture is described).
struct PageSetup {
    static constexpr glm::dvec2 kA4{595.2756, 841.8898};  ///< portrait, points (1/72 inch)
    static constexpr glm::dvec2 kA3{841.8898, 1190.5512};
    static constexpr glm::dvec2 kLetter{612.0, 792.0};

    glm::dvec2 paper = kA4;  ///< either way round; the orientation decides which side is wide
    PageOrientation orientation = PageOrientation::Landscape;
    double margin = 0.0;  ///< points kept clear on every side
    /// Points per raster pixel: what the raster targets measure in pixels (line width 1, marker
    /// size, dash lengths, hatch spacing) measures this many points here.
    double nominalPixel = 0.5;
    bool background = true;  ///< paint DrawList::background over the display surface

    /// The page in points, width x height, as the orientation turns the paper.
    glm::dvec2 pageSize() const;
};

}  // namespace phigs::hardcopy
