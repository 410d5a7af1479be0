#include "acsynt/session/ScreenLayout.h"

#include <cmath>

namespace acsynt {

ScreenLayout::ScreenLayout(int w, int h) : width(w), height(h) {
    const double menuWidth = std::round(0.25 * w);
    // Rows no taller than this keep the longest item's stroke text (cap height 0.45 row) inside.
    menuRow = std::round(0.045 * h);
    const double messageHeight = std::round(0.06 * h);
    const double right = w - menuWidth;
    const double bottom = h - messageHeight;
    geometry = {0, 0, right, bottom};
    menu = {right, 0, double(w), std::round(0.5 * bottom)};
    pad = {right, menu.y1, double(w), std::round(0.78 * bottom)};
    sliders = {right, pad.y1, double(w), bottom};
    message = {0, bottom, double(w), double(h)};
}

PixelBox ScreenLayout::menuFor(std::size_t items) const {
    const double rows = std::min(menu.y1 - menu.y0, menuRow * double(items));
    return {menu.x0, menu.y0, menu.x1, menu.y0 + rows};
}

PixelBox ScreenLayout::viewBox(int index, bool fourViews) const {
    if (!fourViews) return geometry;
    const double mx = (geometry.x0 + geometry.x1) / 2, my = (geometry.y0 + geometry.y1) / 2;
    switch (index) {
        case 1:
            return {geometry.x0, geometry.y0, mx, my};  // top left: plan
        case 2:
            return {mx, geometry.y0, geometry.x1, my};  // top right: front
        case 3:
            return {geometry.x0, my, mx, geometry.y1};  // bottom left: side
        default:
            return {mx, my, geometry.x1, geometry.y1};  // bottom right: the 3D view
    }
}

PixelBox ScreenLayout::padButton(int button) const {
    const double rowHeight = (pad.y1 - pad.y0) / 4, columnWidth = (pad.x1 - pad.x0) / 3;
    if (button == 10) return {pad.x0 + 2, pad.y0 + 3 * rowHeight + 2, pad.x1 - 2, pad.y1 - 2};
    const int row = (button - 1) / 3, column = (button - 1) % 3;
    return {pad.x0 + column * columnWidth + 2, pad.y0 + row * rowHeight + 2,
            pad.x0 + (column + 1) * columnWidth - 2, pad.y0 + (row + 1) * rowHeight - 2};
}

PixelBox ScreenLayout::slider(int device) const {
    const double rowHeight = (sliders.y1 - sliders.y0) / 4;
    const double y0 = sliders.y0 + (device - 1) * rowHeight;
    // The lower part of the row: the echo structure writes "NAME: value" above the track.
    return {sliders.x0 + 6, y0 + rowHeight * 0.55, sliders.x1 - 6, y0 + rowHeight * 0.85};
}

}  // namespace acsynt
