#pragma once

// Conversions between phigs.h's types and the core's, checking counts and pointers first.

#include "Binding.h"
#include "phigs.h"
#include "phigs/store/Element.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace phigs::c {

/// ISO 9592: arithmetic error has occurred (a result no Pfloat holds).
inline constexpr int kArithmeticError = 908;

/// An enumeration argument as the int the application passed, read without an enum-typed
/// load: a C program may pass any int, and in C++ loading an out-of-range enum is undefined.
template <class Enum>
int raw(const Enum& value) {
    static_assert(sizeof(Enum) == sizeof(int));
    int v;
    std::memcpy(&v, &value, sizeof v);
    return v;
}

/// The core's aspect of an ASF, or -1 for a value that names none (phigs.h's Paspect puts the
/// PHIGS PLUS aspects in the sample implementation's order, the core in its own).
int aspectOf(int paspect);
/// The Paspect of a core aspect.
Paspect paspectOf(AspectId aspect);

/// A count the application gives: negative is the binding's bad-argument error.
inline std::size_t count(Pint n, const char* function) {
    if (n < 0) throw Error(kBadArgument, function, "negative count " + std::to_string(n));
    return static_cast<std::size_t>(n);
}

/// The cells of a columns x rows array (cell array, pattern): negative dimensions are the
/// bad-argument error, more cells than a Pint counts storage overflow (900), before any is read.
inline std::size_t cellCount(Pint columns, Pint rows, const char* function) {
    const std::size_t cells = count(columns, function) * count(rows, function);
    if (cells > static_cast<std::size_t>(std::numeric_limits<Pint>::max()))
        throw Error(errors::StorageOverflow, function,
                    std::to_string(columns) + " x " + std::to_string(rows) + " cells: more than 2^31 - 1");
    return cells;
}

std::vector<glm::dvec3> points(const Ppoint_list3* list, const char* function);
std::vector<glm::dvec3> points(const Ppoint_list* list, const char* function);
std::vector<int> ints(const Pint_list* list, const char* function);

/// Pmatrix3 is [row][column]; glm is column-major.
glm::dmat4 toGlm(Pmatrix3 m);
glm::dmat3 toGlm(Pmatrix m);
void fromGlm(const glm::dmat4& g, Pmatrix3 m);
void fromGlm(const glm::dmat3& g, Pmatrix m);
/// A 2D matrix as the 3D one the store keeps (z passes through) and back.
glm::dmat4 lift(const glm::dmat3& m);
glm::dmat3 lower(const glm::dmat4& m);

}  // namespace phigs::c
