#pragma once

// The closed family of structure elements (ISO 9592 and 9592-4). Every element is a plain
// value type; `Element` is the variant over them. Attributes that only carry one index, one
// real or one colour share a payload tagged with their ElementType, so the family stays small
// while every PHIGS attribute keeps its own element type.

#include "geom/Curve.h"
#include "geom/Surface.h"
#include "phigs/core/ColourModels.h"
#include "phigs/store/PointList.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace phigs {

/// Every element type PHIGS (and PHIGS PLUS) knows, as the inquiries report it.
enum class ElementType : int {
    All = 0,  ///< only in search sets: matches every type
    Nil,
    Polyline3,
    Polyline,
    Polymarker3,
    Polymarker,
    FillArea3,
    FillArea,
    FillAreaSet3,
    FillAreaSet,
    Text3,
    Text,
    AnnotationTextRelative3,
    AnnotationTextRelative,
    CellArray3,
    CellArray,
    NonUniformBSplineCurve,
    NonUniformBSplineSurface,
    FillAreaSetWithData,
    TriangleStrip,
    QuadrilateralMesh,
    PolylineSetWithData,
    CellArrayPlus,
    SetOfFillAreaSetsWithData,
    PolylineIndex,
    PolymarkerIndex,
    TextIndex,
    InteriorIndex,
    EdgeIndex,
    Linetype,
    LinewidthScaleFactor,
    PolylineColour,
    PolylineShadingMethod,
    MarkerType,
    MarkerSizeScaleFactor,
    PolymarkerColour,
    TextFont,
    TextPrecision,
    CharacterExpansionFactor,
    CharacterSpacing,
    TextColour,
    CharacterHeight,
    CharacterUpVector,
    TextPath,
    TextAlignment,
    AnnotationTextCharacterHeight,
    AnnotationTextCharacterUpVector,
    AnnotationTextPath,
    AnnotationTextAlignment,
    AnnotationStyle,
    InteriorStyle,
    InteriorStyleIndex,
    InteriorColour,
    BackInteriorStyle,
    BackInteriorStyleIndex,
    BackInteriorColour,
    InteriorShadingMethod,
    BackInteriorShadingMethod,
    InteriorReflectanceEquation,
    BackInteriorReflectanceEquation,
    AreaProperties,
    BackAreaProperties,
    FaceDistinguishingMode,
    FaceCullingMode,
    EdgeFlag,
    Edgetype,
    EdgewidthScaleFactor,
    EdgeColour,
    IndividualAsf,
    CurveApproximationCriteria,
    SurfaceApproximationCriteria,
    ParametricSurfaceCharacteristics,
    LightSourceState,
    DepthCueIndex,
    ColourMappingIndex,
    RenderingColourModel,
    AddNamesToSet,
    RemoveNamesFromSet,
    LocalModellingTransformation3,
    LocalModellingTransformation,
    GlobalModellingTransformation3,
    GlobalModellingTransformation,
    ModelClippingVolume3,
    ModelClippingVolume,
    ModelClippingIndicator,
    RestoreModelClippingVolume,
    ViewIndex,
    ExecuteStructure,
    Label,
    ApplicationData,
    PickId,
    HlhsrIdentifier,
    GeneralizedDrawingPrimitive3,
    GeneralizedDrawingPrimitive,
    GeneralizedStructureElement,
    PatternSize,
    PatternReferencePoint,
    PatternReferencePointAndVectors,
    Count_  ///< number of types, not a type
};

/// The PHIGS name of an element type ("POLYLINE 3", "SET LINETYPE", ...).
std::string_view elementTypeName(ElementType type);
/// The type whose name is `name`, or ElementType::Count_.
ElementType elementTypeFromName(std::string_view name);

