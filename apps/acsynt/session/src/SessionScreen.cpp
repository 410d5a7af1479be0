// What the session shows: the views, the screen areas, the marker overlay, mapped curves, the error map.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

#include "acsynt/ModelFile.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "phigs/core/Error.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/ws/EchoStructures.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace acsynt {

using namespace phigs;
using namespace session_detail;

// ---- the model on the screen

void Session::showModel() {
    core_.style.onlyComponent = core_.style.colourfulComponent = core_.style.highlightComponent = -1;
    core_.style.errorMapComponent = -1;
    core_.reference.reset();
    core_.previewLines.clear();
    core_.previewClipped.clear();
    core_.previewLost.clear();
    core_.phase = Phase::None;
    if (core_.models.empty()) {
        modelPicture_.clear();
        rewriteStructure(phigs_.store(), structures::modelRoot, {});
    } else {
        modelPicture_.build(core_.models.current(), core_.style);
    }
    drawMapped(false);
    drawErrorMap();
    drawOverlay();
    updateViews();
}

void Session::restyle() {
    modelPicture_.restyle(core_.models.current(), core_.style);
}

namespace {

/// Half the shorter side of view v's window at zoom 1: 0.9 of the model's bounding sphere in the
/// three axis views of FOUR_VIEWS, or more where the model's box, seen along the view's axis,
/// would not fit (a slender model's length); the whole sphere in an oblique view, whose direction
/// turns (a smaller window cut off a model seen along its box's diagonal).
double viewHalfSize(bool axisView, int v, double aspect, const glm::dvec3& size, double radius) {
    if (!axisView) return obliqueHalfSize(radius);
    // Across and up the screen: plan (y, x), front (y, z), side (x, z); directions in updateViews.
    const glm::dvec2 seen = v == 1   ? glm::dvec2(size.y, size.x)
                            : v == 2 ? glm::dvec2(size.y, size.z)
                                     : glm::dvec2(size.x, size.z);
    const double needed =
        aspect >= 1 ? std::max(seen.y, seen.x / aspect) / 2 : std::max(seen.x, seen.y * aspect) / 2;
    return std::max(0.9 * radius, 1.05 * needed);
}

}  // namespace

void Session::updateViews() {
    const auto [lo, hi] = modelBounds();
    const glm::dvec3 centre = core_.viewCentre.value_or((lo + hi) / 2.0);
    const double radius = std::max(glm::length(hi - lo) / 2, 1e-6);
    struct Direction {
        glm::dvec3 normal, up;
    };
    const Direction oblique{obliqueDirection(), {0, 0, 1}};
    const Direction directions[] = {
        {{0, 0, 1}, {-1, 0, 0}}, {{-1, 0, 0}, {0, 0, 1}}, {{0, -1, 0}, {0, 0, 1}}, oblique};
    std::vector<Element> geometry;
    for (int v = 1; v <= (core_.fourViews ? 4 : 1); ++v) {
        const Direction& d = core_.fourViews ? directions[v - 1] : oblique;
        const PixelBox b = layout_.viewBox(v, core_.fourViews);
        const glm::dvec3 npcMin = npc({b.x0, b.y1}, 0), npcMax = npc({b.x1, b.y0}, 1);
        ViewMapping mapping;
        const double aspect = (npcMax.x - npcMin.x) / (npcMax.y - npcMin.y);
        const double half = viewHalfSize(core_.fourViews && v < 4, v, aspect, hi - lo, radius) / core_.zoom;
        const glm::dvec2 halfSize =
            aspect >= 1 ? glm::dvec2(half * aspect, half) : glm::dvec2(half, half / aspect);
        mapping.windowMin = -halfSize;
        mapping.windowMax = halfSize;
        mapping.viewportMin = npcMin;
        mapping.viewportMax = npcMax;
        mapping.projectionReferencePoint = {0, 0, 4 * radius};
        mapping.backPlaneDistance = -2 * radius;
        mapping.frontPlaneDistance = 2 * radius;
        ViewRepresentation view;
        view.orientation = evaluateViewOrientationMatrix(centre, d.normal, d.up);
        view.mapping = evaluateViewMappingMatrix(mapping);
        view.clipMin = npcMin;
        view.clipMax = npcMax;
        core_.workstation->setViewRepresentation(v, view);
        geometry.push_back(viewIndex(v));
        geometry.push_back(executeStructure(structures::modelRoot));
    }
    // The view frames, drawn in NPC.
    geometry.push_back(viewIndex(0));
    geometry.push_back(addNamesToSet({structures::lineName}));
    geometry.push_back(colourAttr(ElementType::PolylineColour, {0.35, 0.4, 0.55}));
    for (int v = 1; v <= (core_.fourViews ? 4 : 1); ++v)
        geometry.push_back(polyline3(outline(layout_.viewBox(v, core_.fourViews))));
    rewriteStructure(phigs_.store(), structures::geometry, geometry);
}

