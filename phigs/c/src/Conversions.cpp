#include "Conversions.h"

#include <array>

namespace phigs::c {

namespace {

/// Paspect's order (the index) to the core's aspects.
constexpr std::array<AspectId, 30> kAspects = {
    AspectId::LineType,           AspectId::LinewidthScale,
    AspectId::PolylineColour,     AspectId::MarkerType,
    AspectId::MarkerSizeScale,    AspectId::PolymarkerColour,
    AspectId::TextFont,           AspectId::TextPrecision,
    AspectId::CharacterExpansion, AspectId::CharacterSpacing,
    AspectId::TextColour,         AspectId::InteriorStyle,
    AspectId::InteriorStyleIndex, AspectId::InteriorColour,
    AspectId::EdgeFlag,           AspectId::EdgeType,
    AspectId::EdgewidthScale,     AspectId::EdgeColour,
    AspectId::PolylineShading,    AspectId::InteriorShading,
    AspectId::AreaProperties,     AspectId::InteriorReflectance,
    AspectId::BackInteriorStyle,  AspectId::BackInteriorStyleIndex,
    AspectId::BackInteriorColour, AspectId::BackInteriorShading,
    AspectId::BackAreaProperties, AspectId::BackInteriorReflectance,
    AspectId::CurveApproximation, AspectId::SurfaceApproximation};
static_assert(kAspects.size() == std::size_t(PASPECT_SURF_APPROX_CRIT) + 1);
static_assert(kAspects.size() == std::size_t(AspectId::Count_));

}  // namespace

int aspectOf(int paspect) {
    if (paspect < 0 || paspect >= int(kAspects.size())) return -1;
    return int(kAspects[std::size_t(paspect)]);
}

Paspect paspectOf(AspectId aspect) {
    for (std::size_t i = 0; i < kAspects.size(); ++i)
        if (kAspects[i] == aspect) return static_cast<Paspect>(i);
    return PASPECT_LINETYPE;
}

std::vector<glm::dvec3> points(const Ppoint_list3* list, const char* function) {
    require(list, function);
    std::vector<glm::dvec3> out(count(list->num_points, function));
    if (!out.empty()) require(list->points, function);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {list->points[i].x, list->points[i].y, list->points[i].z};
    return out;
}

std::vector<glm::dvec3> points(const Ppoint_list* list, const char* function) {
    require(list, function);
    std::vector<glm::dvec3> out(count(list->num_points, function));
    if (!out.empty()) require(list->points, function);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {list->points[i].x, list->points[i].y, 0.0};
    return out;
}

std::vector<int> ints(const Pint_list* list, const char* function) {
    require(list, function);
    std::vector<int> out(count(list->num_ints, function));
    if (!out.empty()) require(list->ints, function);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = list->ints[i];
    return out;
}

glm::dmat4 toGlm(Pmatrix3 m) {
    glm::dmat4 g;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) g[c][r] = m[r][c];
    return g;
}

glm::dmat3 toGlm(Pmatrix m) {
    glm::dmat3 g;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) g[c][r] = m[r][c];
    return g;
}

void fromGlm(const glm::dmat4& g, Pmatrix3 m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[r][c] = static_cast<Pfloat>(g[c][r]);
}

void fromGlm(const glm::dmat3& g, Pmatrix m) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[r][c] = static_cast<Pfloat>(g[c][r]);
}

// Rows and columns 0, 1 and the homogeneous 2 of a 2D matrix go to 0, 1 and 3 of the 3D one.
glm::dmat4 lift(const glm::dmat3& m) {
    static constexpr int kTo[3] = {0, 1, 3};
    glm::dmat4 g(1.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) g[kTo[c]][kTo[r]] = m[c][r];
    return g;
}

glm::dmat3 lower(const glm::dmat4& g) {
    static constexpr int kFrom[3] = {0, 1, 3};
    glm::dmat3 m;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] = g[kFrom[c]][kFrom[r]];
    return m;
}

}  // namespace phigs::c
