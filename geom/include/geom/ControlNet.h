#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace geom {

/// Homogeneous control points (w*P, w) grouped in blocks of `stride`: a curve is blocks of one,
/// a surface seen along u is blocks of countV (one row of the net each). Knot algorithms work
/// on whole blocks, so one implementation serves curves and both surface directions.
struct ControlNet {
    std::size_t stride = 1;
    std::vector<glm::dvec4> data;

    std::size_t blocks() const { return stride == 0 ? 0 : data.size() / stride; }
    glm::dvec4* block(std::size_t i) { return data.data() + i * stride; }
    const glm::dvec4* block(std::size_t i) const { return data.data() + i * stride; }
};

/// The curve's control points as a net of blocks of one.
ControlNet homogeneousNet(const Curve& curve);
/// The surface's net along u (blocks are rows of countV points); transposed when alongV.
ControlNet homogeneousNet(const Surface& surface, bool alongV);
/// Back from homogeneous form; weights are kept only when the input was rational.
void setFromNet(Curve& curve, const ControlNet& net, bool rational);
/// Back from homogeneous form, undoing the transposition when alongV.
void setFromNet(Surface& surface, const ControlNet& net, bool alongV, bool rational);

/// Knot insertion (A5.1) on a net; knots and net are replaced together. `where` names the
/// caller in error messages. Throws GeometryError before changing anything.
void insertKnotInNet(int degree, std::vector<double>& knots, ControlNet& net, double u, int times,
                     const char* where);
/// Knot refinement (A5.4) on a net; `inserted` need not be sorted.
void refineNet(int degree, std::vector<double>& knots, ControlNet& net, std::vector<double> inserted,
               const char* where);

}  // namespace geom
