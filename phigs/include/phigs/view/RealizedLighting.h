#pragma once

// What a workstation draws for a light source or depth cue representation: the REALIZED values
// of INQUIRE LIGHT SOURCE / DEPTH CUE REPRESENTATION, and what traversal hands the renderers.

#include "phigs/core/Attributes.h"

namespace phigs {

/// The light source drawn: colour clamped to [0, 1], direction of unit length ((0, 0, -1) for a
/// zero one), attenuation coefficients at least 0, spot concentration exponent in [0, 128], spread
/// angle in [0, pi]; type and position as set.
Light realized(const Light& l);
/// The depth cue drawn: reference planes and scale factors clamped to [0, 1], the planes ordered
/// front >= back (a reversed pair swaps, each plane keeping its scale), colour clamped to [0, 1].
DepthCue realized(const DepthCue& d);

}  // namespace phigs
