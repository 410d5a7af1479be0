#include "phigs/ws/PredefinedRepresentations.h"

namespace phigs {
namespace {

PredefinedRepresentations make() {
    PredefinedRepresentations p;
    const Colour white = Colour::indexed(1);
    // Bundle 1 of each table is the table's default entry; the others show each type once.
    p.polylines = {{LineType::Solid, 1.0, white},
                   {LineType::Dashed, 1.0, white},
                   {LineType::Dotted, 1.0, white},
                   {LineType::DashDotted, 1.0, white},
                   {LineType::Solid, 2.0, Colour::indexed(2)}};
    p.polymarkers = {{MarkerType::Asterisk, 1.0, white},
                     {MarkerType::Dot, 1.0, white},
                     {MarkerType::Plus, 1.0, white},
                     {MarkerType::Circle, 1.0, white},
                     {MarkerType::Cross, 1.0, white}};
    p.texts = {{1, 2, 1.0, 0.0, white},
               {1, 0, 1.0, 0.0, white},
               {1, 1, 1.0, 0.0, white},
               {2, 2, 1.0, 0.0, white},
               {3, 2, 1.0, 0.0, Colour::indexed(2)}};
    for (InteriorStyle style : {InteriorStyle::Hollow, InteriorStyle::Solid, InteriorStyle::Pattern,
                                InteriorStyle::Hatch, InteriorStyle::Empty}) {
        InteriorBundle b;
        b.style = b.backStyle = style;
        p.interiors.push_back(b);
    }
    p.edges = {EdgeBundle{}, {true, LineType::Solid, 1.0, white}, {true, LineType::Dashed, 1.0, white}};
    p.patterns = {PatternRepresentation::indexed(2, 2, {0, 1, 1, 0}),
                  PatternRepresentation::indexed(4, 1, {1, 1, 0, 0})};
    const ColourTable colours;
    for (int i : colours.definedIndices()) p.colours.push_back(colours.get(i));
    p.views = {ViewRepresentation{}};
    return p;
}

}  // namespace

const PredefinedRepresentations& predefinedRepresentations(WorkstationType) {
    static const PredefinedRepresentations p = make();
    return p;
}

}  // namespace phigs
