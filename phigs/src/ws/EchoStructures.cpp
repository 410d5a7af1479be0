#include "phigs/ws/EchoStructures.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace phigs {
namespace {

/// The elements of a solid box, outlined, between two NPC corners.
void addBox(std::vector<Element>& out, glm::dvec3 a, glm::dvec3 b, const glm::dvec3& fill,
            const glm::dvec3& outline) {
    const glm::dvec3 lo = glm::min(a, b), hi = glm::max(a, b);
    const std::vector<glm::dvec3> corners = {
        {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}};
    out.push_back(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb(fill)});
    out.push_back(fillArea3(corners));
    out.push_back(ColourAttribute{ElementType::PolylineColour, Colour::fromRgb(outline)});
    std::vector<glm::dvec3> loop = corners;
    loop.push_back(corners.front());
    out.push_back(polyline3(loop));
}

/// Centred stroke text of cap height `height` (NPC) at `centre`.
void addText(std::vector<Element>& out, const glm::dvec3& centre, double height, const std::string& text,
             const glm::dvec3& colour) {
    out.push_back(ColourAttribute{ElementType::TextColour, Colour::fromRgb(colour)});
    out.push_back(RealAttribute{ElementType::CharacterHeight, height});
    out.push_back(AlignmentAttribute{ElementType::TextAlignment, 2, 3});  // centre, half
    out.push_back(TextElement{centre, {1, 0, 0}, {0, 1, 0}, text, false});
}

/// Replaces the structure's contents with `elements`; refused before any change while a
/// structure is open.
void replaceContents(StructureStore& store, int structureId, const std::vector<Element>& elements) {
    store.openStructure(structureId);  // error 6 when one is open: nothing changed yet
    store.emptyStructure(structureId);
    for (const Element& e : elements) store.insert(e);
    store.closeStructure();
}

std::vector<Element> prologue() {
    return {viewIndex(0), IndexAttribute{ElementType::InteriorStyle, 1}};
}

}  // namespace

void buildChoicePanel(StructureStore& store, int structureId, const ChoicePanel& panel, int current,
                      const WorkstationMapping& mapping, const EchoStyle& style) {
    std::vector<Element> elements = prologue();
    const double z = style.npcZ;
    for (int n = 1; n <= static_cast<int>(panel.alternatives.size()); ++n) {
        const auto [topLeft, bottomRight] = panel.row(n);
        // One pixel of gap between rows, so the boxes read as separate buttons.
        const glm::dvec3 a = mapping.pixelsToNpc(topLeft + glm::dvec2(1.0, 1.0), z);
        const glm::dvec3 b = mapping.pixelsToNpc(bottomRight - glm::dvec2(1.0, 1.0), z);
        const bool isCurrent = n == current;
        elements.push_back(pickId(n));
        addBox(elements, a, b, isCurrent ? style.current : style.box, style.outline);
        addText(elements, (a + b) * 0.5, std::abs(a.y - b.y) * 0.45, panel.alternatives[n - 1],
                isCurrent ? style.currentText : style.text);
    }
    replaceContents(store, structureId, elements);
}

void buildValuatorSlider(StructureStore& store, int structureId, const ValuatorSlider& slider, double value,
                         const std::string& label, const WorkstationMapping& mapping,
                         const EchoStyle& style) {
    const EchoVolume& area = slider.area;
    const bool horizontal = area.xmax - area.xmin >= area.ymax - area.ymin;
    const double z = style.npcZ;
    std::vector<Element> elements = prologue();
    elements.push_back(pickId(1));
    const glm::dvec3 lo = mapping.pixelsToNpc({area.xmin, area.ymax}, z);  // bottom left
    const glm::dvec3 hi = mapping.pixelsToNpc({area.xmax, area.ymin}, z);  // top right
    addBox(elements, lo, hi, style.track, style.outline);

    // The knob: a tenth of the long axis (at least 6 pixels) centred on the value.
    const double along = slider.knobAt(value);
    const double length = horizontal ? area.xmax - area.xmin : area.ymax - area.ymin;
    const double half = std::max(3.0, length * 0.05);
    const glm::dvec3 knobA = horizontal ? mapping.pixelsToNpc({along - half, area.ymax}, z)
                                        : mapping.pixelsToNpc({area.xmin, along + half}, z);
    const glm::dvec3 knobB = horizontal ? mapping.pixelsToNpc({along + half, area.ymin}, z)
                                        : mapping.pixelsToNpc({area.xmax, along - half}, z);
    elements.push_back(pickId(2));
    addBox(elements, knobA, knobB, style.current, style.outline);

    char number[32];
    std::snprintf(number, sizeof number, "%.3g", value);
    const std::string text = label.empty() ? std::string(number) : label + ": " + number;
    const double thickness = horizontal ? hi.y - lo.y : hi.x - lo.x;
    const double height = std::abs(thickness) * 0.6;
    const glm::dvec3 at = horizontal ? glm::dvec3((lo.x + hi.x) * 0.5, hi.y + height, z)
                                     : glm::dvec3(hi.x + height * text.size() * 0.5, (lo.y + hi.y) * 0.5, z);
    elements.push_back(pickId(3));
    addText(elements, at, height, text, style.text);
    replaceContents(store, structureId, elements);
}

}  // namespace phigs
