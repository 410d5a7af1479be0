#include "phigs/core/ColourModels.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace phigs {
namespace {

/// Linear BT.709 RGB to CIE XYZ, white D65, as IEC 61966-2-1 ("sRGB", 1999) gives it: its Y row
/// sums to 1, so RGB (1, 1, 1) has Y = 1. glm is column-major.
const glm::dmat3 rgbToXyz{0.4124, 0.2126, 0.0193,  //
                          0.3576, 0.7152, 0.1192,  //
                          0.1805, 0.0722, 0.9505};
const glm::dmat3 xyzToRgb = glm::inverse(rgbToXyz);

/// The reference white's chromaticity (u', v'): that of RGB (1, 1, 1).
glm::dvec2 whiteChromaticity() {
    const glm::dvec3 w = rgbToXyz * glm::dvec3(1.0);
    const double d = w.x + 15.0 * w.y + 3.0 * w.z;
    return {4.0 * w.x / d, 9.0 * w.y / d};
}

glm::dvec3 cieluvToRgb(const glm::dvec3& c) {
    const double u = c.x, v = c.y, y = c.z;
    if (!(v > 0.0)) return glm::dvec3(0.0);
    const glm::dvec3 xyz{y * 9.0 * u / (4.0 * v), y, y * (12.0 - 3.0 * u - 20.0 * v) / (4.0 * v)};
    return xyzToRgb * xyz;
}

glm::dvec3 rgbToCieluv(const glm::dvec3& rgb) {
    const glm::dvec3 xyz = rgbToXyz * rgb;
    const double d = xyz.x + 15.0 * xyz.y + 3.0 * xyz.z;
    if (!(d > 0.0)) {
        const glm::dvec2 w = whiteChromaticity();
        return {w.x, w.y, 0.0};
    }
    return {4.0 * xyz.x / d, 9.0 * xyz.y / d, xyz.y};
}

/// The hue (a fraction of a turn, in [0, 1)) of an RGB colour whose largest and smallest
/// components are `hi` and `lo` (hi > lo).
double hueOf(const glm::dvec3& c, double hi, double lo) {
    const double d = hi - lo;
    double h;
    if (hi == c.x)
        h = (c.y - c.z) / d;
    else if (hi == c.y)
        h = 2.0 + (c.z - c.x) / d;
    else
        h = 4.0 + (c.x - c.y) / d;
    h /= 6.0;
    if (h < 0.0) h += 1.0;
    return h >= 1.0 ? 0.0 : h;
}

/// The fully saturated RGB colour of hue `h` (a fraction of a turn), each component in [0, 1].
glm::dvec3 pureHue(double h) {
    h = 6.0 * (h - std::floor(h));
    // Each component is 1 within a sixth of a turn of its centre and falls to 0 over the next sixth.
    const auto part = [h](double centre) {
        const double d = std::abs(h - centre);
        return std::clamp(2.0 - std::min(d, 6.0 - d), 0.0, 1.0);
    };
    return {part(0.0), part(2.0), part(4.0)};
}

glm::dvec3 hsvToRgb(const glm::dvec3& c) {
    const double s = c.y, v = c.z;
    return v * (glm::dvec3(1.0) - s * (glm::dvec3(1.0) - pureHue(c.x)));
}

glm::dvec3 rgbToHsv(const glm::dvec3& rgb) {
    const double hi = std::max({rgb.x, rgb.y, rgb.z}), lo = std::min({rgb.x, rgb.y, rgb.z});
    if (!(hi > lo)) return {0.0, 0.0, hi};
    return {hueOf(rgb, hi, lo), (hi - lo) / hi, hi};
}

glm::dvec3 hlsToRgb(const glm::dvec3& c) {
    const double l = c.y, s = c.z;
    const double chroma = (1.0 - std::abs(2.0 * l - 1.0)) * s;
    return glm::dvec3(l - chroma / 2.0) + chroma * pureHue(c.x);
}

glm::dvec3 rgbToHls(const glm::dvec3& rgb) {
    const double hi = std::max({rgb.x, rgb.y, rgb.z}), lo = std::min({rgb.x, rgb.y, rgb.z});
    const double l = (hi + lo) / 2.0;
    if (!(hi > lo)) return {0.0, l, 0.0};
    return {hueOf(rgb, hi, lo), l, (hi - lo) / (1.0 - std::abs(hi + lo - 1.0))};
}

}  // namespace

bool isColourModel(int model) {
    return model >= 1 && model <= 4;
}

glm::dvec3 toRgb(ColourModel model, const glm::dvec3& c) {
    switch (model) {
        case ColourModel::Cieluv:
            return cieluvToRgb(c);
        case ColourModel::Hsv:
            return hsvToRgb(c);
        case ColourModel::Hls:
            return hlsToRgb(c);
        case ColourModel::Rgb:
            break;
    }
    return c;
}

glm::dvec3 fromRgb(ColourModel model, const glm::dvec3& rgb) {
    switch (model) {
        case ColourModel::Cieluv:
            return rgbToCieluv(rgb);
        case ColourModel::Hsv:
            return rgbToHsv(rgb);
        case ColourModel::Hls:
            return rgbToHls(rgb);
        case ColourModel::Rgb:
            break;
    }
    return rgb;
}

glm::dvec3 clampedRgb(ColourModel model, const glm::dvec3& components) {
    return glm::clamp(toRgb(model, components), glm::dvec3(0.0), glm::dvec3(1.0));
}

}  // namespace phigs