glm::dvec2 Session::pixelOf(const glm::dvec3& world, int view) {
    const ViewRepresentation& v = core_.workstation->tables().views.get(view);
    glm::dvec4 p = v.mapping * v.orientation * glm::dvec4(world, 1.0);
    p /= p.w;
    return mapping_->toPixels(glm::dvec3(p));
}

std::vector<glm::dvec3> Session::outline(const PixelBox& b) const {
    return {npc({b.x0, b.y0}), npc({b.x1, b.y0}), npc({b.x1, b.y1}), npc({b.x0, b.y1}), npc({b.x0, b.y0})};
}

void Session::drawScreen() {
    auto& store = phigs_.store();
    const ScreenLayout& l = layout_;

    // The menu panel of choice device 1 and the sliders of valuators 1-4: phigs echo structures.
    std::vector<std::string> labels;
    for (const auto& item : menuItems_) labels.push_back(shown(item));
    buildChoicePanel(store, structures::menu,
                     ChoicePanel{1, l.menuFor(menuItems_.size()).echoVolume(), labels}, 0, *mapping_);
    // U and W are the component's own parameters, as picks and the message line give them;
    // their sliders span the reference patch (initialised again when it changes).
    if (sliderRange(1) != sliderRanges_[0] || sliderRange(2) != sliderRanges_[1]) initialiseSliders();
    const double values[4] = {core_.reference ? core_.reference->u : 0,
                              core_.reference ? core_.reference->w : 0, core_.azimuth, core_.zoom};
    for (int d = 1; d <= 4; ++d) {
        const glm::dvec2 range = sliderRanges_[d - 1];
        const ValuatorSlider slider{d, l.slider(d).echoVolume(), range.x, range.y};
        buildValuatorSlider(store, structures::sliders + d - 1, slider,
                            std::clamp(values[d - 1], range.x, range.y), sliderNames[d - 1], *mapping_);
    }

    drawPad();
    drawMessage();
}

void Session::drawPad() {
    const ScreenLayout& l = layout_;
    const double unit = 1.0 / mapping_->pixelsPerNpc;  // one pixel in NPC
    // The pointer-valuator pad: pickable buttons (pick id = button), live while the marker moves.
    const bool padLive = core_.phase == Phase::MoveMarker;  // DEFINE POINT's marker moves; off after DONE
    std::vector<Element> pad{
        viewIndex(0), IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)},
        RealAttribute{ElementType::CharacterHeight, 0.25 * (l.pad.y1 - l.pad.y0) / 4 * unit},
        AlignmentAttribute{ElementType::TextAlignment, 2, 3}, addNamesToSet({structures::buttonName})};
    static const char* const arrows[] = {"NW", "N", "NE", "W", "[]", "E", "SW", "S", "SE", "DONE"};
    for (int button = 1; button <= 10; ++button) {
        const PixelBox b = l.padButton(button);
        pad.push_back(pickId(button));
        pad.push_back(colourAttr(ElementType::InteriorColour,
                                 padLive ? glm::dvec3(0.2, 0.3, 0.2) : glm::dvec3(0.1, 0.1, 0.12)));
        auto corners = outline(b);
        corners.pop_back();
        pad.push_back(fillArea3(corners));
        pad.push_back(
            colourAttr(ElementType::TextColour, padLive ? glm::dvec3(0.7, 1, 0.7) : glm::dvec3(0.4)));
        pad.push_back(textAt(npc(b.centre()), arrows[button - 1]));
    }
    rewriteStructure(phigs_.store(), structures::pad, pad);
}

void Session::drawMessage() {
    const ScreenLayout& l = layout_;
    const double unit = 1.0 / mapping_->pixelsPerNpc;  // one pixel in NPC
    // Title, menu name, current model and the message line.
    const PixelBox& m = l.message;
    const double rowHeight = (m.y1 - m.y0) / 2;
    std::string heading = std::string(title) + "   MENU: " + shown(menu_->title);
    if (!core_.models.empty()) heading += "   MODEL: " + core_.models.current().name;
    std::vector<Element> msg{viewIndex(0),
                             addNamesToSet({structures::lineName}),
                             RealAttribute{ElementType::CharacterHeight, 0.45 * rowHeight * unit},
                             AlignmentAttribute{ElementType::TextAlignment, 1, 3},
                             colourAttr(ElementType::PolylineColour, {0.35, 0.4, 0.55}),
                             polyline3(outline(m)),
                             colourAttr(ElementType::TextColour, {0.6, 0.75, 1.0}),
                             textAt(npc({m.x0 + 6, m.y0 + rowHeight * 0.5}), heading),
                             colourAttr(ElementType::TextColour, {1.0, 1.0, 0.55}),
                             textAt(npc({m.x0 + 6, m.y0 + rowHeight * 1.5}), messageLine())};
    rewriteStructure(phigs_.store(), structures::message, msg);
}