/// A colour as PHIGS PLUS has it: an index into the workstation colour table, or direct, its
/// three components (`rgb`) given in colour model `model` (ColourModels.h; RGB unless set).
struct Colour {
    bool direct = false;
    ColourModel model = ColourModel::Rgb;
    int index = 1;
    glm::dvec3 rgb{1.0};
    static Colour indexed(int i) { return {false, ColourModel::Rgb, i, glm::dvec3(1.0)}; }
    static Colour fromRgb(glm::dvec3 c) { return {true, ColourModel::Rgb, 0, c}; }
    static Colour inModel(ColourModel m, glm::dvec3 c) { return {true, m, 0, c}; }
    /// Equal when they name the same colour (an indexed colour's rgb and a direct one's index are unused).
    bool operator==(const Colour& o) const {
        return direct == o.direct && (direct ? model == o.model && rgb == o.rgb : index == o.index);
    }
};

// ---- output primitives. 2D forms keep z = 0 and set twoD, so inquiries report the 2D type.

/// POLYLINE 3 / POLYLINE.
struct PolylineElement {
    [[no_unique_address]] PointList points;  ///< twoD lies in its tail padding
    bool twoD = false;
    bool operator==(const PolylineElement&) const = default;
};
/// POLYMARKER 3 / POLYMARKER.
struct PolymarkerElement {
    [[no_unique_address]] PointList points;  ///< twoD lies in its tail padding
    bool twoD = false;
    bool operator==(const PolymarkerElement&) const = default;
};
/// FILL AREA 3 / FILL AREA.
struct FillAreaElement {
    [[no_unique_address]] PointList points;  ///< twoD lies in its tail padding
    bool twoD = false;
    bool operator==(const FillAreaElement&) const = default;
};
/// FILL AREA SET 3 / FILL AREA SET: the first contour bounds, later ones may be holes.
struct FillAreaSetElement {
    std::vector<std::vector<glm::dvec3>> contours;
    bool twoD = false;
    bool operator==(const FillAreaSetElement&) const = default;
};
/// TEXT 3 (text point and two direction vectors spanning the text plane) / TEXT.
struct TextElement {
    glm::dvec3 position{0.0};
    glm::dvec3 direction1{1, 0, 0};
    glm::dvec3 direction2{0, 1, 0};
    std::string text;
    bool twoD = false;
    bool operator==(const TextElement&) const = default;
};
/// ANNOTATION TEXT RELATIVE 3 / ANNOTATION TEXT RELATIVE: reference point (modelling) + NPC offset.
struct AnnotationTextElement {
    glm::dvec3 reference{0.0};
    glm::dvec3 offset{0.0};
    std::string text;
    bool twoD = false;
    bool operator==(const AnnotationTextElement&) const = default;
};
/// CELL ARRAY 3 (parallelogram P, Q, R) / CELL ARRAY (twoD: rectangle of opposite corners P, Q in
/// z = 0, R unused): colour indices, row by row from P.
struct CellArrayElement {
    glm::dvec3 p{0.0}, q{1, 0, 0}, r{0, 1, 0};
    int columns = 0, rows = 0;
    std::vector<int> colourIndices;  ///< columns * rows
    bool twoD = false;
    bool operator==(const CellArrayElement&) const = default;
};
/// NON-UNIFORM B-SPLINE CURVE (PHIGS PLUS): order = degree + 1, knots, (rational) points, range.
struct NurbsCurveElement {
    geom::Curve curve;
    double rangeStart = 0.0, rangeEnd = 0.0;  ///< equal: the whole domain; else start < end inside it
    bool operator==(const NurbsCurveElement& o) const;
};
/// One trimming curve of a NURBS surface, in (u, v) parameter space (z ignored).
using TrimLoop = std::vector<geom::Curve>;
/// How one trimming curve shows (PHIGS PLUS): a visible one is drawn along the surface as an
/// edge while the edge flag is on; its approximation criteria (as SET CURVE APPROXIMATION
/// CRITERIA's, chordal values measured in (u, v)) say how finely it is followed, for trimming
/// and for drawing.
struct TrimCurveDisplay {
    bool visible = false;
    int approximation = 1;  ///< 1 workstation dependent, 2 constant between knots, 3..8 chordal
    double approximationValue = 1.0;
    bool operator==(const TrimCurveDisplay&) const = default;
};
/// NON-UNIFORM B-SPLINE SURFACE with trimming loops (PHIGS PLUS).
struct NurbsSurfaceElement {
    NurbsSurfaceElement() = default;
    NurbsSurfaceElement(geom::Surface surface, std::vector<TrimLoop> trimLoops = {},
                        std::vector<TrimCurveDisplay> trimDisplay = {})
        : surface(std::move(surface)), trimLoops(std::move(trimLoops)), trimDisplay(std::move(trimDisplay)) {}

