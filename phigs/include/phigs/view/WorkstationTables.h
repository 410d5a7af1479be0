#pragma once

#include "phigs/core/Attributes.h"
#include "phigs/core/ErrorLog.h"
#include "phigs/store/Element.h"
#include "phigs/view/ColourMappingTable.h"
#include "phigs/view/PrimitiveLimits.h"
#include "phigs/view/ViewTable.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <map>
#include <optional>

namespace phigs {

/// Polyline bundle, extended as PHIGS PLUS does (shading method, curve approximation criteria).
struct PolylineBundle {
    LineType type = LineType::Solid;
    double width = 1.0;
    Colour colour = Colour::indexed(1);
    ShadingMethod shading = ShadingMethod::None;  ///< NONE or COLOUR (the polyline shading methods)
    ApproximationAttribute approximation{ElementType::CurveApproximationCriteria};
    bool operator==(const PolylineBundle&) const = default;
};
/// Polymarker bundle.
struct PolymarkerBundle {
    MarkerType type = MarkerType::Asterisk;
    double scale = 1.0;
    Colour colour = Colour::indexed(1);
    bool operator==(const PolymarkerBundle&) const = default;
};
/// Text bundle.
struct TextBundle {
    int font = 1, precision = 2;  ///< precision 2: STROKE
    double expansion = 1.0, spacing = 0.0;
    Colour colour = Colour::indexed(1);
    bool operator==(const TextBundle&) const = default;
};
/// Interior bundle, extended as PHIGS PLUS does (back face, shading, reflectance, approximation).
struct InteriorBundle {
    InteriorStyle style = InteriorStyle::Hollow;
    int styleIndex = 1;
    Colour colour = Colour::indexed(1);
    InteriorStyle backStyle = InteriorStyle::Hollow;
    int backStyleIndex = 1;
    Colour backColour = Colour::indexed(1);
    ShadingMethod shading = ShadingMethod::None, backShading = ShadingMethod::None;
    ReflectanceModel reflectance = ReflectanceModel::None, backReflectance = ReflectanceModel::None;
    AreaPropertiesAttribute properties{ElementType::AreaProperties};
    AreaPropertiesAttribute backProperties{ElementType::BackAreaProperties};
    ApproximationAttribute approximation{ElementType::SurfaceApproximationCriteria};
    bool operator==(const InteriorBundle&) const = default;
};
/// Edge bundle.
struct EdgeBundle {
    bool visible = false;
    LineType type = LineType::Solid;
    double width = 1.0;
    Colour colour = Colour::indexed(1);
    bool operator==(const EdgeBundle&) const = default;
};

/// A bundle table: entry 1 predefined; an undefined index reads as entry 1 (ISO 9592).
template <class Bundle>
class BundleTable {
public:
    explicit BundleTable(int capacity = 32) : capacity_(capacity) { entries_[1] = Bundle{}; }
    void set(int index, const Bundle& bundle, ErrorLog* log, const char* function) {
        if (index < 1) raise(log, errors::BundleIndexBelowOne, function, "index " + std::to_string(index));
        if (!entries_.contains(index) && static_cast<int>(entries_.size()) >= capacity_)
            raise(log, errors::BundleTableFull, function, "index " + std::to_string(index));
        entries_[index] = bundle;
    }
    const Bundle& get(int index) const {
        auto it = entries_.find(index);
        return it != entries_.end() ? it->second : entries_.at(1);
    }
    bool defined(int index) const { return entries_.contains(index); }
    std::vector<int> definedIndices() const {
        std::vector<int> out;
        for (const auto& [i, b] : entries_) out.push_back(i);
        return out;
    }

private:
    int capacity_;
    std::map<int, Bundle> entries_;
};

/// The colour table: 0 background (black), 1 foreground (white), 2-7 red, green, blue, yellow,
/// cyan, magenta; an undefined index reads as entry 1.
class ColourTable {
public:
    explicit ColourTable(int capacity = 256);
    /// SET COLOUR REPRESENTATION: errors 113 (index < 0), 103 (beyond capacity), 118 (component outside
    /// [0,1]). The entry keeps `components` in `model` as given.
    void set(int index, const glm::dvec3& components, ErrorLog* log, ColourModel model = ColourModel::Rgb);
    /// The RGB colour drawn for entry `index` (index 1 when undefined), clamped to [0, 1].
    glm::dvec3 get(int index) const;
    /// Entry `index` as set: a direct colour in the model it was given in (index 1 when undefined).
    Colour given(int index) const;
    bool defined(int index) const { return entries_.contains(index); }
    std::vector<int> definedIndices() const;
    /// RGB of a colour as drawn: direct converted from its model and clamped, indexed through the table.
    glm::dvec3 resolve(const Colour& colour) const {
        return colour.direct ? clampedRgb(colour.model, colour.rgb) : get(colour.index);
    }
    /// A general colour a representation may hold: error 113 for an index below 0, 136 for a
    /// direct component outside [0, 1].
    static void check(const Colour& colour, ErrorLog* log, const char* function);

private:
    int capacity_;
    std::map<int, Colour> entries_;  ///< direct colours
};

/// Everything of a workstation that traversal reads: colour, bundle, view, light and depth cue
/// tables, the colour mapping table and the HLHSR mode. `generation` changes whenever any of them changes.
struct WorkstationTables {
    ColourTable colours;
    BundleTable<PolylineBundle> polylines;
    BundleTable<PolymarkerBundle> polymarkers;
    BundleTable<TextBundle> texts;
    BundleTable<InteriorBundle> interiors;
    BundleTable<EdgeBundle> edges;
    ViewTable views;
    std::map<int, Light> lights;        ///< light source table (PHIGS PLUS); 1: white ambient
    std::map<int, DepthCue> depthCues;  ///< depth cue table (PHIGS PLUS); 0: suppressed
    /// The colour of each light and depth cue entry as given: an index, or direct in its model
    /// (`lights[i].colour` holds it as RGB, unclamped); an entry without one was given in RGB.
    std::map<int, Colour> lightColours, depthCueColours;
    ColourMappingTable colourMappings;  ///< colour mapping table (PHIGS PLUS); 0: TRUE
    int hlhsrMode = 0;                  ///< 0 none, 1 z-buffer
    glm::dvec3 windowMin{0.0}, windowMax{1.0};
    glm::dvec3 viewportMin{0.0}, viewportMax{1.0};
    glm::dvec2 displaySize{1.0};  ///< the display surface in device coordinates
    PrimitiveLimits limits;       ///< the line and marker attributes drawn (the description's)
    std::uint64_t generation = 0;

    WorkstationTables() : lights{{1, Light{}}}, depthCues{{0, DepthCue{}}} {}
    /// Light `index` as drawn now (its indirect colour through the colour table), realized
    /// (phigs/view/RealizedLighting.h); empty when the entry is undefined.
    std::optional<Light> drawnLight(int index) const;
    /// Depth cue `index` as drawn now, as drawnLight; empty when undefined.
    std::optional<DepthCue> drawnDepthCue(int index) const;
    /// The colour light `index` was given in (RGB of `lights` when none is kept).
    Colour givenLightColour(int index) const;
    Colour givenDepthCueColour(int index) const;
};

}  // namespace phigs
