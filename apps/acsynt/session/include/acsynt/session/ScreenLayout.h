#pragma once

#include "phigs/input/InputTypes.h"

#include <glm/glm.hpp>

#include <algorithm>

namespace acsynt {

/// A rectangle of screen pixels, origin at the top left, y down (as input sources give them).
struct PixelBox {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool contains(glm::dvec2 p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
    glm::dvec2 centre() const { return {(x0 + x1) / 2, (y0 + y1) / 2}; }
    /// At least one pixel each way: on a window too small for the area the device still has a
    /// (tiny) echo volume, which PHIGS requires to be non-empty.
    phigs::EchoVolume echoVolume() const {
        return {x0, std::max(x1, x0 + 1), y0, std::max(y1, y0 + 1), 0, 1};
    }
};

/// Where the session's areas lie on a W x H screen, in pixels: the geometry area (one or four
/// views), the menu panel, the pointer-valuator pad, the sliders and the message line. (The
/// workstation's phigs::WorkstationMapping turns pixels into NPC.)
struct ScreenLayout {
    ScreenLayout(int width, int height);

    int width, height;
    PixelBox geometry;   ///< the geometry window (four quadrants in four-view mode)
    PixelBox menu;       ///< the menu panel's room: rows top to bottom (choice device 1)
    double menuRow = 0;  ///< the tallest menu row
    PixelBox pad;        ///< the 3 x 3 pointer-valuator buttons and DONE
    PixelBox sliders;    ///< the continuous valuators, one row each
    PixelBox message;    ///< the message line

    /// The menu panel's echo area for `items` alternatives: rows of at most menuRow pixels.
    PixelBox menuFor(std::size_t items) const;
    /// The pixel box of view `index` (1..4 in four-view mode; 1 is the whole area otherwise).
    PixelBox viewBox(int index, bool fourViews) const;
    /// Pad button `button` (1..9 the compass row by row from the top left, 10 DONE).
    PixelBox padButton(int button) const;
    /// Slider of valuator `device` (1..4).
    PixelBox slider(int device) const;
};

}  // namespace acsynt
