#pragma once

// One list of fields per element payload, shared by the archive's writer and reader and by the
// element checks: fields(visitor, payload) calls visitor(field) for each field in file order.
// The leading type token already says 2D / 3D, add / remove and which tagged attribute, so
// those are not fields. A field added by a later archive format version comes after a
// since(v, version) test: a reader of an older file (a visitor with a `version` member below it)
// skips the field and leaves its default; every other visitor sees it.

#include "phigs/store/Element.h"

namespace phigs::detail {

/// Whether visitor `v` takes the fields that archive format `version` added.
template <class V>
constexpr bool since(const V& v, int version) {
    if constexpr (requires { v.version; })
        return v.version >= version;
    else
        return true;
}

template <class V>
void fields(V& v, PolylineElement& e) {
    v(e.points);
}
template <class V>
void fields(V& v, PolymarkerElement& e) {
    v(e.points);
}
template <class V>
void fields(V& v, FillAreaElement& e) {
    v(e.points);
}
template <class V>
void fields(V& v, FillAreaSetElement& e) {
    v(e.contours);
}
template <class V>
void fields(V& v, TextElement& e) {
    v(e.position), v(e.direction1), v(e.direction2), v(e.text);
}
template <class V>
void fields(V& v, AnnotationTextElement& e) {
    v(e.reference), v(e.offset), v(e.text);
}
template <class V>
void fields(V& v, CellArrayElement& e) {
    v(e.p), v(e.q), v(e.r), v(e.columns), v(e.rows), v(e.colourIndices);
}
template <class V>
void fields(V& v, NurbsCurveElement& e) {
    v(e.curve), v(e.rangeStart), v(e.rangeEnd);
}
template <class V>
void fields(V& v, NurbsSurfaceElement& e) {
    v(e.surface), v(e.trimLoops);
    if (since(v, 3)) v(e.trimDisplay);
}
template <class V>
void fields(V& v, FillAreaSetWithDataElement& e) {
    v(e.contours), v(e.vertexColours), v(e.vertexNormals), v(e.hasFacetColour), v(e.facetColour),
        v(e.hasFacetNormal), v(e.facetNormal);
    if (since(v, 2)) v(e.edgeFlags);
}
template <class V>
void fields(V& v, TriangleStripElement& e) {
    v(e.points), v(e.vertexColours), v(e.vertexNormals);
    if (since(v, 2)) v(e.facetColours), v(e.facetNormals);
}
template <class V>
void fields(V& v, QuadrilateralMeshElement& e) {
    v(e.rows), v(e.columns), v(e.points), v(e.vertexColours), v(e.vertexNormals);
    if (since(v, 2)) v(e.facetColours), v(e.facetNormals);
}
template <class V>
void fields(V& v, PolylineSetWithDataElement& e) {
    v(e.polylines), v(e.vertexColours);
}
template <class V>
void fields(V& v, CellArrayPlusElement& e) {
    v(e.p), v(e.q), v(e.r), v(e.columns), v(e.rows), v(e.colours);
}
template <class V>
void fields(V& v, SetOfFillAreaSetsElement& e) {
    v(e.vertices), v(e.vertexColours), v(e.vertexNormals), v(e.sets), v(e.facetColours), v(e.facetNormals),
        v(e.edgeFlags);
}
template <class V>
void fields(V& v, IndexAttribute& e) {
    v(e.value);
}
template <class V>
void fields(V& v, RealAttribute& e) {
    v(e.value);
}
template <class V>
void fields(V& v, ColourAttribute& e) {
    v(e.colour);
}
template <class V>
void fields(V& v, UpVectorAttribute& e) {
    v(e.up);
}
template <class V>
void fields(V& v, PatternAttribute& e) {  // e.type is set before a reader calls this
    if (e.type == ElementType::PatternSize) {
        v(e.size);
        return;
    }
    v(e.referencePoint);
    if (e.type == ElementType::PatternReferencePointAndVectors) v(e.vectorX), v(e.vectorY);
}
template <class V>
void fields(V& v, AlignmentAttribute& e) {
    v(e.horizontal), v(e.vertical);
}
template <class V>
void fields(V& v, AreaPropertiesAttribute& e) {
    v(e.ambient), v(e.diffuse), v(e.specular), v(e.specularColour), v(e.specularExponent), v(e.transparency);
}
template <class V>
void fields(V& v, AsfAttribute& e) {
    v(e.aspect), v(e.individual);
}
template <class V>
void fields(V& v, ApproximationAttribute& e) {
    v(e.criteria), v(e.valueU), v(e.valueV);
}
template <class V>
void fields(V& v, SurfaceCharacteristicsAttribute& e) {
    v(e.style), v(e.placement), v(e.curvesU), v(e.curvesV);
    if (since(v, 2)) v(e.origin), v(e.direction), v(e.levels);
}
template <class V>
void fields(V& v, LightSourceStateAttribute& e) {
    v(e.activate), v(e.deactivate);
}
template <class V>
void fields(V& v, TransformElement& e) {
    v(e.matrix), v(e.composition);
}
template <class V>
void fields(V& v, ModelClipElement& e) {
    v(e.op), v(e.halfSpaces);
}
template <class V>
void fields(V&, RestoreModelClipElement&) {
}
template <class V>
void fields(V& v, NameSetElement& e) {
    v(e.names);
}
template <class V>
void fields(V& v, ExecuteStructureElement& e) {
    v(e.structureId);
}
template <class V>
void fields(V& v, LabelElement& e) {
    v(e.label);
}
template <class V>
void fields(V& v, ApplicationDataElement& e) {
    v(e.data);
}
template <class V>
void fields(V& v, GdpElement& e) {
    v(e.identifier), v(e.points), v(e.data);
}
template <class V>
void fields(V& v, GseElement& e) {
    v(e.identifier), v(e.data);
}

}  // namespace phigs::detail
