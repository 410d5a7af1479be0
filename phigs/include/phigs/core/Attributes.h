#pragma once

// PHIGS attribute values as traversal resolves them and the workstation tables hold them:
// the enumerations of ISO 9592 / 9592-4 and the resolved styles, lights and depth cues. At
// the bottom of phigs (core), so the tables, traversal and its consumers share them.

#include "phigs/core/ColourModels.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace phigs {

/// PHIGS line types (ISO 9592 values).
enum class LineType : int { Solid = 1, Dashed = 2, Dotted = 3, DashDotted = 4 };
/// PHIGS marker types (ISO 9592 values).
enum class MarkerType : int { Dot = 1, Plus = 2, Asterisk = 3, Circle = 4, Cross = 5 };
/// PHIGS interior styles.
enum class InteriorStyle : int { Hollow = 0, Solid = 1, Pattern = 2, Hatch = 3, Empty = 4 };
/// PHIGS PLUS interior shading methods.
enum class ShadingMethod : int { None = 1, Colour = 2 /* Gouraud */, DotProduct = 3, Normal = 4 /* Phong */ };
/// PHIGS PLUS reflectance (lighting) equations.
enum class ReflectanceModel : int { None = 1, Ambient = 2, Diffuse = 3, Specular = 4 };
/// PHIGS PLUS back-face processing: which faces are drawn and how.
enum class CullMode : int { None = 0, BackFaces = 1, FrontFaces = 2 };
/// PHIGS text paths.
enum class TextPath : int { Right = 0, Left = 1, Up = 2, Down = 3 };
enum class HorizontalAlignment : int { Normal = 0, Left = 1, Centre = 2, Right = 3 };
enum class VerticalAlignment : int { Normal = 0, Top = 1, Cap = 2, Half = 3, Base = 4, Bottom = 5 };

/// Resolved polyline (and edge) attributes; colours are RGB already looked up in the colour table.
struct LineStyle {
    glm::vec3 colour{1.0f};
    LineType type = LineType::Solid;
    float width = 1.0f;  ///< linewidth scale factor (1 = one nominal pixel)
    bool operator==(const LineStyle&) const = default;
};

/// Resolved polymarker attributes.
struct MarkerStyle {
    glm::vec3 colour{1.0f};
    MarkerType type = MarkerType::Asterisk;
    float scale = 1.0f;  ///< marker size scale factor (1 = nominal size, 7 pixels)
    bool operator==(const MarkerStyle&) const = default;
};

/// PHIGS PLUS surface reflectance properties.
struct Reflectance {
    float ambient = 0.3f;   ///< ambient coefficient
    float diffuse = 0.7f;   ///< diffuse coefficient
    float specular = 0.0f;  ///< specular coefficient
    glm::vec3 specularColour{1.0f};
    float specularExponent = 10.0f;
    float transparency = 0.0f;  ///< PHIGS PLUS transparency coefficient: 0 opaque, 1 invisible
    bool operator==(const Reflectance&) const = default;
};

/// Where a PATTERN interior's pattern box lies, in modelling coordinates (ISO 9592 pattern
/// reference point, reference vectors and pattern size): the box spans size.x along vectorX and
/// size.y along vectorY from the reference point, and is projected onto the primitive's plane.
struct PatternPlacement {
    glm::dvec3 referencePoint{0.0};
    glm::dvec3 vectorX{1, 0, 0}, vectorY{0, 1, 0};
    glm::dvec2 size{1.0, 1.0};
    bool operator==(const PatternPlacement&) const = default;
};

/// PHIGS PLUS back interior style, shading and reflectance equation: used for back faces when
/// face distinguishing is on. A HOLLOW or EMPTY back style fills no back face.
struct BackFaceStyle {
    InteriorStyle style = InteriorStyle::Hollow;
    int styleIndex = 1;
    ShadingMethod shading = ShadingMethod::None;
    ReflectanceModel reflectance = ReflectanceModel::None;
    bool operator==(const BackFaceStyle&) const = default;
};

