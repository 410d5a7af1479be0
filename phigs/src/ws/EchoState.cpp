#include "phigs/ws/EchoState.h"

#include "EchoShapes.h"

#include <algorithm>
#include <cmath>

namespace phigs {
namespace {

DrawItem echoItem(DrawPrimitive primitive) {
    DrawItem item;
    item.primitive = std::move(primitive);
    item.context.edit().viewIndex = 0;  // world = NPC: the items are placed in NPC already
    item.context.edit().pickable = false;
    return item;
}

/// A solid box between two NPC corners (z of the first), then its outline.
void appendBox(DrawList& picture, const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& fill,
               const glm::dvec3& outlineColour) {
    const double z = lo.z;
    const std::vector<glm::dvec3> corners = {
        {lo.x, lo.y, z}, {hi.x, lo.y, z}, {hi.x, hi.y, z}, {lo.x, hi.y, z}};
    DrawFillArea box;
    box.contours = {corners};
    InteriorStyleSet interior;
    interior.style = InteriorStyle::Solid;
    interior.colour = glm::vec3(fill);
    box.interior = interior;
    picture.items.push_back(echoItem(std::move(box)));
    DrawPolyline outline;
    std::vector<glm::dvec3> closed = corners;
    closed.push_back(corners.front());
    outline.points = closed;
    outline.style = LineStyle{glm::vec3(outlineColour)};
    picture.items.push_back(echoItem(std::move(outline)));
}

void appendStringEcho(DrawList& picture, const StringEchoArea& echo, const WorkstationMapping& mapping,
                      const EchoStyle& style) {
    const EchoVolume& a = echo.area;
    const double z = style.npcZ;
    const glm::dvec3 lo = mapping.pixelsToNpc({a.xmin, a.ymax}, z);  // bottom left
    const glm::dvec3 hi = mapping.pixelsToNpc({a.xmax, a.ymin}, z);  // top right
    appendBox(picture, lo, hi, style.box, style.outline);

    // Cap height 45 % of the area, from a quarter of that height in from the left edge.
    const double height = std::abs(hi.y - lo.y) * 0.45;
    DrawText text;
    text.text = echo.shown();
    text.position = {lo.x + height * 0.25 + mapping.npcLength(2.0), (lo.y + hi.y) * 0.5, z};
    TextStyle textStyle;
    textStyle.colour = glm::vec3(echo.cancelled ? style.current : style.text);
    textStyle.height = height;
    textStyle.horizontal = HorizontalAlignment::Left;
    textStyle.vertical = VerticalAlignment::Half;
    text.style = textStyle;
    picture.items.push_back(echoItem(std::move(text)));
}

/// A device echo's shapes as items: a box as a solid fill area and its outline, a label as
/// centred stroke text.
void appendShapes(DrawList& picture, const std::vector<detail::EchoShape>& shapes, const EchoStyle& style) {
    for (const detail::EchoShape& s : shapes) {
        if (!s.box) {
            DrawText text;
            text.text = s.text;
            text.position = s.a;
            TextStyle textStyle;
            textStyle.colour = glm::vec3(s.colour);
            textStyle.height = s.height;
            textStyle.horizontal = HorizontalAlignment::Centre;
            textStyle.vertical = VerticalAlignment::Half;
            text.style = textStyle;
            picture.items.push_back(echoItem(std::move(text)));
            continue;
        }
        appendBox(picture, glm::min(s.a, s.b), glm::max(s.a, s.b), s.colour, style.outline);
    }
}

}  // namespace

void appendEchoes(DrawList& picture, const EchoState& echo, const WorkstationMapping& mapping,
                  const EchoStyle& style) {
    if (echo.empty()) return;
    if (!echo.picked.empty())
        for (DrawItem& item : picture.items)
            if (std::find(echo.picked.begin(), echo.picked.end(), item.source.path()) != echo.picked.end())
                item.context.edit().highlighted = true;
    for (const StringEchoArea& s : echo.strings) appendStringEcho(picture, s, mapping, style);
    for (const ChoiceEcho& c : echo.choices)
        appendShapes(picture, detail::choicePanelShapes(c.panel, c.current, mapping, style), style);
    for (const ValuatorEcho& v : echo.valuators)
        appendShapes(picture, detail::valuatorSliderShapes(v.slider, v.value, {}, mapping, style), style);
    ++picture.generation;  // the list differs from the picture it was copied from
}

}  // namespace phigs
