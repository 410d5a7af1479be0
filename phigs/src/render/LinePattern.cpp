#include "phigs/render/LinePattern.h"

#include <algorithm>
#include <cmath>

namespace phigs::render {

LinePattern linePattern(LineType type) {
    switch (type) {
        case LineType::Dashed:
            return {{12, 6, 12, 6}, 36};
        case LineType::Dotted:
            return {{2, 4, 2, 4}, 12};
        case LineType::DashDotted:
            return {{12, 5, 2, 5}, 24};
        case LineType::Solid:
            break;
    }
    return {};
}

bool linePatternOn(LineType type, float width, float distance) {
    const LinePattern p = linePattern(type);
    if (p.period == 0.0f) return true;
    const float scale = std::max(1.0f, width);
    float d = std::fmod(distance / scale, p.period);
    if (d < 0) d += p.period;
    for (int i = 0; i < 4; ++i) {
        if (d < p.lengths[i]) return i % 2 == 0;
        d -= p.lengths[i];
    }
    return false;
}

}  // namespace phigs::render
