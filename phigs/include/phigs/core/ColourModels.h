#pragma once

// The PHIGS colour models (ISO 9592: RGB, CIE 1976 L*u*v* chromaticity, HSV, HLS) and their
// conversions to and from the workstation's RGB.
//
// Every model has three components in [0, 1]:
// - RGB: red, green, blue, linear, with the primaries of ITU-R BT.709 (as sRGB; to CIE XYZ by the
//   matrix of IEC 61966-2-1, "Multimedia systems and equipment - Colour measurement and
//   management - Part 2-1: Default RGB colour space - sRGB", 1999).
// - CIELUV: the CIE 1976 UCS chromaticity u', v' and the luminance Y relative to the reference
//   white, CIE standard illuminant D65 (u' = 0.1978, v' = 0.4683), whose Y = 1 is RGB (1, 1, 1).
//   Black (Y = 0) has the white point's chromaticity; v' = 0 is no colour and converts to black.
// - HSV: hue as a fraction of a turn (0 red, 1/3 green, 2/3 blue), saturation, value.
// - HLS: hue as in HSV, lightness, saturation (Foley, van Dam, Feiner, Hughes, "Computer
//   Graphics: Principles and Practice", 2nd ed., 1990, section 13.3).
// fromRgb(m, toRgb(m, c)) == c for every c in the model's canonical range (hue in [0, 1), and for
// HSV/HLS a defined hue: saturation > 0, value > 0 or lightness in (0, 1)); toRgb(m, fromRgb(m, rgb))
// == rgb for every RGB colour, to rounding. A CIELUV colour outside the RGB gamut converts to RGB
// components outside [0, 1]; the workstation draws them clamped (clampedRgb).

#include <cstdint>

#include <glm/vec3.hpp>

namespace phigs {

/// A PHIGS colour model, with its ISO 9592 number (PMODEL_RGB .. PMODEL_HLS in the C binding).
enum class ColourModel : std::uint8_t { Rgb = 1, Cieluv = 2, Hsv = 3, Hls = 4 };

/// Whether `model` is the number of a colour model (1 .. 4).
bool isColourModel(int model);
/// The RGB colour of `components` given in `model` (unclamped for CIELUV outside the gamut).
glm::dvec3 toRgb(ColourModel model, const glm::dvec3& components);
/// The components in `model` of the RGB colour `rgb`.
glm::dvec3 fromRgb(ColourModel model, const glm::dvec3& rgb);
/// The RGB colour a workstation draws for `components` in `model`: toRgb clamped to [0, 1].
glm::dvec3 clampedRgb(ColourModel model, const glm::dvec3& components);

}  // namespace phigs
