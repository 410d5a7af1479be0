// PHIGS PLUS surfaces: shading methods, light types, reflectance, back faces, depth cueing,
// hidden-surface removal, iso-lines on shaded surfaces, highlighting.
#include "RenderTestSupport.h"
#include "SceneMeshes.h"
#include "phigs/vk/ImageTarget.h"

#include <glm/common.hpp>

#include <random>

namespace test_shading {

using namespace phigs;
using namespace render_test;

namespace {

DrawMesh shaded(std::shared_ptr<const MeshData> mesh, ShadingMethod shading, glm::vec3 colour) {
    DrawMesh m;
    m.mesh = std::move(mesh);
    m.interior.edit().style = InteriorStyle::Solid;
    m.interior.edit().colour = colour;
    m.interior.edit().shading = shading;
    m.interior.edit().reflectance = ReflectanceModel::Specular;
    m.interior.edit().properties.ambient = 0.2f;
    m.interior.edit().properties.diffuse = 0.7f;
    m.interior.edit().properties.specular = 0.6f;
    m.interior.edit().properties.specularExponent = 30.0f;
    return m;
}

std::vector<Light> keyLights() {
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.colour = glm::vec3(1.0f);
    Light key;
    key.type = LightType::Directional;
    key.direction = glm::normalize(glm::dvec3(-1, -1, -2));
    return {ambient, key};
}

}  // namespace

TEST_CASE("surfaces: flat, Gouraud and Phong shading with specular reflectance", "[render][shading]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        list.hiddenSurfaceRemoval = true;
        list.lightSets.push_back(keyLights());
        const ShadingMethod methods[] = {ShadingMethod::None, ShadingMethod::Colour, ShadingMethod::Normal};
        for (int k = 0; k < 3; ++k) {
            DrawItem i = item(shaded(sphere({0.18f + 0.32f * k, 0.5f, 0.5f}, 0.14f, 12, 8), methods[k],
                                     {0.2f, 0.5f, 1.0f}));
            i.context.edit().lightSet = 0;
            list.items.push_back(i);
        }
        const Image image = ws.draw(list);
        // The lit side (upper right, toward the light) is brighter than the far side.
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t cx = std::uint32_t((0.18 + 0.32 * k) * 256), cy = 128;
            CHECK(at(image, cx + 14, cy - 14).b > at(image, cx - 20, cy + 20).b + 40);
        }
        compareWithReference(image, "shading");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("lights: ambient, directional, positional and spot light on four grids", "[render][shading]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        Light ambient;
        ambient.type = LightType::Ambient;
        ambient.colour = {0.6f, 0.6f, 0.6f};
        Light directional;
        directional.type = LightType::Directional;
        directional.direction = glm::normalize(glm::dvec3(1, 0, -1));
        directional.colour = {1, 0.9f, 0.6f};
        Light positional;
        positional.type = LightType::Positional;
        positional.position = {0.2, 0.3, 0.62};
        positional.attenuation = {0.3f, 3.0f};
        Light spot;
        spot.type = LightType::Spot;
        spot.position = {0.75, 0.25, 0.9};
        spot.direction = {0, 0, -1};
        spot.concentration = 2.0f;
        spot.spreadAngle = 0.35f;
        spot.colour = {0.5f, 1.0f, 0.5f};
        list.lightSets = {{ambient}, {directional}, {positional}, {spot}};
        const double cells[4][2] = {{0.02, 0.52}, {0.52, 0.52}, {0.02, 0.02}, {0.52, 0.02}};
        for (int k = 0; k < 4; ++k) {
            DrawMesh m =
                shaded(grid(cells[k][0], cells[k][1], cells[k][0] + 0.46, cells[k][1] + 0.46, 0.5, 16),
                       ShadingMethod::Normal, {1, 1, 1});
            m.interior.edit().reflectance = ReflectanceModel::Diffuse;
            m.interior.edit().properties.ambient = 1.0f;
            m.interior.edit().properties.diffuse = 1.0f;
            DrawItem i = item(m);
            i.context.edit().lightSet = k;
            list.items.push_back(i);
        }
        const Image image = ws.draw(list);
        CHECK(near(at(image, 64, 64), 153, 153, 153));             // ambient 0.6, uniform
        CHECK(near(at(image, 192, 64), 180, 162, 108, 6));         // cos 45 deg
        CHECK(at(image, 51, 179).r > at(image, 110, 240).r + 60);  // positional falls off
        CHECK(at(image, 192, 192).g > 200);                        // inside the spot cone
        CHECK(at(image, 140, 140).g < 30);                         // outside it
        compareWithReference(image, "lights");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("back faces: distinguished colour, and culling of back or front faces", "[render][shading]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        // Top row faces the viewer, bottom row faces away (clockwise seen from +z).
        auto quad = [](double x, double y, bool front) {
            DrawFillArea f;
            std::vector<glm::dvec3> c = {
                {x, y, 0.5}, {x + 0.25, y, 0.5}, {x + 0.25, y + 0.4, 0.5}, {x, y + 0.4, 0.5}};
            if (!front) std::reverse(c.begin(), c.end());
            f.contours = {c};
            f.interior.edit().style = InteriorStyle::Solid;
            f.interior.edit().colour = {0.2f, 0.8f, 0.2f};
            f.interior.edit().backColour = {0.9f, 0.2f, 0.2f};
            f.interior.edit().distinguishBackFaces = true;
            f.interior.edit().back.style = InteriorStyle::Solid;
            f.facetNormal = front ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 0, -1);
            return f;
        };
        const CullMode culls[] = {CullMode::None, CullMode::BackFaces, CullMode::FrontFaces};
        for (int k = 0; k < 3; ++k)
            for (bool front : {true, false}) {
                DrawFillArea f = quad(0.05 + 0.32 * k, front ? 0.55 : 0.05, front);
                f.interior.edit().cull = culls[k];
                list.items.push_back(item(f));
            }
        const Image image = ws.draw(list);
        auto px = [&](double x, double y) {
            return at(image, std::uint32_t(x * 256), std::uint32_t((1 - y) * 256));
        };
        CHECK(near(px(0.17, 0.75), 51, 204, 51));  // front, no culling
        CHECK(near(px(0.17, 0.25), 230, 51, 51));  // back, distinguished
        CHECK(near(px(0.49, 0.75), 51, 204, 51));  // front survives back-face culling
        CHECK(near(px(0.49, 0.25), 25, 25, 25));   // back culled
        CHECK(near(px(0.81, 0.75), 25, 25, 25));   // front culled
        CHECK(near(px(0.81, 0.25), 230, 51, 51));  // back survives front-face culling
        compareWithReference(image, "back_faces");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("hidden surfaces: depth buffer on and off, iso-lines on a shaded surface do not z-fight",
          "[render][shading]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        list.lightSets.push_back(keyLights());
        // Near red square drawn first, far blue square second: with HLHSR the red one stays in front.
        auto square = [](double x, double z, glm::vec3 colour) {
            return solidRectangle(x, 0.55, x + 0.3, 0.95, z, colour);
        };
        list.items.push_back(item(square(0.05, 0.8, {1, 0.2f, 0.2f})));
        list.items.push_back(item(square(0.2, 0.3, {0.2f, 0.2f, 1})));
        DrawMesh globe =
            shaded(sphere({0.7f, 0.35f, 0.5f}, 0.25f, 32, 16, 4), ShadingMethod::Normal, {0.9f, 0.9f, 0.9f});
        globe.isoLineStyle.edit().colour = {1, 1, 0};
        DrawItem g = item(globe);
        g.context.edit().lightSet = 0;
        list.items.push_back(g);

        list.hiddenSurfaceRemoval = false;
        const Image painter = ws.draw(list);
        CHECK(near(at(painter, 64, 51), 51, 51, 255));  // blue, drawn last, covers the overlap
        list.hiddenSurfaceRemoval = true;
        const Image hidden = ws.draw(list);
        CHECK(near(at(hidden, 64, 51), 255, 51, 51));  // red, nearer, wins
        // The iso-line u = 0.5 runs over the front from the pole to the left rim at y = centre: every
        // pixel of it is yellow, none lost to the surface it lies on.
        int yellow = 0, total = 0;
        const std::uint32_t y = std::uint32_t((1 - 0.35) * 256);
        for (std::uint32_t x = std::uint32_t(0.47 * 256); x < std::uint32_t(0.69 * 256); ++x) {
            bool found = false;
            for (std::uint32_t dy = y - 2; dy <= y + 2; ++dy) {
                const Rgb c = at(hidden, x, dy);
                found = found || (c.r > 200 && c.g > 200 && c.b < 80);
            }
            yellow += found;
            ++total;
        }
        CHECK(yellow == total);
        compareWithReference(hidden, "hidden_surfaces");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("depth cueing fades toward the cue colour with depth, highlighting marks an item",
          "[render][shading]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        DepthCue cue;
        cue.enabled = true;
        cue.frontPlane = 1.0;
        cue.backPlane = 0.0;
        cue.frontScale = 1.0f;
        cue.backScale = 0.0f;
        cue.colour = {0.1f, 0.1f, 0.1f};
        list.depthCues.push_back(cue);
        for (int k = 0; k < 5; ++k) {
            const double x = 0.05 + 0.18 * k, z = 1.0 - 0.2 * k;
            DrawItem i = item(solidRectangle(x, 0.55, x + 0.15, 0.95, z, {1, 1, 1}));
            i.context.edit().depthCue = 0;
            list.items.push_back(i);
        }
        for (int k = 0; k < 2; ++k) {
            DrawPolyline l;
            l.points = {{0.1, 0.3 - 0.15 * k, 0.5}, {0.9, 0.3 - 0.15 * k, 0.5}};
            l.style.edit().colour = {0.2f, 0.4f, 1.0f};
            l.style.edit().width = 5.0f;
            DrawItem i = item(l);
            i.context.edit().highlighted = k == 1;
            list.items.push_back(i);
        }
        const Image image = ws.draw(list);
        const int front = at(image, 30, 64).r, back = at(image, 30 + 4 * 46, 64).r;
        CHECK(front > 250);
        CHECK(back < 120);
        CHECK(at(image, 40 + 46, 64).r < front);
        const Rgb normal = at(image, 128, std::uint32_t((1 - 0.3) * 256));
        const Rgb marked = at(image, 128, std::uint32_t((1 - 0.15) * 256));
        CHECK(near(normal, 51, 102, 255));
        CHECK(marked.r > 150);
        CHECK(marked.g > 150);
        compareWithReference(image, "depth_cue_highlight");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("flat shading derives facet normals for a mesh without normals, front and back",
          "[render][shading]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 64, 64);
        DrawList list = emptyScene();
        Light toward;
        toward.type = LightType::Directional;
        toward.direction = {0, 0, -1};  // shines at the viewer's side of the square
        list.lightSets.push_back({toward});
        for (bool front : {true, false}) {
            auto mesh = std::make_shared<MeshData>();
            const float x = front ? 0.05f : 0.55f;
            mesh->positions = {
                {x, 0.3f, 0.5f}, {x + 0.4f, 0.3f, 0.5f}, {x + 0.4f, 0.7f, 0.5f}, {x, 0.7f, 0.5f}};
            mesh->triangles = front ? std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}
                                    : std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2};
            DrawMesh m = shaded(mesh, ShadingMethod::None, {1, 1, 1});
            m.interior.edit().reflectance = ReflectanceModel::Diffuse;
            m.interior.edit().properties.diffuse = 1.0f;
            DrawItem i = item(m);
            i.context.edit().lightSet = 0;
            list.items.push_back(i);
        }
        const Image image = ws.draw(list);
        // Both sides face the light as the viewer sees them: fully lit.
        CHECK(near(at(image, 16, 32), 255, 255, 255, 3));
        CHECK(near(at(image, 48, 32), 255, 255, 255, 3));
    }
    requireNoValidationMessages(context);
}

TEST_CASE("meshes: visible edges and a hollow interior draw the triangle edges, curves draw as polylines",
          "[render][shading]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 64, 64);
        DrawList list = emptyScene();
        DrawMesh solid;
        solid.mesh = grid(0.05, 0.05, 0.45, 0.45, 0.5, 2);
        solid.interior.edit().style = InteriorStyle::Solid;
        solid.interior.edit().colour = {0, 0, 1};
        solid.edges.edit().visible = true;
        solid.edges.edit().colour = {1, 0, 0};
        list.items.push_back(item(solid));
        DrawMesh hollow;
        hollow.mesh = grid(0.55, 0.05, 0.95, 0.45, 0.5, 2);
        hollow.interior.edit().style = InteriorStyle::Hollow;
        hollow.interior.edit().colour = {0, 1, 0};
        list.items.push_back(item(hollow));
        DrawCurve curve;
        std::vector<glm::dvec3> curvePoints;
        for (int k = 0; k <= 16; ++k)
            curvePoints.push_back({0.1 + 0.05 * k, 0.75 + 0.1 * std::sin(0.4 * k), 0.5});
        curve.points = curvePoints;
        curve.style.edit().colour = {1, 1, 0};
        list.items.push_back(item(curve));
        const Image image = ws.draw(list);
        int red = 0, blue = 0, green = 0, yellow = 0, greenInside = 0;
        for (std::uint32_t y = 0; y < 64; ++y)
            for (std::uint32_t x = 0; x < 64; ++x) {
                const Rgb c = at(image, x, y);
                red += near(c, 255, 0, 0);
                blue += near(c, 0, 0, 255);
                green += near(c, 0, 255, 0);
                yellow += near(c, 255, 255, 0);
            }
        // The hollow grid's cells stay background between its edges.
        greenInside = near(at(image, 39, 39), 25, 25, 25) ? 1 : 0;
        CHECK(red > 40);
        CHECK(blue > 150);
        CHECK(green > 40);
        CHECK(greenInside == 1);
        CHECK(yellow > 30);
    }
    requireNoValidationMessages(context);
}

