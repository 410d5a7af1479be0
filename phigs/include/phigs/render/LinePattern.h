#pragma once

#include "phigs/traverse/DrawList.h"

#include <array>

namespace phigs::render {

/// The on/off dash lengths of a PHIGS line type in pixels at line width 1 (they scale with the
/// width); the shader uses the same table (shaders/pattern.glsl).
struct LinePattern {
    std::array<float, 4> lengths{};  ///< on, off, on, off
    float period = 0.0f;             ///< 0: solid
};

LinePattern linePattern(LineType type);

/// Whether the pattern draws at `distance` pixels along the line (with width `width`).
bool linePatternOn(LineType type, float width, float distance);

}  // namespace phigs::render