    geom::Surface surface;
    std::vector<TrimLoop> trimLoops;  ///< closed loops; the even-odd rule decides what is kept
    /// Empty (every trimming curve hidden, workstation dependent), or one per trimming curve,
    /// loop by loop.
    std::vector<TrimCurveDisplay> trimDisplay;
    /// How trimming curve `curve` (counted loop by loop) shows.
    TrimCurveDisplay displayOf(std::size_t curve) const {
        return curve < trimDisplay.size() ? trimDisplay[curve] : TrimCurveDisplay{};
    }
    bool operator==(const NurbsSurfaceElement& o) const;
};
/// FILL AREA SET 3 WITH DATA (PHIGS PLUS): optional facet colour and normal, per-vertex colours and normals.
struct FillAreaSetWithDataElement {
    std::vector<std::vector<glm::dvec3>> contours;
    std::vector<std::vector<Colour>> vertexColours;      ///< empty, or one per vertex
    std::vector<std::vector<glm::dvec3>> vertexNormals;  ///< empty, or one per vertex
    bool hasFacetColour = false;
    Colour facetColour;
    bool hasFacetNormal = false;
    glm::dvec3 facetNormal{0, 0, 1};
    /// empty, or shaped as `contours`: flag k (0 off, 1 on) is the edge from vertex k to k + 1 (cyclic)
    std::vector<std::vector<int>> edgeFlags{};
    bool operator==(const FillAreaSetWithDataElement&) const = default;
};
/// TRIANGLE STRIP 3 WITH DATA (PHIGS PLUS): triangle k has points k, k + 1, k + 2.
struct TriangleStripElement {
    std::vector<glm::dvec3> points;
    std::vector<Colour> vertexColours;       ///< empty, or one per point
    std::vector<glm::dvec3> vertexNormals;   ///< empty, or one per point
    std::vector<Colour> facetColours{};      ///< empty, or one per triangle (points - 2)
    std::vector<glm::dvec3> facetNormals{};  ///< empty, or one per triangle
    bool operator==(const TriangleStripElement&) const = default;
};
/// QUADRILATERAL MESH 3 WITH DATA (PHIGS PLUS): a rows x columns grid of points, row by row.
struct QuadrilateralMeshElement {
    int rows = 0, columns = 0;
    std::vector<glm::dvec3> points;
    std::vector<Colour> vertexColours;
    std::vector<glm::dvec3> vertexNormals;
    std::vector<Colour>
        facetColours{};  ///< empty, or one per quadrilateral ((rows-1) x (columns-1), row by row)
    std::vector<glm::dvec3> facetNormals{};  ///< empty, or one per quadrilateral
    bool operator==(const QuadrilateralMeshElement&) const = default;
};
/// POLYLINE SET 3 WITH DATA (PHIGS PLUS): polylines, optionally a colour at every vertex.
struct PolylineSetWithDataElement {
    std::vector<std::vector<glm::dvec3>> polylines;
    std::vector<std::vector<Colour>> vertexColours;  ///< empty, or one list per polyline, one per vertex
    bool operator==(const PolylineSetWithDataElement&) const = default;
};
/// CELL ARRAY 3 PLUS (PHIGS PLUS): CELL ARRAY 3 with general colours (indexed or direct), row by row.
struct CellArrayPlusElement {
    glm::dvec3 p{0.0}, q{1, 0, 0}, r{0, 1, 0};
    int columns = 0, rows = 0;
    std::vector<Colour> colours;  ///< columns * rows
    bool operator==(const CellArrayPlusElement&) const = default;
};
/// SET OF FILL AREA SETS 3 WITH DATA (PHIGS PLUS): fill area sets whose contours index one shared
/// vertex list; optional facet data per set, edge visibility per contour edge, vertex data.
struct SetOfFillAreaSetsElement {
    std::vector<glm::dvec3> vertices;
    std::vector<Colour> vertexColours;                ///< empty, or one per vertex
    std::vector<glm::dvec3> vertexNormals;            ///< empty, or one per vertex
    std::vector<std::vector<std::vector<int>>> sets;  ///< set, contour, 0-based vertex index
    std::vector<Colour> facetColours;                 ///< empty, or one per set
    std::vector<glm::dvec3> facetNormals;             ///< empty, or one per set
    /// empty, or shaped as `sets`: flag k (0 off, 1 on) is the edge from vertex k to k + 1 (cyclic)
    std::vector<std::vector<std::vector<int>>> edgeFlags;
    bool operator==(const SetOfFillAreaSetsElement&) const = default;
};