void Session::drawOverlay() {
    std::vector<Element> e{addNamesToSet({structures::lineName})};
    if (core_.reference && !core_.models.empty()) {
        const Component& comp = core_.models.current().components[std::size_t(core_.reference->component)];
        const glm::dvec3 at = geom::evaluate(comp.surface, core_.reference->u, core_.reference->w);
        e.push_back(IndexAttribute{ElementType::MarkerType, int(MarkerType::Circle)});
        e.push_back(RealAttribute{ElementType::MarkerSizeScaleFactor, 2.0});
        e.push_back(colourAttr(ElementType::PolymarkerColour, {1, 0.2, 0.2}));
        e.push_back(polymarker3({at}));
        if (core_.phase == Phase::Placed && !core_.mappedSincePlaced) {
            geom::curvemap::Placement placement = core_.placement;
            placement.reference = {core_.reference->u, core_.reference->w};
            placement.offset = 0.5;
            const auto frame = geom::curvemap::placementFrame(comp.surface, placement);
            const double length = 1.5;
            e.push_back(RealAttribute{ElementType::LinewidthScaleFactor, 2.0});
            e.push_back(colourAttr(ElementType::PolylineColour, {0.1, 1.0, 0.2}));  // u tangent: green
            e.push_back(polyline3({frame.surfacePoint, frame.surfacePoint + length * frame.tangentU}));
            e.push_back(colourAttr(ElementType::PolylineColour, {0.75, 0.2, 1.0}));  // w tangent: purple
            e.push_back(polyline3({frame.surfacePoint, frame.surfacePoint + length * frame.tangentW}));
            e.push_back(colourAttr(ElementType::PolylineColour, {1, 1, 1}));  // normal: white
            e.push_back(polyline3({frame.surfacePoint, frame.surfacePoint + length * frame.z}));
            e.push_back(RealAttribute{ElementType::AnnotationTextCharacterHeight, 0.012});
            e.push_back(colourAttr(ElementType::TextColour, {0.1, 1.0, 0.2}));
            e.push_back(AnnotationTextElement{
                frame.surfacePoint + length * frame.tangentU, {0.004, 0.004, 0}, "U", false});
            e.push_back(colourAttr(ElementType::TextColour, {0.75, 0.2, 1.0}));
            e.push_back(AnnotationTextElement{
                frame.surfacePoint + length * frame.tangentW, {0.004, 0.004, 0}, "W", false});
            e.push_back(RealAttribute{ElementType::LinewidthScaleFactor, 1.0});
            // The placed curve above the patch.
            e.push_back(colourAttr(ElementType::PolylineColour, {0.3, 0.9, 1.0}));
            for (const geom::Curve& c : core_.curves) {
                std::vector<glm::dvec3> points;
                const int n = 200;
                for (int k = 0; k <= n; ++k) {
                    const double t = c.domainStart() + (c.domainEnd() - c.domainStart()) * k / n;
                    points.push_back(frame.toModel(geom::evaluate(c, t)));
                }
                e.push_back(polyline3(points));
            }
        }
    }
    e.push_back(colourAttr(ElementType::PolylineColour, {0.9, 0.9, 0.4}));
    for (const auto& line : core_.previewLines) e.push_back(polyline3(line));
    e.push_back(colourAttr(ElementType::PolylineColour, {1.0, 0.55, 0.1}));
    for (const auto& line : core_.previewClipped) e.push_back(polyline3(line));
    e.push_back(colourAttr(ElementType::PolylineColour, {1.0, 0.15, 0.15}));
    for (const auto& line : core_.previewLost) e.push_back(polyline3(line));
    rewriteStructure(phigs_.store(), structures::overlay, e);
}

void Session::drawMapped(bool all) {
    std::vector<Element> e{addNamesToSet({structures::lineName}),
                           RealAttribute{ElementType::LinewidthScaleFactor, 2.0}};
    if (!core_.models.empty()) {
        const std::string& name = core_.models.current().name;
        // Blue and red by turns over this model's curves, so that a curve keeps its colour
        // whatever other models map (a reduction's carried copies, say).
        std::size_t onModel = 0;
        for (std::size_t i = 0; i < core_.mappings.size(); ++i) {
            const MappingRecord& m = core_.mappings[i];
            if (m.model != name) continue;
            const bool red = onModel++ % 2 == 1;
            if (!all && i + 1 != core_.mappings.size()) continue;
            e.push_back(colourAttr(ElementType::PolylineColour,
                                   red ? glm::dvec3(1.0, 0.25, 0.15) : glm::dvec3(0.1, 0.3, 1.0)));
            for (const auto& line : m.polylines) e.push_back(polyline3(line));
        }
    }
    rewriteStructure(phigs_.store(), structures::mapped, e);
}

