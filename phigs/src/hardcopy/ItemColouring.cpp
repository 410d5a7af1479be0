#include "phigs/hardcopy/ItemColouring.h"

#include "phigs/core/ColourModels.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace phigs::hardcopy {
namespace {

/// One light's share (scene.glsl oneLight): ambient always, diffuse from model 3, specular from 4.
glm::dvec3 oneLight(const Light& light, int model, const Reflectance& k, glm::dvec3 base,
                    const glm::dvec3& world, const glm::dvec3& n, const glm::dvec3& eye) {
    const glm::dvec3 colour(light.colour);
    if (light.type == LightType::Ambient) return double(k.ambient) * colour * base;
    if (model < 3) return glm::dvec3(0.0);
    const glm::dvec3 direction =
        glm::length(light.direction) > 0.0 ? glm::normalize(light.direction) : glm::dvec3(0, 0, -1);
    glm::dvec3 l = -direction;
    double attenuation = 1.0;
    if (light.type != LightType::Directional) {
        const glm::dvec3 toLight = light.position - world;
        const double distance = glm::length(toLight);
        l = toLight / std::max(distance, 1e-9);
        attenuation = 1.0 / std::max(double(light.attenuation.x) + light.attenuation.y * distance, 1e-9);
        if (light.type == LightType::Spot) {
            const double c = glm::dot(-l, direction);
            attenuation *= c >= std::cos(double(light.spreadAngle))
                               ? std::pow(std::max(c, 0.0), light.concentration)
                               : 0.0;
        }
    }
    const double nl = glm::dot(n, l);
    glm::dvec3 sum = double(k.diffuse) * colour * base * (std::max(nl, 0.0) * attenuation);
    if (model >= 4) {
        const glm::dvec3 r = glm::reflect(-l, n);
        const double rv = std::max(glm::dot(r, eye), 0.0);
        const double facing = nl > 0.0 ? attenuation : 0.0;
        sum += double(k.specular) * colour * glm::dvec3(k.specularColour) *
               (std::pow(rv, std::max(double(k.specularExponent), 0.0)) * facing);
    }
    return sum;
}

/// The components of `rgb` in the rendering colour model `m`, as the raster's shaders take them
/// (shaders/colour_models.glsl): other models than RGB see the colour clamped to [0, 1].
glm::dvec3 inModel(ColourModel m, glm::dvec3 rgb) {
    if (m == ColourModel::Rgb) return rgb;
    return fromRgb(m, glm::clamp(rgb, glm::dvec3(0.0), glm::dvec3(1.0)));
}

glm::dvec3 unit(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : glm::dvec3(0.0);
}

}  // namespace

ItemColouring::ItemColouring(const DrawList& list, const DrawItem& item, const glm::dvec4& viewer,
                             const glm::vec4& highlight)
    : viewer_(viewer), highlight_(item.highlighted() ? highlight : glm::vec4(0.0f)) {
    if (item.lightSet() >= 0 && item.lightSet() < int(list.lightSets.size()))
        lights_ = &list.lightSets[std::size_t(item.lightSet())];
    if (item.depthCue() >= 0 && item.depthCue() < int(list.depthCues.size()) &&
        list.depthCues[std::size_t(item.depthCue())].enabled)
        cue_ = &list.depthCues[std::size_t(item.depthCue())];
}

glm::dvec3 ItemColouring::towardViewer(const glm::dvec3& world) const {
    if (viewer_.w == 0.0) return glm::dvec3(viewer_);
    const glm::dvec3 d = glm::dvec3(viewer_) - world;
    const double length = glm::length(d);
    return length > 0.0 ? d / length : glm::dvec3(0, 0, 1);
}

glm::vec3 ItemColouring::lit(const InteriorStyleSet& interior, bool back, glm::vec3 base,
                             const glm::dvec3& world, const glm::dvec3& normal) const {
    const int model =
        int(back && interior.distinguishBackFaces ? interior.back.reflectance : interior.reflectance);
    if (model <= 1 || !lights_) return base;
    const Reflectance& k = back ? interior.backProperties : interior.properties;
    glm::dvec3 sum(0.0);
    for (const Light& light : *lights_)
        sum += oneLight(light, model, k, glm::dvec3(base), world, normal, towardViewer(world));
    return glm::vec3(sum);
}