// ---- attributes

/// Every attribute whose value is one integer: bundle indices, linetype, marker type, font,
/// precision, text path, interior style (index), shading and reflectance methods, edge flag,
/// edgetype, face modes, depth cue and colour mapping indices, view index, pick id, HLHSR id,
/// annotation style, model clipping indicator, rendering colour model.
struct IndexAttribute {
    ElementType type = ElementType::PolylineIndex;
    int value = 1;
    bool operator==(const IndexAttribute&) const = default;
};
/// Every attribute whose value is one real: scale factors, expansion, spacing, heights.
struct RealAttribute {
    ElementType type = ElementType::LinewidthScaleFactor;
    double value = 1.0;
    bool operator==(const RealAttribute&) const = default;
};
/// Every colour attribute (polyline, polymarker, text, interior, back interior, edge).
struct ColourAttribute {
    ElementType type = ElementType::PolylineColour;
    Colour colour;
    bool operator==(const ColourAttribute&) const = default;
};
/// CHARACTER UP VECTOR and ANNOTATION TEXT CHARACTER UP VECTOR.
struct UpVectorAttribute {
    ElementType type = ElementType::CharacterUpVector;
    glm::dvec2 up{0, 1};
    bool operator==(const UpVectorAttribute&) const = default;
};
/// PATTERN SIZE (`size`), PATTERN REFERENCE POINT (`referencePoint` with z = 0; the vectors
/// stay the axes) and PATTERN REFERENCE POINT AND VECTORS (all three): where and how large a
/// PATTERN interior's cells lie in modelling coordinates.
struct PatternAttribute {
    ElementType type = ElementType::PatternSize;
    glm::dvec2 size{1, 1};
    glm::dvec3 referencePoint{0, 0, 0};
    glm::dvec3 vectorX{1, 0, 0}, vectorY{0, 1, 0};
    bool operator==(const PatternAttribute&) const = default;
};
/// TEXT ALIGNMENT and ANNOTATION TEXT ALIGNMENT (horizontal, vertical).
struct AlignmentAttribute {
    ElementType type = ElementType::TextAlignment;
    int horizontal = 0, vertical = 0;
    bool operator==(const AlignmentAttribute&) const = default;
};
/// SET (BACK) AREA PROPERTIES (PHIGS PLUS reflectance properties).
struct AreaPropertiesAttribute {
    ElementType type = ElementType::AreaProperties;
    double ambient = 0.3, diffuse = 0.7, specular = 0.0;
    Colour specularColour = Colour::fromRgb(glm::dvec3(1.0));
    double specularExponent = 10.0, transparency = 0.0;
    bool operator==(const AreaPropertiesAttribute&) const = default;
};
/// Which attribute an aspect source flag controls.
enum class AspectId : int {
    LineType,
    LinewidthScale,
    PolylineColour,
    MarkerType,
    MarkerSizeScale,
    PolymarkerColour,
    TextFont,
    TextPrecision,
    CharacterExpansion,
    CharacterSpacing,
    TextColour,
    InteriorStyle,
    InteriorStyleIndex,
    InteriorColour,
    EdgeFlag,
    EdgeType,
    EdgewidthScale,
    EdgeColour,
    BackInteriorStyle,
    BackInteriorStyleIndex,
    BackInteriorColour,
    InteriorShading,
    BackInteriorShading,
    InteriorReflectance,
    BackInteriorReflectance,
    AreaProperties,
    BackAreaProperties,
    PolylineShading,
    CurveApproximation,
    SurfaceApproximation,
    Count_
};
/// SET INDIVIDUAL ASF: attribute `aspect` comes from the individual value (true) or the bundle.
struct AsfAttribute {
    AspectId aspect = AspectId::LineType;
    bool individual = true;
    bool operator==(const AsfAttribute&) const = default;
};
/// SET CURVE / SURFACE APPROXIMATION CRITERIA (PHIGS PLUS): criteria type and its values.
struct ApproximationAttribute {
    ElementType type = ElementType::SurfaceApproximationCriteria;
    int criteria = 1;  ///< 1 workstation dependent, 2 constant between knots, 6 chordal deviation (WC)
    double valueU = 1.0, valueV = 1.0;
    bool operator==(const ApproximationAttribute&) const = default;
};
/// SET PARAMETRIC SURFACE CHARACTERISTICS: 1 none, 2 workstation dependent, 3 iso-curves,
/// 4 / 5 level curves in modelling / world coordinates (the surface cut by the planes through
/// origin + t * direction perpendicular to direction, one per t in levels).
struct SurfaceCharacteristicsAttribute {
    int style = 1;
    int placement = 0;  ///< iso-curves: 0 uniform, 1 at knots
    int curvesU = 0, curvesV = 0;
    glm::dvec3 origin{0.0};         ///< level curves
    glm::dvec3 direction{0, 0, 1};  ///< level curves: not zero
    std::vector<double> levels{};   ///< level curves: the parameters t
    bool operator==(const SurfaceCharacteristicsAttribute&) const = default;
};
/// SET LIGHT SOURCE STATE: indices into the workstation light source table.
struct LightSourceStateAttribute {
    std::vector<int> activate, deactivate;
    bool operator==(const LightSourceStateAttribute&) const = default;
};

