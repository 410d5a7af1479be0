#pragma once

#include "geom/Surface.h"

#include <cstddef>

namespace geom::curvemap {

/// The ACSYNT curve-mapping thesis's "wave": an open bicubic surface over [-size/2, size/2]^2 (x, y) with
/// heights amplitude * sin(2 pi x / wavelength) * cos(2 pi y / wavelength); uniform clamped knots 0..patchesU
/// and 0..patchesV, so patch (i, j) is the unit square [i, i+1] x [j, j+1].
Surface makeWaveSurface(std::size_t patchesU = 8, std::size_t patchesV = 8, double size = 10.0,
                        double amplitude = 0.6, double wavelength = 5.0);

/// A fuselage-like tube along x, closed in u (around: periodic bicubic with a C2 seam on top
/// at u = 0, normals outward) and open in w (along the length, x from 0 to length). The cross section is a
/// slightly flattened circle whose radius swells from 0.45 * radius at the nose to radius mid-body and 0.3 *
/// radius at the tail. Domains: u in [0, patchesU], w in [0, patchesV].
Surface makeFuselageSurface(std::size_t patchesU = 12, std::size_t patchesV = 10, double length = 30.0,
                            double radius = 5.0);

/// A tapered, swept wing along +y: a symmetric NACA 00xx section (`thickness` of the chord)
/// closed around in u (periodic; u = 0 at the trailing edge, then the lower surface, the
/// leading edge at u = patchesU / 2 and the upper surface, so normals point outward and the
/// top of mid-chord is u = 3 patchesU / 4), open along the span in w (tips are boundaries).
/// Chord `rootChord` at the root, half of it at the tip; the leading edge sweeps back by 0.2 of
/// the span. Domains: u in [0, patchesU], w in [0, patchesV].
Surface makeWingSurface(std::size_t patchesU = 20, std::size_t patchesV = 20, double span = 20.0,
                        double rootChord = 8.0, double thickness = 0.12);

}  // namespace geom::curvemap
