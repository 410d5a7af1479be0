// The transformation utilities: answers in *err_ind (2 while PHIGS is closed), never the handler.

#include "Conversions.h"
#include "Inquiry.h"
#include "phigs.h"
#include "phigs/core/TransformUtilities.h"
#include "phigs/view/ViewMatrices.h"

#include <cmath>

using namespace phigs;
using phigs::c::inquire;

namespace {

glm::dvec3 vec(const Pvec3* v) {
    c::require(v, "transformation utility");
    return {v->delta_x, v->delta_y, v->delta_z};
}
glm::dvec2 vec(const Pvec* v) {
    c::require(v, "transformation utility");
    return {v->delta_x, v->delta_y};
}
glm::dvec3 point(const Ppoint3* p) {
    c::require(p, "transformation utility");
    return {p->x, p->y, p->z};
}
glm::dvec2 point(const Ppoint* p) {
    c::require(p, "transformation utility");
    return {p->x, p->y};
}

/// Writes the matrix a utility made, unless an entry is not finite as a Pfloat (a NaN or infinite
/// argument, or an overflow): that is the arithmetic error, and `out` is left as it was.
template <class Matrix, class Out>
void answer(const Matrix& m, Out out, const char* function) {
    c::require(out, function);
    for (int column = 0; column < Matrix::length(); ++column)
        for (int row = 0; row < Matrix::length(); ++row)
            if (!std::isfinite(static_cast<Pfloat>(m[column][row])))
                throw Error(
                    c::kArithmeticError, function,
                    "the matrix is not finite: an argument is NaN or infinite, or a product overflows");
    c::fromGlm(m, out);
}

}  // namespace

extern "C" {

void ptranslate3(const Pvec3* v, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) { answer(translate3(vec(v)), m, "TRANSLATE 3"); });
}
void ptranslate(const Pvec* v, Pint* err, Pmatrix m) {
    inquire(err, [&](Phigs&) { answer(translate2(vec(v)), m, "TRANSLATE"); });
}
void pscale3(const Pvec3* v, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) { answer(scale3(vec(v)), m, "SCALE 3"); });
}
void pscale(const Pvec* v, Pint* err, Pmatrix m) {
    inquire(err, [&](Phigs&) { answer(scale2(vec(v)), m, "SCALE"); });
}
void protate_x(Pfloat a, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) { answer(rotateX(a), m, "ROTATE X"); });
}
void protate_y(Pfloat a, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) { answer(rotateY(a), m, "ROTATE Y"); });
}
void protate_z(Pfloat a, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) { answer(rotateZ(a), m, "ROTATE Z"); });
}
void protate(Pfloat a, Pint* err, Pmatrix m) {
    inquire(err, [&](Phigs&) { answer(rotate2(a), m, "ROTATE"); });
}

void pcompose_matrix3(Pmatrix3 a, Pmatrix3 b, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) {
        c::require(a, "COMPOSE MATRIX 3");
        c::require(b, "COMPOSE MATRIX 3");
        answer(c::toGlm(a) * c::toGlm(b), m, "COMPOSE MATRIX 3");
    });
}
void pcompose_matrix(Pmatrix a, Pmatrix b, Pint* err, Pmatrix m) {
    inquire(err, [&](Phigs&) {
        c::require(a, "COMPOSE MATRIX");
        c::require(b, "COMPOSE MATRIX");
        answer(c::toGlm(a) * c::toGlm(b), m, "COMPOSE MATRIX");
    });
}

void ptran_point3(const Ppoint3* p, Pmatrix3 m, Pint* err, Ppoint3* r) {
    inquire(err, [&](Phigs&) {
        c::require(m, "TRANSFORM POINT 3");
        c::require(r, "TRANSFORM POINT 3");
        const auto q = transformPoint3(c::toGlm(m), point(p));
        if (!q) throw Error(c::kArithmeticError, "TRANSFORM POINT 3");
        *r = {static_cast<Pfloat>(q->x), static_cast<Pfloat>(q->y), static_cast<Pfloat>(q->z)};
    });
}
void ptran_point(const Ppoint* p, Pmatrix m, Pint* err, Ppoint* r) {
    inquire(err, [&](Phigs&) {
        c::require(m, "TRANSFORM POINT");
        c::require(r, "TRANSFORM POINT");
        const auto q = transformPoint2(c::toGlm(m), point(p));
        if (!q) throw Error(c::kArithmeticError, "TRANSFORM POINT");
        *r = {static_cast<Pfloat>(q->x), static_cast<Pfloat>(q->y)};
    });
}