// ---- transforms, clipping, names, control

/// How a modelling transform combines with the current one (ISO 9592 composition types).
enum class Composition : int { Preconcatenate = 0, Postconcatenate = 1, Replace = 2 };
/// SET LOCAL / GLOBAL MODELLING TRANSFORMATION (3). Preconcatenate: M' = M * T (T applied to the
/// coordinates first, column vectors, as PHIGS and PEX implementations compose it);
/// postconcatenate: M' = T * M; replace: M' = T.
struct TransformElement {
    ElementType type = ElementType::LocalModellingTransformation3;
    glm::dmat4 matrix{1.0};
    Composition composition = Composition::Replace;  ///< ignored for global transforms
    bool operator==(const TransformElement&) const = default;
};
/// SET MODEL CLIPPING VOLUME (3): half spaces (point, normal: kept where dot(x - p, n) >= 0).
struct ModelClipElement {
    int op = 1;  ///< 1 replace, 2 intersect
    std::vector<std::pair<glm::dvec3, glm::dvec3>> halfSpaces;
    bool twoD = false;
    bool operator==(const ModelClipElement&) const = default;
};
/// RESTORE MODEL CLIPPING VOLUME.
struct RestoreModelClipElement {
    bool operator==(const RestoreModelClipElement&) const = default;
};
/// ADD NAMES TO SET / REMOVE NAMES FROM SET.
struct NameSetElement {
    bool add = true;
    std::vector<int> names;
    bool operator==(const NameSetElement&) const = default;
};
/// EXECUTE STRUCTURE.
struct ExecuteStructureElement {
    int structureId = 0;
    bool operator==(const ExecuteStructureElement&) const = default;
};
/// LABEL.
struct LabelElement {
    int label = 0;
    bool operator==(const LabelElement&) const = default;
};
/// APPLICATION DATA: opaque bytes traversal ignores.
struct ApplicationDataElement {
    std::string data;
    bool operator==(const ApplicationDataElement&) const = default;
};