TEST_CASE("transparency: a surface blends over what lies behind it, whatever the traversal order",
          "[render][shading]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 128, 128);
        DrawList list = emptyScene();
        list.hiddenSurfaceRemoval = true;
        auto square = [](double x0, double x1, double z, glm::vec3 colour, float transparency) {
            DrawFillArea f = solidRectangle(x0, 0.2, x1, 0.8, z, colour);
            f.interior.edit().properties.transparency = transparency;
            return f;
        };
        // Traversal order: the see-through blue square (front) first, then the opaque red one
        // behind it, then an opaque green one in front of the blue on the right.
        list.items.push_back(item(square(0.1, 0.9, 0.8, {0, 0, 1}, 0.5f)));
        list.items.push_back(item(square(0.1, 0.5, 0.3, {1, 0, 0}, 0.0f)));
        list.items.push_back(item(square(0.7, 0.9, 0.95, {0, 1, 0}, 0.0f)));
        const Image image = ws.draw(list);
        CHECK(near(at(image, 38, 64), 128, 0, 128));  // blue half over red
        CHECK(near(at(image, 77, 64), 13, 13, 140));  // blue half over the background (0.1 grey)
        CHECK(near(at(image, 102, 64), 0, 255, 0));   // opaque green in front hides the blue
        CHECK(near(at(image, 64, 8), 26, 26, 26));    // background untouched
        CHECK(image.pixel(38, 64)[3] == 255);         // the picture itself stays opaque
        compareWithReference(image, "transparency");

        // Without hidden-surface removal the traversal order paints: red then green over the blue.
        list.hiddenSurfaceRemoval = false;
        const Image painted = ws.draw(list);
        CHECK(near(at(painted, 38, 64), 255, 0, 0));
        CHECK(near(at(painted, 77, 64), 13, 13, 140));
    }
    requireNoValidationMessages(context);
}