void pbuild_tran_matrix3(const Ppoint3* p, const Pvec3* shift, Pfloat x, Pfloat y, Pfloat z,
                         const Pvec3* scale, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) {
        answer(buildTransformationMatrix3(point(p), vec(shift), {x, y, z}, vec(scale)), m,
               "BUILD TRANSFORMATION MATRIX 3");
    });
}
void pbuild_tran_matrix(const Ppoint* p, const Pvec* shift, Pfloat angle, const Pvec* scale, Pint* err,
                        Pmatrix m) {
    inquire(err, [&](Phigs&) {
        answer(buildTransformationMatrix2(point(p), vec(shift), angle, vec(scale)), m,
               "BUILD TRANSFORMATION MATRIX");
    });
}
void pcompose_tran_matrix3(Pmatrix3 in, const Ppoint3* p, const Pvec3* shift, Pfloat x, Pfloat y, Pfloat z,
                           const Pvec3* scale, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) {
        c::require(in, "COMPOSE TRANSFORMATION MATRIX 3");
        answer(composeTransformationMatrix3(c::toGlm(in), point(p), vec(shift), {x, y, z}, vec(scale)), m,
               "COMPOSE TRANSFORMATION MATRIX 3");
    });
}
void pcompose_tran_matrix(Pmatrix in, const Ppoint* p, const Pvec* shift, Pfloat angle, const Pvec* scale,
                          Pint* err, Pmatrix m) {
    inquire(err, [&](Phigs&) {
        c::require(in, "COMPOSE TRANSFORMATION MATRIX");
        answer(composeTransformationMatrix2(c::toGlm(in), point(p), vec(shift), angle, vec(scale)), m,
               "COMPOSE TRANSFORMATION MATRIX");
    });
}

void peval_view_ori_matrix3(const Ppoint3* vrp, const Pvec3* vpn, const Pvec3* vup, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) {
        answer(evaluateViewOrientationMatrix(point(vrp), vec(vpn), vec(vup)), m,
               "EVALUATE VIEW ORIENTATION MATRIX 3");
    });
}

// The 2D form: the view plane normal is +z and the view reference point lies in z = 0.
void peval_view_ori_matrix(const Ppoint* vrp, const Pvec* vup, Pint* err, Pmatrix m) {
    inquire(err, [&](Phigs&) {
        const glm::dvec2 r = point(vrp), u = vec(vup);
        answer(c::lower(evaluateViewOrientationMatrix({r, 0.0}, {0, 0, 1}, {u, 0.0})), m,
               "EVALUATE VIEW ORIENTATION MATRIX");
    });
}

void peval_view_map_matrix3(const Pview_map3* map, Pint* err, Pmatrix3 m) {
    inquire(err, [&](Phigs&) {
        c::require(map, "EVALUATE VIEW MAPPING MATRIX 3");
        const int type = c::raw(map->proj_type);
        if (type != PTYPE_PARAL && type != PTYPE_PERSPECT)
            throw Error(PE_ENUM_TYPE_INVAL, "EVALUATE VIEW MAPPING MATRIX 3");
        ViewMapping v;
        v.windowMin = {map->win.x_min, map->win.y_min};
        v.windowMax = {map->win.x_max, map->win.y_max};
        v.viewportMin = {map->proj_vp.x_min, map->proj_vp.y_min, map->proj_vp.z_min};
        v.viewportMax = {map->proj_vp.x_max, map->proj_vp.y_max, map->proj_vp.z_max};
        v.projection = type == PTYPE_PARAL ? ProjectionType::Parallel : ProjectionType::Perspective;
        v.projectionReferencePoint = point(&map->proj_ref_point);
        v.viewPlaneDistance = map->view_plane;
        v.backPlaneDistance = map->back_plane;
        v.frontPlaneDistance = map->front_plane;
        answer(evaluateViewMappingMatrix(v), m, "EVALUATE VIEW MAPPING MATRIX 3");
    });
}

// The 2D form: the window onto the projection viewport, parallel, at z = 0.
void peval_view_map_matrix(const Pview_map* map, Pint* err, Pmatrix m) {
    inquire(err, [&](Phigs&) {
        c::require(map, "EVALUATE VIEW MAPPING MATRIX");
        ViewMapping v;
        v.windowMin = {map->win.x_min, map->win.y_min};
        v.windowMax = {map->win.x_max, map->win.y_max};
        v.viewportMin = {map->proj_vp.x_min, map->proj_vp.y_min, 0.0};
        v.viewportMax = {map->proj_vp.x_max, map->proj_vp.y_max, 1.0};
        v.projectionReferencePoint = {(v.windowMin.x + v.windowMax.x) / 2,
                                      (v.windowMin.y + v.windowMax.y) / 2, 1.0};
        answer(c::lower(evaluateViewMappingMatrix(v)), m, "EVALUATE VIEW MAPPING MATRIX");
    });
}

}  // extern "C"