glm::vec3 ItemColouring::facet(const InteriorStyleSet& interior, const std::vector<FacetVertex>& vertices,
                               bool vertexNormals, bool back, bool facetNormals) const {
    if (vertices.empty()) return interior.colour;
    const bool useBack = interior.distinguishBackFaces && back;
    glm::dvec3 centre(0.0), normal(0.0), base(0.0);
    // A facet shows the mean of its vertices' colours, taken in the rendering colour model.
    const ColourModel space = interior.renderingModel;
    for (const FacetVertex& v : vertices)
        centre += v.position, normal += v.normal, base += inModel(space, glm::dvec3(v.colour));
    const double n = double(vertices.size());
    centre /= n, base = toRgb(space, base / n);
    const glm::vec3 front = glm::vec3(base), backBase = useBack ? interior.backColour : front;
    const ReflectanceModel model = useBack ? interior.back.reflectance : interior.reflectance;
    const bool lighting = model != ReflectanceModel::None && lights_;
    if (!lighting) return useBack ? interior.backColour : front;
    const ShadingMethod method = vertexNormals ? interior.shadingOf(back) : ShadingMethod::None;
    if (method == ShadingMethod::Colour || method == ShadingMethod::DotProduct) {
        // Gouraud: each vertex lit (the back with the normal turned round), then averaged.
        glm::dvec3 sum(0.0);
        for (const FacetVertex& v : vertices) {
            const glm::vec3 b = useBack ? interior.backColour : v.colour;
            const glm::vec3 vertex =
                lit(interior, useBack, b, v.position, back ? -unit(v.normal) : unit(v.normal));
            sum += inModel(space, glm::dvec3(glm::clamp(vertex, glm::vec3(0.0f), glm::vec3(1.0f))));
        }
        return glm::vec3(toRgb(space, sum / n));
    }
    glm::dvec3 facetNormal(0.0);
    if (method == ShadingMethod::Normal || facetNormals) {
        facetNormal = unit(normal);
    } else {
        // Flat: the plane's normal, turned the way the vertex normals point, else toward the viewer.
        for (std::size_t i = 1; i + 1 < vertices.size(); ++i)
            facetNormal += glm::cross(vertices[i].position - vertices[0].position,
                                      vertices[i + 1].position - vertices[0].position);
        facetNormal = unit(facetNormal);
        const glm::dvec3 eye = towardViewer(centre);
        const glm::dvec3 towards = glm::dot(normal, normal) > 0.0 ? normal : (back ? -eye : eye);
        if (glm::dot(facetNormal, towards) < 0.0) facetNormal = -facetNormal;
    }
    if (back) facetNormal = -facetNormal;
    return lit(interior, useBack, backBase, centre, facetNormal);
}

ItemColouring::CellLighting ItemColouring::patternLighting(const InteriorStyleSet& interior,
                                                           std::vector<FacetVertex> vertices,
                                                           bool vertexNormals, bool back,
                                                           bool facetNormals) const {
    // The side's base colour is the cell's whichever side shows (front, back, vertex colours).
    auto litWith = [&](float base) {
        InteriorStyleSet in = interior;
        in.colour = in.backColour = glm::vec3(base);
        for (FacetVertex& v : vertices) v.colour = glm::vec3(base);
        return facet(in, vertices, vertexNormals, back, facetNormals);
    };
    const glm::vec3 offset = litWith(0.0f);
    return {litWith(1.0f) - offset, offset};
}

glm::vec3 ItemColouring::finish(glm::vec3 colour, double npcZ, ColourModel model) const {
    // A lit colour past 1 is clamped before it is depth cued, as the raster does.
    colour = glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
    if (cue_) {
        const double range = std::max(cue_->frontPlane - cue_->backPlane, 1e-9);
        const float t = float(std::clamp((npcZ - cue_->backPlane) / range, 0.0, 1.0));
        const float s = cue_->backScale + (cue_->frontScale - cue_->backScale) * t;
        if (model == ColourModel::Rgb) {
            colour = s * colour + (1.0f - s) * cue_->colour;
        } else {
            const glm::dvec3 mixed = double(s) * inModel(model, glm::dvec3(colour)) +
                                     double(1.0f - s) * inModel(model, glm::dvec3(cue_->colour));
            colour = glm::vec3(toRgb(model, mixed));
        }
    }
    colour = glm::mix(colour, glm::vec3(highlight_), highlight_.w);
    return glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace phigs::hardcopy