void Session::drawErrorMap() {
    std::vector<Element> e;
    if (const ReductionRecord* shown = core_.shownReduction(); core_.style.errorMapComponent >= 0 && shown) {
        const ReductionRecord& r = *shown;
        const Component& comp = core_.models.current().components[std::size_t(r.componentIndex)];
        const auto& d = r.deviation;
        QuadrilateralMeshElement mesh;
        mesh.rows = int(d.u.size());
        mesh.columns = int(d.v.size());
        const double top = core_.errorMapTop();
        for (std::size_t i = 0; i < d.u.size(); ++i)
            for (std::size_t j = 0; j < d.v.size(); ++j) {
                mesh.points.push_back(geom::evaluate(comp.surface, d.u[i], d.v[j]));
                mesh.vertexColours.push_back(Colour::fromRgb(errorColour(d.error[i * d.v.size() + j] / top)));
            }
        e.push_back(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
        e.push_back(IndexAttribute{ElementType::InteriorShadingMethod, int(ShadingMethod::Colour)});
        e.push_back(std::move(mesh));
    }
    rewriteStructure(phigs_.store(), structures::errorMap, e);
    drawLegend();
}

void Session::drawLegend() {
    std::vector<Element> e;
    if (const ReductionRecord* shown = core_.shownReduction(); core_.style.errorMapComponent >= 0 && shown) {
        // A colour bar in the lower left of the geometry area (inside the lower left view with
        // four views): 0 to the scale's top in model units (metres), the scale's kind and the
        // largest error measured above it.
        const PixelBox& g = layout_.geometry;
        const PixelBox area = core_.fourViews ? layout_.viewBox(3, true) : g;
        const double gw = g.x1 - g.x0, gh = g.y1 - g.y0;
        const double unit = 1.0 / mapping_->pixelsPerNpc;
        const double textHeight = std::max(6.0, 0.028 * gh);
        const PixelBox bar{area.x0 + 0.03 * gw, g.y1 - 0.05 * gh - 1.6 * textHeight,
                           area.x0 + std::min(0.45 * gw, area.x1 - area.x0 - 0.15 * gw),
                           g.y1 - 0.05 * gh - 1.6 * textHeight + std::max(5.0, 0.03 * gh)};
        const PixelBox back{bar.x0 - 4, bar.y0 - 2.6 * textHeight - 4, bar.x1 + 0.12 * gw,
                            bar.y1 + 1.6 * textHeight + 2};
        e = {viewIndex(0), addNamesToSet({structures::lineName}),
             IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)},
             colourAttr(ElementType::InteriorColour, {0.05, 0.06, 0.12})};
        auto box = [&](const PixelBox& b) {
            auto corners = outline(b);
            corners.pop_back();
            return fillArea3(corners);
        };
        e.push_back(box(back));
        const int steps = 32;
        for (int k = 0; k < steps; ++k) {
            const double x0 = bar.x0 + (bar.x1 - bar.x0) * k / steps;
            const double x1 = bar.x0 + (bar.x1 - bar.x0) * (k + 1) / steps;
            e.push_back(colourAttr(ElementType::InteriorColour, errorColour((k + 0.5) / steps)));
            e.push_back(box({x0, bar.y0, x1, bar.y1}));
        }
        const double top = core_.errorMapTop(), largest = shown->maxError;
        e.push_back(RealAttribute{ElementType::CharacterHeight, 0.7 * textHeight * unit});
        e.push_back(colourAttr(ElementType::TextColour, {0.9, 0.9, 0.9}));
        e.push_back(AlignmentAttribute{ElementType::TextAlignment, 1, 3});
        e.push_back(textAt(npc({bar.x0, bar.y0 - 1.8 * textHeight}),
                           core_.errorScale > 0 ? "ERROR, FIXED SCALE" : "ERROR, RELATIVE SCALE"));
        e.push_back(textAt(npc({bar.x0, bar.y0 - 0.7 * textHeight}), "MAX " + lengthText(largest)));
        // Ticks under the bar: 0, half and the top (which any larger error shows as).
        e.push_back(AlignmentAttribute{ElementType::TextAlignment, 2, 3});
        const double below = bar.y1 + 0.9 * textHeight;
        e.push_back(textAt(npc({bar.x0, below}), "0"));
        e.push_back(textAt(npc({(bar.x0 + bar.x1) / 2, below}), lengthText(top / 2)));
        e.push_back(textAt(npc({bar.x1, below}),
                           (core_.errorScale > 0 && largest > top ? ">" : "") + lengthText(top)));
    }
    rewriteStructure(phigs_.store(), structures::legend, e);
}

}  // namespace acsynt