/// GENERALIZED DRAWING PRIMITIVE 3 / GENERALIZED DRAWING PRIMITIVE: an identified primitive on
/// points with a data record. Traversal draws the identifiers of phigs/store/Gdp.h and ignores
/// the others, as ISO 9592 lets a workstation do with a GDP it cannot generate.
struct GdpElement {
    int identifier = 0;
    PointList points;
    std::string data;
    bool twoD = false;
    bool operator==(const GdpElement&) const = default;
};
/// GENERALIZED STRUCTURE ELEMENT: an identified element with a data record; stored, archived
/// and inquired, and ignored by traversal (this implementation registers no GSE).
struct GseElement {
    int identifier = 0;
    std::string data;
    bool operator==(const GseElement&) const = default;
};

/// A structure element.
using Element =
    std::variant<PolylineElement, PolymarkerElement, FillAreaElement, FillAreaSetElement, TextElement,
                 AnnotationTextElement, CellArrayElement, NurbsCurveElement, NurbsSurfaceElement,
                 FillAreaSetWithDataElement, TriangleStripElement, QuadrilateralMeshElement,
                 PolylineSetWithDataElement, CellArrayPlusElement, SetOfFillAreaSetsElement, IndexAttribute,
                 RealAttribute, ColourAttribute, UpVectorAttribute, AlignmentAttribute,
                 AreaPropertiesAttribute, AsfAttribute, ApproximationAttribute,
                 SurfaceCharacteristicsAttribute, LightSourceStateAttribute, TransformElement,
                 ModelClipElement, RestoreModelClipElement, NameSetElement, ExecuteStructureElement,
                 LabelElement, ApplicationDataElement, GdpElement, GseElement, PatternAttribute>;

/// The PHIGS element type of an element.
ElementType elementType(const Element& element);
/// Which payload family carries a type (the variant index), -1 for All, Nil, Count_ and any
/// value outside the enumeration.
int payloadIndexOf(ElementType type);
/// Checks an element against the rules of its type (counts, consistent lists, the type tag
/// matching its family, every real finite); returns an empty string when valid, else the reason.
std::string validateElement(const Element& element);
/// The largest magnitude of the element's reals (points, curves and surfaces included): what a
/// binding whose reals are floats checks before it answers an element's content.
double largestMagnitude(const Element& element);
/// Approximate storage of an element in bytes (INQUIRE ELEMENT TYPE AND SIZE).
std::size_t elementSize(const Element& element);

// ---- element constructors with the PHIGS names, for readable application code
inline Element polyline3(PointList p) {
    return PolylineElement{std::move(p), false};
}
inline Element polymarker3(PointList p) {
    return PolymarkerElement{std::move(p), false};
}
inline Element fillArea3(PointList p) {
    return FillAreaElement{std::move(p), false};
}
inline Element label(int l) {
    return LabelElement{l};
}
inline Element executeStructure(int id) {
    return ExecuteStructureElement{id};
}
inline Element pickId(int id) {
    return IndexAttribute{ElementType::PickId, id};
}
inline Element viewIndex(int i) {
    return IndexAttribute{ElementType::ViewIndex, i};
}
inline Element polylineColourIndex(int i) {
    return ColourAttribute{ElementType::PolylineColour, Colour::indexed(i)};
}
inline Element addNamesToSet(std::vector<int> n) {
    return NameSetElement{true, std::move(n)};
}
inline Element removeNamesFromSet(std::vector<int> n) {
    return NameSetElement{false, std::move(n)};
}
inline Element localTransformation3(const glm::dmat4& m, Composition c) {
    return TransformElement{ElementType::LocalModellingTransformation3, m, c};
}
inline Element globalTransformation3(const glm::dmat4& m) {
    return TransformElement{ElementType::GlobalModellingTransformation3, m, Composition::Replace};
}

}  // namespace phigs
