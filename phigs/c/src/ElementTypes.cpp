#include "ElementTypes.h"

#include <map>

namespace phigs::c {

namespace {

using T = ElementType;

const std::map<ElementType, Pelem_type>& plainTypes() {
    static const std::map<ElementType, Pelem_type> table = {
        {T::Polyline3, PELEM_POLYLINE3},
        {T::Polyline, PELEM_POLYLINE},
        {T::Polymarker3, PELEM_POLYMARKER3},
        {T::Polymarker, PELEM_POLYMARKER},
        {T::FillArea3, PELEM_FILL_AREA3},
        {T::FillArea, PELEM_FILL_AREA},
        {T::FillAreaSet3, PELEM_FILL_AREA_SET3},
        {T::FillAreaSet, PELEM_FILL_AREA_SET},
        {T::Text3, PELEM_TEXT3},
        {T::Text, PELEM_TEXT},
        {T::AnnotationTextRelative3, PELEM_ANNO_TEXT_REL3},
        {T::AnnotationTextRelative, PELEM_ANNO_TEXT_REL},
        {T::CellArray3, PELEM_CELL_ARRAY3},
        {T::CellArray, PELEM_CELL_ARRAY},
        {T::NonUniformBSplineCurve, PELEM_NUNI_BSP_CURVE},
        {T::NonUniformBSplineSurface, PELEM_NUNI_BSP_SURF},
        {T::FillAreaSetWithData, PELEM_FILL_AREA_SET3_DATA},
        {T::TriangleStrip, PELEM_TRI_STRIP3_DATA},
        {T::QuadrilateralMesh, PELEM_QUAD_MESH3_DATA},
        {T::PolylineSetWithData, PELEM_POLYLINE_SET3_DATA},
        {T::CellArrayPlus, PELEM_CELL_ARRAY3_PLUS},
        {T::SetOfFillAreaSetsWithData, PELEM_SET_OF_FILL_AREA_SET3_DATA},
        {T::PolylineIndex, PELEM_LINE_IND},
        {T::PolymarkerIndex, PELEM_MARKER_IND},
        {T::TextIndex, PELEM_TEXT_IND},
        {T::InteriorIndex, PELEM_INT_IND},
        {T::EdgeIndex, PELEM_EDGE_IND},
        {T::Linetype, PELEM_LINETYPE},
        {T::LinewidthScaleFactor, PELEM_LINEWIDTH},
        {T::PolylineShadingMethod, PELEM_LINE_SHAD_METH},
        {T::MarkerType, PELEM_MARKER_TYPE},
        {T::MarkerSizeScaleFactor, PELEM_MARKER_SIZE},
        {T::TextFont, PELEM_TEXT_FONT},
        {T::TextPrecision, PELEM_TEXT_PREC},
        {T::CharacterExpansionFactor, PELEM_CHAR_EXPAN},
        {T::CharacterSpacing, PELEM_CHAR_SPACE},
        {T::CharacterHeight, PELEM_CHAR_HT},
        {T::CharacterUpVector, PELEM_CHAR_UP_VEC},
        {T::TextPath, PELEM_TEXT_PATH},
        {T::TextAlignment, PELEM_TEXT_ALIGN},
        {T::AnnotationTextCharacterHeight, PELEM_ANNO_CHAR_HT},
        {T::AnnotationTextCharacterUpVector, PELEM_ANNO_CHAR_UP_VEC},
        {T::AnnotationTextPath, PELEM_ANNO_PATH},
        {T::AnnotationTextAlignment, PELEM_ANNO_ALIGN},
        {T::AnnotationStyle, PELEM_ANNO_STYLE},
        {T::InteriorStyle, PELEM_INT_STYLE},
        {T::InteriorStyleIndex, PELEM_INT_STYLE_IND},
        {T::BackInteriorStyle, PELEM_BACK_INT_STYLE},
        {T::BackInteriorStyleIndex, PELEM_BACK_INT_STYLE_IND},
        {T::InteriorShadingMethod, PELEM_INT_SHAD_METH},
        {T::BackInteriorShadingMethod, PELEM_BACK_INT_SHAD_METH},
        {T::InteriorReflectanceEquation, PELEM_REFL_EQN},
        {T::BackInteriorReflectanceEquation, PELEM_BACK_REFL_EQN},
        {T::AreaProperties, PELEM_REFL_PROPS},
        {T::BackAreaProperties, PELEM_BACK_REFL_PROPS},
        {T::FaceDistinguishingMode, PELEM_FACE_DISTING_MODE},
        {T::FaceCullingMode, PELEM_FACE_CULL_MODE},
        {T::EdgeFlag, PELEM_EDGE_FLAG},
        {T::Edgetype, PELEM_EDGETYPE},
        {T::EdgewidthScaleFactor, PELEM_EDGEWIDTH},
        {T::IndividualAsf, PELEM_INDIV_ASF},
        {T::CurveApproximationCriteria, PELEM_CURVE_APPROX_CRIT},
        {T::SurfaceApproximationCriteria, PELEM_SURF_APPROX_CRIT},
        {T::ParametricSurfaceCharacteristics, PELEM_PARA_SURF_CHARS},
        {T::LightSourceState, PELEM_LIGHT_SRC_STATE},
        {T::DepthCueIndex, PELEM_DCUE_IND},
        {T::ColourMappingIndex, PELEM_COLR_MAP_IND},
        {T::RenderingColourModel, PELEM_RENDERING_COLR_MODEL},
        {T::AddNamesToSet, PELEM_ADD_NAMES_SET},
        {T::RemoveNamesFromSet, PELEM_REMOVE_NAMES_SET},
        {T::LocalModellingTransformation3, PELEM_LOCAL_MODEL_TRAN3},
        {T::LocalModellingTransformation, PELEM_LOCAL_MODEL_TRAN},
        {T::GlobalModellingTransformation3, PELEM_GLOBAL_MODEL_TRAN3},
        {T::GlobalModellingTransformation, PELEM_GLOBAL_MODEL_TRAN},
        {T::ModelClippingVolume3, PELEM_MODEL_CLIP_VOL3},
        {T::ModelClippingVolume, PELEM_MODEL_CLIP_VOL},
        {T::ModelClippingIndicator, PELEM_MODEL_CLIP_IND},
        {T::RestoreModelClippingVolume, PELEM_RESTORE_MODEL_CLIP_VOL},
        {T::ViewIndex, PELEM_VIEW_IND},
        {T::ExecuteStructure, PELEM_EXEC_STRUCT},
        {T::Label, PELEM_LABEL},
        {T::ApplicationData, PELEM_APPL_DATA},
        {T::PickId, PELEM_PICK_ID},
        {T::HlhsrIdentifier, PELEM_HLHSR_ID},
        {T::GeneralizedDrawingPrimitive3, PELEM_GDP3},
        {T::GeneralizedDrawingPrimitive, PELEM_GDP},
        {T::GeneralizedStructureElement, PELEM_GSE},
        {T::PatternSize, PELEM_PAT_SIZE},
        {T::PatternReferencePoint, PELEM_PAT_REF_POINT},
        {T::PatternReferencePointAndVectors, PELEM_PAT_REF_POINT_VECS},
    };
    return table;
}

// (index form, general form) of each colour attribute.
const std::map<ElementType, std::pair<Pelem_type, Pelem_type>>& colourTypes() {
    static const std::map<ElementType, std::pair<Pelem_type, Pelem_type>> table = {
        {T::PolylineColour, {PELEM_LINE_COLR_IND, PELEM_LINE_COLR}},
        {T::PolymarkerColour, {PELEM_MARKER_COLR_IND, PELEM_MARKER_COLR}},
        {T::TextColour, {PELEM_TEXT_COLR_IND, PELEM_TEXT_COLR}},
        {T::InteriorColour, {PELEM_INT_COLR_IND, PELEM_INT_COLR}},
        {T::BackInteriorColour, {PELEM_BACK_INT_COLR_IND, PELEM_BACK_INT_COLR}},
        {T::EdgeColour, {PELEM_EDGE_COLR_IND, PELEM_EDGE_COLR}},
    };
    return table;
}

}  // namespace

Pelem_type cElementType(const Element& element) {
    const ElementType type = elementType(element);
    if (auto colour = std::get_if<ColourAttribute>(&element)) {
        const auto& forms = colourTypes().at(type);
        return colour->colour.direct ? forms.second : forms.first;
    }
    return plainTypes().at(type);
}

}  // namespace phigs::c
