#include "phigs/ws/EchoStructures.h"

#include "EchoShapes.h"

#include <algorithm>
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

/// Replaces the structure's contents with the shapes, each run of one pick id after its
/// PICK ID element, through view 0 (world = NPC); refused before any change while a structure
/// is open.
void replaceContents(StructureStore& store, int structureId, const std::vector<detail::EchoShape>& shapes,
                     const EchoStyle& style) {
    std::vector<Element> elements = {viewIndex(0), IndexAttribute{ElementType::InteriorStyle, 1}};
    int pick = 0;
    for (const detail::EchoShape& s : shapes) {
        if (s.pickId != pick) elements.push_back(pickId(pick = s.pickId));
        if (s.box)
            addBox(elements, s.a, s.b, s.colour, style.outline);
        else
            addText(elements, s.a, s.height, s.text, s.colour);
    }
    store.openStructure(structureId);  // error 6 when one is open: nothing changed yet
    store.emptyStructure(structureId);
    for (const Element& e : elements) store.insert(e);
    store.closeStructure();
}

}  // namespace

void buildChoicePanel(StructureStore& store, int structureId, const ChoicePanel& panel, int current,
                      const WorkstationMapping& mapping, const EchoStyle& style) {
    replaceContents(store, structureId, detail::choicePanelShapes(panel, current, mapping, style), style);
}

void buildValuatorSlider(StructureStore& store, int structureId, const ValuatorSlider& slider, double value,
                         const std::string& label, const WorkstationMapping& mapping,
                         const EchoStyle& style) {
    replaceContents(store, structureId, detail::valuatorSliderShapes(slider, value, label, mapping, style),
                    style);
}

}  // namespace phigs
