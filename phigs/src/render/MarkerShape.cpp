#include "phigs/render/MarkerShape.h"

#include <algorithm>
#include <cmath>

namespace phigs::render {

MarkerShape markerShape(MarkerType type, float scale) {
    MarkerShape shape;
    const float r = 0.5f * kNominalMarkerPixels * std::max(scale, 0.0f);
    auto segment = [&](glm::vec2 a, glm::vec2 b) { shape.segments.insert(shape.segments.end(), {a, b}); };
    switch (type) {
        case MarkerType::Dot: {
            // A dot stays visible at any scale: at least 2 pixels, growing slowly with the scale.
            const float h = std::max(1.0f, 0.15f * r);
            shape.triangles = {{-h, -h}, {h, -h}, {h, h}, {-h, -h}, {h, h}, {-h, h}};
            break;
        }
        case MarkerType::Plus:
            segment({-r, 0}, {r, 0});
            segment({0, -r}, {0, r});
            break;
        case MarkerType::Asterisk: {
            segment({-r, 0}, {r, 0});
            segment({0, -r}, {0, r});
            const float d = r * 0.7071f;
            segment({-d, -d}, {d, d});
            segment({-d, d}, {d, -d});
            break;
        }
        case MarkerType::Circle: {
            const int n = std::clamp(int(std::ceil(r * 2.0f)), 12, 64);
            for (int i = 0; i < n; ++i) {
                const float a0 = 6.2831853f * float(i) / float(n), a1 = 6.2831853f * float(i + 1) / float(n);
                segment({r * std::cos(a0), r * std::sin(a0)}, {r * std::cos(a1), r * std::sin(a1)});
            }
            break;
        }
        case MarkerType::Cross:
            segment({-r, -r}, {r, r});
            segment({-r, r}, {r, -r});
            break;
    }
    return shape;
}

}  // namespace phigs::render
