#include "acsynt/session/ModelPicture.h"

#include "geom/Evaluate.h"
#include "phigs/core/Error.h"
#include "phigs/traverse/DrawList.h"

#include <algorithm>

namespace acsynt {

using namespace phigs;

void rewriteStructure(StructureStore& store, int id, const std::vector<Element>& elements) {
    const char* function = "REWRITE STRUCTURE";
    if (store.isStructureOpen())
        throw Error(errors::NotStructureClosed, function,
                    "structure " + std::to_string(store.openStructureId()) + " is open");
    // Everything the store would refuse is refused before the structure is emptied, so a bad
    // element leaves the structure as it was.
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const std::string where = "structure " + std::to_string(id) + " element " + std::to_string(i + 1);
        if (std::string reason = validateElement(elements[i]); !reason.empty())
            throw Error(
                errors::InvalidElementData, function,
                where + " (" + std::string(elementTypeName(elementType(elements[i]))) + "): " + reason);
        if (const auto* x = std::get_if<ExecuteStructureElement>(&elements[i]))
            if (x->structureId == id ||
                (store.exists(x->structureId) && store.wouldCycle(id, x->structureId)))
                throw Error(errors::StructureCycle, function,
                            where + " executes " + std::to_string(x->structureId));
    }
    store.emptyStructure(id);
    store.openStructure(id);
    for (const Element& e : elements) store.insert(e);
    store.closeStructure();
}

namespace {

Element colourOf(ElementType type, const glm::dvec3& rgb) {
    return ColourAttribute{type, Colour::fromRgb(rgb)};
}
Element indexOf(ElementType type, int value) {
    return IndexAttribute{type, value};
}

/// The patch as a surface of its own: 8 + 8 local knots, 4 x 4 hull; its domain is [u0, u1] x [w0, w1].
geom::Surface patchSurface(const Patch& p) {
    return geom::Surface(3, 3, std::vector<double>(p.knotsU.begin(), p.knotsU.end()),
                         std::vector<double>(p.knotsW.begin(), p.knotsW.end()), 4, 4,
                         std::vector<glm::dvec3>(p.hull.begin(), p.hull.end()));
}

std::vector<glm::dvec3> boundary(const Patch& p) {
    std::vector<glm::dvec3> points;
    const int n = 8;
    auto at = [&](double u, double w) { return evaluatePatchHull(p, u, w); };
    for (int k = 0; k < n; ++k) points.push_back(at(p.u0 + (p.u1 - p.u0) * k / n, p.w0));
    for (int k = 0; k < n; ++k) points.push_back(at(p.u1, p.w0 + (p.w1 - p.w0) * k / n));
    for (int k = 0; k < n; ++k) points.push_back(at(p.u1 - (p.u1 - p.u0) * k / n, p.w1));
    for (int k = 0; k <= n; ++k) points.push_back(at(p.u0, p.w1 - (p.w1 - p.w0) * k / n));
    return points;
}

}  // namespace

glm::dvec3 ModelPicture::patchColour(int number) {
    static const glm::dvec3 cycle[] = {{0.95, 0.30, 0.30}, {0.30, 0.85, 0.35}, {0.35, 0.50, 1.00},
                                       {0.95, 0.85, 0.25}, {0.30, 0.90, 0.90}, {0.90, 0.40, 0.90},
                                       {1.00, 0.60, 0.20}, {0.60, 0.95, 0.60}, {0.70, 0.60, 1.00}};
    return cycle[(number - 1) % 9];
}