TEST_CASE("lit surfaces of more materials than the lit runs hold light as the equation says",
          "[render][shading]") {
    // Each material's lights are premultiplied by it once a frame, a lit run each, up to the lit
    // buffer's room; the draws past it light the general way. Both must give the PHIGS PLUS equation's
    // colour: flat grids facing the viewer (n = eye = +z), random colours and coefficients, lit by a random
    // ambient and directional light; some grids moved in z by their modelling transform.
    vk::Context context(lavapipeWithValidation());
    std::mt19937 random(31);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 2; ++trial) {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        Light ambient;
        ambient.type = LightType::Ambient;
        ambient.colour = {0.2f + 0.5f * unit(random), 0.2f + 0.5f * unit(random), 0.2f + 0.5f * unit(random)};
        Light key;
        key.type = LightType::Directional;
        key.direction = glm::normalize(glm::dvec3(unit(random) - 0.5, unit(random) - 0.5, -1.0));
        key.colour = {0.5f + 0.5f * unit(random), 0.5f + 0.5f * unit(random), 0.5f + 0.5f * unit(random)};
        list.lightSets.push_back({ambient, key});
        const int side = 17;  // 289 materials: more than the 256 lit runs
        std::vector<glm::vec3> expected;
        for (int k = 0; k < side * side; ++k) {
            const double x0 = (k % side + 0.1) / side, y0 = (k / side + 0.1) / side;
            const glm::vec3 colour(unit(random), unit(random), unit(random));
            DrawMesh m =
                shaded(grid(x0, y0, x0 + 0.8 / side, y0 + 0.8 / side, 0.5, 2), ShadingMethod::Normal, colour);
            Reflectance& p = m.interior.edit().properties;
            p.ambient = unit(random), p.diffuse = unit(random), p.specular = unit(random);
            p.specularExponent = 1.0f + 20.0f * unit(random);
            p.specularColour = {unit(random), unit(random), unit(random)};
            DrawItem i = item(m);
            i.context.edit().lightSet = 0;
            if (k % 3 == 0) {
                i.context.edit().modelTransform = glm::dmat4(1.0);
                i.context.edit().modelTransform.edit()[3] = glm::dvec4(0.0, 0.0, 0.1, 1.0);
            }
            list.items.push_back(i);
            const glm::vec3 l = -glm::vec3(key.direction);  // toward the light; n = eye = +z
            const glm::vec3 lit =
                p.ambient * ambient.colour * colour + p.diffuse * key.colour * colour * l.z +
                p.specular * key.colour * p.specularColour * std::pow(l.z, p.specularExponent);
            expected.push_back(glm::clamp(lit, 0.0f, 1.0f));
        }
        const Image image = ws.draw(list);
        for (int k = 0; k < side * side; ++k) {
            const glm::dvec2 centre((k % side + 0.5) / side * 256, (1.0 - (k / side + 0.5) / side) * 256);
            INFO("trial " << trial << ", material " << k);
            CHECK(shows(image, centre, glm::dvec3(expected[std::size_t(k)]), 3));
        }
    }
    requireNoValidationMessages(context);
}

}  // namespace test_shading