/// Resolved interior (fill area, mesh, surface) attributes.
struct InteriorStyleSet {
    InteriorStyle style = InteriorStyle::Hollow;
    int styleIndex = 1;  ///< hatch or pattern index
    PatternPlacement pattern;
    glm::vec3 colour{1.0f};
    glm::vec3 backColour{1.0f};  ///< PHIGS PLUS back interior colour
    ShadingMethod shading = ShadingMethod::None;
    ReflectanceModel reflectance = ReflectanceModel::None;
    Reflectance properties;
    Reflectance backProperties;
    CullMode cull = CullMode::None;
    bool distinguishBackFaces = false;  ///< back faces use backColour / backProperties / back
    BackFaceStyle back;
    /// PHIGS PLUS rendering colour model: the space the vertex colours, the lit vertex colours
    /// (Gouraud) and depth cueing are interpolated and mixed in (lighting itself sums in RGB).
    ColourModel renderingModel = ColourModel::Rgb;
    /// The style, style index and shading method a side's faces are drawn with: the back ones for
    /// back faces with face distinguishing on, else the front ones.
    InteriorStyle styleOf(bool backFace) const { return backSide(backFace) ? back.style : style; }
    int styleIndexOf(bool backFace) const { return backSide(backFace) ? back.styleIndex : styleIndex; }
    ShadingMethod shadingOf(bool backFace) const { return backSide(backFace) ? back.shading : shading; }
    /// Whether a side's faces are filled: not culled, and drawn with a SOLID, HATCH or PATTERN style
    /// (each side by its own style with face distinguishing on; HOLLOW and EMPTY fill nothing).
    bool fillsFrontFaces() const { return cull != CullMode::FrontFaces && filled(style); }
    bool fillsBackFaces() const { return cull != CullMode::BackFaces && filled(styleOf(true)); }
    /// Whether the two sides are drawn differently in style, style index or shading method.
    bool sidesDiffer() const {
        return distinguishBackFaces &&
               (back.style != style || back.styleIndex != styleIndex || back.shading != shading);
    }
    bool operator==(const InteriorStyleSet&) const = default;

private:
    bool backSide(bool backFace) const { return backFace && distinguishBackFaces; }
    static bool filled(InteriorStyle s) { return s != InteriorStyle::Hollow && s != InteriorStyle::Empty; }
};

/// Resolved edge attributes (fill areas, meshes, surfaces).
struct EdgeStyle {
    bool visible = false;
    glm::vec3 colour{1.0f};
    LineType type = LineType::Solid;
    float width = 1.0f;
    bool operator==(const EdgeStyle&) const = default;
};

/// Resolved text attributes (stroke precision; the geometry is generated by the consumer).
struct TextStyle {
    glm::vec3 colour{1.0f};
    int font = 1;
    float expansion = 1.0f;     ///< character expansion factor
    float spacing = 0.0f;       ///< character spacing, a fraction of the height
    double height = 0.01;       ///< character height in modelling units (annotation: NPC)
    glm::dvec2 upVector{0, 1};  ///< in the text plane
    TextPath path = TextPath::Right;
    HorizontalAlignment horizontal = HorizontalAlignment::Normal;
    VerticalAlignment vertical = VerticalAlignment::Normal;
    bool operator==(const TextStyle&) const = default;
};

/// PHIGS PLUS light source types.
enum class LightType : int { Ambient = 1, Directional = 2, Positional = 3, Spot = 4 };

/// One active light, in world coordinates.
struct Light {
    LightType type = LightType::Ambient;
    glm::vec3 colour{1.0f};
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0, 0, -1};
    glm::vec2 attenuation{1.0f, 0.0f};  ///< constant, linear (positional and spot)
    float concentration = 1.0f;         ///< spot exponent
    float spreadAngle = 3.14159265f;    ///< spot cone half angle, radians
    bool operator==(const Light&) const = default;
};

/// Depth cueing (PHIGS PLUS): colour mixed toward `colour` between the reference planes (NPC z).
struct DepthCue {
    bool enabled = false;
    double frontPlane = 1.0, backPlane = 0.0;
    float frontScale = 1.0f, backScale = 0.0f;
    glm::vec3 colour{0.0f};
    bool operator==(const DepthCue&) const = default;
};

}  // namespace phigs