void ModelPicture::build(const Model& model, const DisplayStyle& style) {
    clear();
    for (std::size_t c = 0; c < model.components.size(); ++c) {
        const Component& comp = model.components[c];
        const int index = static_cast<int>(c);
        for (const Patch& p : comp.patches.patches) {
            const int id = structures::patch(index, p.number);
            rewriteStructure(
                store_, id,
                {pickId(p.number), addNamesToSet({structures::pickableName}),
                 NurbsSurfaceElement{patchSurface(p), {}}, removeNamesFromSet({structures::pickableName}),
                 addNamesToSet({structures::lineName}), polyline3(boundary(p))});
            built_.push_back(id);
        }
        std::vector<Element> hull{addNamesToSet({structures::lineName}),
                                  colourOf(ElementType::PolylineColour, {0.95, 0.75, 0.2})};
        const geom::Surface& s = comp.surface;
        for (std::size_t i = 0; i < s.countU; ++i) {
            std::vector<glm::dvec3> row;
            for (std::size_t j = 0; j < s.countV; ++j) row.push_back(s.point(i, j));
            hull.push_back(polyline3(row));
        }
        for (std::size_t j = 0; j < s.countV; ++j) {
            std::vector<glm::dvec3> column;
            for (std::size_t i = 0; i < s.countU; ++i) column.push_back(s.point(i, j));
            hull.push_back(polyline3(column));
        }
        rewriteStructure(store_, structures::hull(index), hull);
        built_.push_back(structures::hull(index));
        built_.push_back(structures::component(index));
    }
    restyle(model, style);
}

void ModelPicture::restyle(const Model& model, const DisplayStyle& style) {
    std::vector<Element> root;
    for (std::size_t c = 0; c < model.components.size(); ++c) {
        const int index = static_cast<int>(c);
        writeComponent(model, index, style);
        if (style.onlyComponent >= 0 && style.onlyComponent != index) continue;
        if (style.errorMapComponent != index) root.push_back(executeStructure(structures::component(index)));
        if (style.hull) root.push_back(executeStructure(structures::hull(index)));
    }
    root.push_back(executeStructure(structures::errorMap));
    root.push_back(executeStructure(structures::mapped));
    root.push_back(executeStructure(structures::overlay));
    rewriteStructure(store_, structures::modelRoot, root);
}

void ModelPicture::writeComponent(const Model& model, int index, const DisplayStyle& style) {
    const Component& comp = model.components[static_cast<std::size_t>(index)];
    std::vector<Element> e;
    e.push_back(label(index + 1));
    if (style.shaded) {
        e.push_back(indexOf(ElementType::InteriorStyle, static_cast<int>(InteriorStyle::Solid)));
        e.push_back(indexOf(ElementType::InteriorShadingMethod, static_cast<int>(ShadingMethod::Colour)));
        e.push_back(
            indexOf(ElementType::InteriorReflectanceEquation, static_cast<int>(ReflectanceModel::Specular)));
        AreaPropertiesAttribute properties{ElementType::AreaProperties};
        properties.ambient = 0.35;
        properties.diffuse = 0.65;
        properties.specular = 0.25;
        properties.specularExponent = 20;
        e.push_back(properties);
        e.push_back(LightSourceStateAttribute{{1, 2}, {}});
        e.push_back(colourOf(ElementType::PolylineColour, comp.colour * 0.45));
    } else {
        e.push_back(indexOf(ElementType::InteriorStyle, static_cast<int>(InteriorStyle::Empty)));
        e.push_back(SurfaceCharacteristicsAttribute{3, 0, 1, 1});
        e.push_back(colourOf(ElementType::PolylineColour, comp.colour));
    }
    e.push_back(colourOf(ElementType::InteriorColour, comp.colour));
    for (const Patch& p : comp.patches.patches) {
        if (style.colourfulComponent == index)
            e.push_back(colourOf(ElementType::InteriorColour, patchColour(p.number)));
        else if (style.highlightComponent == index && style.highlightPatch == p.number)
            e.push_back(colourOf(ElementType::InteriorColour, {1.0, 0.85, 0.1}));
        e.push_back(executeStructure(structures::patch(index, p.number)));
        if (style.highlightComponent == index && style.highlightPatch == p.number)
            e.push_back(colourOf(ElementType::InteriorColour, comp.colour));
    }
    rewriteStructure(store_, structures::component(index), e);
}

void ModelPicture::clear() {
    for (int id : built_)
        if (store_.exists(id)) store_.deleteStructure(id);
    built_.clear();
}

std::optional<PickedPatch> ModelPicture::fromPath(const std::vector<PickPathItem>& path) {
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
        if (it->structureId >= 100000)
            return PickedPatch{it->structureId / 100000 - 1, it->structureId % 100000};
        if (it->structureId >= 1000 && it->structureId < 2000) return PickedPatch{it->structureId - 1000, 0};
    }
    return std::nullopt;
}

}  // namespace acsynt
