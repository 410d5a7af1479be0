// Several views in one workstation (orientation, mapping, clip limits each), the workstation
// window/viewport mapping, and the PNG hardcopy workstation.
#include "RenderTestSupport.h"
#include "SceneMeshes.h"
#include "phigs/hardcopy/VectorDescriber.h"
#include "phigs/traverse/WorkstationMapping.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/vk/HardcopyTarget.h"
#include "phigs/vk/ImageTarget.h"

#include <glm/geometric.hpp>

#include <random>

namespace test_views {

using namespace phigs;
using namespace render_test;

namespace {

/// World -> VRC for a view reference point, view plane normal and view up vector (PHIGS EVALUATE
/// VIEW ORIENTATION MATRIX 3).
glm::dmat4 orientation(glm::dvec3 vrp, glm::dvec3 vpn, glm::dvec3 vup) {
    const glm::dvec3 n = glm::normalize(vpn);
    const glm::dvec3 u = glm::normalize(glm::cross(vup, n));
    const glm::dvec3 v = glm::cross(n, u);
    glm::dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) {
        m[i][0] = u[i];
        m[i][1] = v[i];
        m[i][2] = n[i];
    }
    m[3] = glm::dvec4(-glm::dot(u, vrp), -glm::dot(v, vrp), -glm::dot(n, vrp), 1.0);
    return m;
}

/// Parallel VRC window [-h, h]^2, depth [-h, h] -> the NPC box [lo, hi] (PHIGS EVALUATE VIEW MAPPING).
glm::dmat4 parallelMapping(double h, glm::dvec3 lo, glm::dvec3 hi) {
    glm::dmat4 m(1.0);
    const glm::dvec3 scale = (hi - lo) / (2.0 * h);
    m[0][0] = scale.x;
    m[1][1] = scale.y;
    m[2][2] = scale.z;
    m[3] = glm::dvec4(lo + h * scale, 1.0);
    return m;
}

void addAxesAndBody(DrawList& list, int view, std::shared_ptr<const MeshData> body) {
    const glm::vec3 colours[3] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.3f, 0.5f, 1}};
    for (int a = 0; a < 3; ++a) {
        DrawPolyline axis;
        glm::dvec3 end(0.0);
        end[a] = 1.2;
        axis.points = {glm::dvec3(0.0), end};
        axis.style.edit().colour = colours[a];
        axis.style.edit().width = 2.0f;
        list.items.push_back(item(axis, view));
    }
    DrawMesh m;
    m.mesh = std::move(body);
    m.interior.edit().style = InteriorStyle::Solid;
    m.interior.edit().colour = {0.8f, 0.8f, 0.8f};
    m.interior.edit().shading = ShadingMethod::Normal;
    m.interior.edit().reflectance = ReflectanceModel::Diffuse;
    DrawItem i = item(m, view);
    i.context.edit().lightSet = 0;
    list.items.push_back(i);
}

}  // namespace

TEST_CASE("views: four views with their own orientation, mapping and clip limits", "[render][views]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        list.views.clear();
        list.hiddenSurfaceRemoval = true;
        Light ambient;
        ambient.colour = glm::vec3(0.3f);
        Light key;
        key.type = LightType::Directional;
        key.direction = glm::normalize(glm::dvec3(-1, -2, -3));
        list.lightSets.push_back({ambient, key});
        // An elongated body (a fuselage-like ellipsoid, made from a scaled sphere).
        auto body = sphere({0, 0, 0}, 1.0f, 24, 12);
        for (auto& p : body->positions) p *= glm::vec3(0.9f, 0.3f, 0.2f);
        const glm::dvec3 vpns[4] = {{0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {1, -1, 1}};
        const glm::dvec3 vups[4] = {{0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
        const glm::dvec2 corners[4] = {{0, 0.5}, {0.5, 0.5}, {0, 0}, {0.5, 0}};
        for (int v = 0; v < 4; ++v) {
            DrawView view;
            const glm::dvec3 lo(corners[v] + 0.01, 0.0), hi(corners[v] + 0.49, 1.0);
            view.orientation = orientation({0, 0, 0}, vpns[v], vups[v]);
            view.mapping = parallelMapping(1.3, lo, hi);
            view.clipMin = lo;
            view.clipMax = hi;
            list.views.push_back(view);
            addAxesAndBody(list, v, body);
            // A polyline crossing the whole view shows that each view clips at its own limits.
            DrawPolyline across;
            across.points = {{-5, -5, -5}, {5, 5, 5}};
            across.style.edit().colour = {1, 1, 0};
            list.items.push_back(item(across, v));
        }
        const Image image = ws.draw(list);
        // The x axis (red) runs right in the front view (top left)...
        CHECK(at(image, 64 + 52, 64).r > 200);
        // ...and toward the viewer in the side view (bottom left), where it is a point at the centre.
        CHECK(at(image, 64 + 40, 192).r < 100);
        // Clip limits: the gaps between the view boxes stay background.
        for (std::uint32_t y = 0; y < 256; y += 4) CHECK(near(at(image, 128, y), 25, 25, 25));
        compareWithReference(image, "views");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("views: every entry of the view table can be used up to the last one", "[render][views]") {
    // The workstation types' view tables hold 32 entries: a view at index 31 draws (with the
    // entries below it defined or not) as view 1 does.
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 64, 64);
        for (const int index : {1, 16, 31}) {
            DrawList list = emptyScene();
            list.views.assign(static_cast<std::size_t>(index) + 1, DrawView{});
            DrawView& view = list.views.back();
            view.mapping = parallelMapping(1.0, {0.0, 0.0, 0.0}, {0.5, 0.5, 1.0});  // the lower left quarter
            DrawPolyline cross;
            cross.points = {{-1, -1, 0}, {1, 1, 0}};
            cross.style.edit().colour = {1, 1, 0};
            cross.style.edit().width = 3.0f;
            list.items.push_back(item(cross, index));
            INFO("view " << index);
            const Image image = ws.draw(list);
            CHECK(at(image, 16, 48).r > 200);  // on the diagonal of the lower left quarter
            CHECK(near(at(image, 48, 16), 25, 25, 25));
        }
    }
    requireNoValidationMessages(context);
}

TEST_CASE("views: a perspective view's depth limits cut a tilted area at its true NPC depth",
          "[render][views]") {
    // NPC z of a plane is affine across the screen only after the perspective divide: the cut
    // by the front clip limit is where z/w reaches it, a straight line, for random tilts.
    vk::Context context(lavapipeWithValidation());
    {
        const std::uint32_t size = 160;
        vk::ImageTarget ws(context, size, size);
        ViewMapping perspective;
        perspective.projection = ProjectionType::Perspective;
        perspective.projectionReferencePoint = {0, 0, 2};
        perspective.backPlaneDistance = -1.0;
        perspective.frontPlaneDistance = 1.0;
        const glm::dmat4 mapping = evaluateViewMappingMatrix(perspective);
        std::mt19937 random(612);
        std::uniform_real_distribution<double> centre(-0.3, 0.3), slope(-0.5, 0.5), share(0.2, 0.8);
        for (int trial = 0; trial < 6; ++trial) {
            // A plane z = z0 + gx x + gy y, its corners over [-0.6, 0.6]^2 within VRC z [-0.9, 0.9],
            // cut by a front limit between its nearest and farthest corners' NPC depths.
            const double z0 = centre(random), gx = slope(random), gy = slope(random);
            const auto corner = [&](double x, double y) { return glm::dvec3(x, y, z0 + gx * x + gy * y); };
            const glm::dvec3 a = corner(-0.6, -0.6), b = corner(0.6, -0.6), c = corner(0.6, 0.6),
                             d = corner(-0.6, 0.6);
            double nearest = -1e9, farthest = 1e9;
            for (const glm::dvec3& p : {a, b, c, d}) {
                const glm::dvec4 q = mapping * glm::dvec4(p, 1.0);
                nearest = std::max(nearest, q.z / q.w), farthest = std::min(farthest, q.z / q.w);
            }
            DrawList list = emptyScene();
            DrawView view;
            view.mapping = mapping;
            view.clipMax.z = farthest + (nearest - farthest) * share(random);
            list.views.push_back(view);
            DrawFillArea quad = solidRectangle(0, 0, 1, 1, 0, {1, 1, 0});
            quad.contours = {{a, b, c, d}};
            list.items.push_back(item(quad, 1));
            const Image image = ws.draw(list);
            // Each pixel's expected state from the plane's points sampled over it: drawn when all
            // lie nearer than the limit, empty when all lie beyond it (or off the quad).
            std::vector<double> lo(size * size, 1e9), hi(size * size, -1e9);
            const int samples = 1200;
            for (int i = 0; i <= samples; ++i)
                for (int j = 0; j <= samples; ++j) {
                    const glm::dvec3 p =
                        a + (b - a) * (double(i) / samples) + (d - a) * (double(j) / samples);
                    const glm::dvec4 q = mapping * glm::dvec4(p, 1.0);
                    const glm::dvec3 npc = glm::dvec3(q) / q.w;
                    const int x = int(npc.x * size), y = int((1.0 - npc.y) * size);
                    if (x < 0 || y < 0 || x >= int(size) || y >= int(size)) continue;
                    lo[std::size_t(y) * size + std::size_t(x)] =
                        std::min(lo[std::size_t(y) * size + std::size_t(x)], npc.z);
                    hi[std::size_t(y) * size + std::size_t(x)] =
                        std::max(hi[std::size_t(y) * size + std::size_t(x)], npc.z);
                }
            std::size_t wrong = 0, drawn = 0, cut = 0;
            for (std::uint32_t y = 1; y + 1 < size; ++y)
                for (std::uint32_t x = 1; x + 1 < size; ++x) {
                    const std::size_t k = std::size_t(y) * size + x;
                    const bool shows = at(image, x, y).r > 128;
                    // Pixels on the quad's outline (partly covered) say nothing.
                    bool inside = true;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx)
                            inside = inside && hi[k + std::size_t(dy * int(size) + dx)] > -1e9;
                    if (!inside) continue;
                    if (hi[k] < view.clipMax.z) wrong += !shows, ++drawn;
                    if (lo[k] > view.clipMax.z) wrong += shows, ++cut;
                }
            INFO("trial " << trial << ": " << drawn << " pixels nearer than the limit, " << cut << " beyond, "
                          << wrong << " wrong");
            CHECK(wrong == 0);
        }
    }
    requireNoValidationMessages(context);
}

TEST_CASE("workstation window and viewport: zoom into NPC and map isotropically", "[render][views]") {
    DrawList list = emptyScene();
    list.windowMin = {0.0, 0.0, 0.0};
    list.windowMax = {0.5, 0.5, 1.0};
    {
        // GPU-free: the workstation transform itself.
        const WorkstationMapping square(list, 256, 256);
        CHECK(square.pixelsPerNpc == Approx(512.0));
        const glm::dvec2 centre = square.toPixels({0.25, 0.25, 0.0});
        CHECK(centre.x == Approx(128.0));
        CHECK(centre.y == Approx(128.0));
        // A wide target: device coordinates span its shorter side; the window keeps its aspect.
        const WorkstationMapping wide(list, 400, 200);
        CHECK(wide.pixelsPerNpc == Approx(400.0));
        CHECK(wide.toPixels({0.5, 0.5, 0}).x == Approx(200.0));
        const PixelRect rect = wide.scissor({-1, -1}, {2, 2});
        CHECK(rect.width == 200);
        CHECK(rect.height == 200);
    }
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawPolymarker m;
        m.points = {{0.25, 0.25, 0.5}, {0.75, 0.75, 0.5}};  // the second lies outside the window
        m.style.edit().type = MarkerType::Plus;
        m.style.edit().scale = 3.0f;
        list.items.push_back(item(m));
        DrawFillArea f;
        f.contours = {{{0.0, 0.0, 0.5}, {0.1, 0.0, 0.5}, {0.1, 0.1, 0.5}, {0.0, 0.1, 0.5}}};
        f.interior.edit().style = InteriorStyle::Solid;
        f.interior.edit().colour = {0, 0, 1};
        list.items.push_back(item(f));
        const Image image = ws.draw(list);
        CHECK(std::max(at(image, 128 + 8, 127).g, at(image, 128 + 8, 128).g) > 200);
        CHECK(near(at(image, 20, 236), 0, 0, 255));  // the NPC square 0..0.1 is now 51 pixels wide
        CHECK(near(at(image, 48, 208), 0, 0, 255));
        CHECK(near(at(image, 56, 200), 25, 25, 25));
        compareWithReference(image, "workstation_window");
    }
    requireNoValidationMessages(context);
}

namespace {

/// Pixels of the marker colour (pure green), all of them or those inside `rect`.
std::size_t markerPixels(const Image& image, const PixelRect* rect = nullptr) {
    std::size_t n = 0;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const bool in = !rect || (std::int64_t(x) >= rect->x && std::int64_t(x) < rect->x + rect->width &&
                                      std::int64_t(y) >= rect->y && std::int64_t(y) < rect->y + rect->height);
            if (in && at(image, x, y).g > 128 && at(image, x, y).r < 64) ++n;
        }
    return n;
}

}  // namespace

TEST_CASE("views: a marker is clipped by its position, not by its glyph", "[render][views]") {
    // ISO 9592 clips a marker by its position: one just outside a view's clip rectangle draws
    // nothing even where its glyph reaches inside; one just inside draws what the scissor keeps.
    vk::Context context(lavapipeWithValidation());
    {
        constexpr std::uint32_t size = 128;
        vk::ImageTarget ws(context, size, size);
        std::mt19937 random(20261205);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int outside = 0, inside = 0;
        for (int trial = 0; trial < 40; ++trial) {
            DrawList list = emptyScene();
            DrawView& view = list.views[0];
            view.clipMin = {0.2 + 0.2 * unit(random), 0.2 + 0.2 * unit(random), 0.0};
            view.clipMax = {0.6 + 0.2 * unit(random), 0.6 + 0.2 * unit(random), 1.0};
            // A point 0.5 to 4 pixels off one edge, outside or inside, somewhere along it.
            const int edge = int(random() % 4), axis = edge % 2;
            const bool out = trial % 2 == 0;
            const double offset = (0.5 + 3.5 * unit(random)) / size * (out ? 1.0 : -1.0);
            glm::dvec3 p(0.0, 0.0, 0.5);
            p[axis] = edge < 2 ? view.clipMin[axis] - offset : view.clipMax[axis] + offset;
            p[1 - axis] = glm::mix(view.clipMin[1 - axis], view.clipMax[1 - axis], 0.2 + 0.6 * unit(random));
            DrawPolymarker m;
            m.points = {p};
            m.style.edit().type = random() % 2 ? MarkerType::Plus : MarkerType::Asterisk;
            m.style.edit().scale = 4.0f;
            m.style.edit().colour = {0, 1, 0};
            list.items.push_back(item(m));
            const PixelRect rect = WorkstationMapping(list, size, size)
                                       .scissor(glm::dvec2(view.clipMin), glm::dvec2(view.clipMax));
            view.clipXY = false;
            const Image whole = ws.draw(list);
            // The glyph reaches across the edge: the test means something either way.
            REQUIRE(markerPixels(whole, &rect) > 0);
            REQUIRE(markerPixels(whole) > markerPixels(whole, &rect));
            view.clipXY = true;
            const Image clipped = ws.draw(list);
            if (out) {
                CHECK(markerPixels(clipped) == 0);
                ++outside;
            } else {
                CHECK(markerPixels(clipped) == markerPixels(whole, &rect));
                CHECK(markerPixels(clipped, &rect) == markerPixels(clipped));
                ++inside;
            }
        }
        CHECK(outside == 20);
        CHECK(inside == 20);
    }
    requireNoValidationMessages(context);
}

TEST_CASE("views: annotation text is clipped by its reference point, on screen and on paper",
          "[render][views]") {
    // ISO 9592: a reference point outside the view's clip rectangle or the workstation window
    // displays nothing, though the offset brings the text (and its lead line) inside; one just
    // inside draws it. The vector hardcopy paints the same.
    vk::Context context(lavapipeWithValidation());
    {
        constexpr std::uint32_t size = 128;
        vk::ImageTarget ws(context, size, size);
        std::mt19937 random(20261207);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int trial = 0; trial < 24; ++trial) {
            DrawList list = emptyScene();
            const double lo = 0.2 + 0.1 * unit(random), hi = 0.7 + 0.1 * unit(random);
            const bool byWindow = trial % 4 >= 2, out = trial % 2 == 0;
            if (byWindow) {
                list.windowMin = {lo, lo, 0.0};
                list.windowMax = {hi, hi, 1.0};
            } else {
                list.views[0].clipMin = {lo, lo, 0.0};
                list.views[0].clipMax = {hi, hi, 1.0};
                list.views[0].clipXY = true;
            }
            const double off = (1.0 + 3.0 * unit(random)) / size;
            DrawText note;
            note.text = "NOTE";
            note.annotation = true;
            note.position = {out ? lo - off : lo + off, 0.4 + 0.2 * unit(random), 0.5};
            note.annotationOffset = {0.1, 0.0, 0.0};
            note.style.edit().height = 0.06;
            note.style.edit().colour = {0, 1, 0};
            note.leadLine = LineStyle{{0, 1, 0}, LineType::Solid, 1.0f};
            list.items.push_back(item(note));
            INFO("trial " << trial << (byWindow ? ", window" : ", view limits")
                          << (out ? ", outside" : ", inside"));
            const Image image = ws.draw(list);
            const hardcopy::VectorPicture paper = hardcopy::describePicture(list, hardcopy::PageSetup{});
            const auto strokes =
                std::count_if(paper.ops.begin(), paper.ops.end(), [](const hardcopy::VectorOp& op) {
                    return std::holds_alternative<hardcopy::VectorStroke>(op);
                });
            if (out) {
                CHECK(markerPixels(image) == 0);
                CHECK(strokes == 0);
            } else {
                CHECK(markerPixels(image) > 20);
                CHECK(strokes > 4);
            }
        }
    }
    requireNoValidationMessages(context);
}

TEST_CASE("an offscreen image past the device's limits is refused, naming them", "[render][views]") {
    // Vulkan leaves sizes past maxImageDimension2D undefined (validation errors, or a failed
    // allocation naming no cause): refused before anything is made.
    vk::Context context(lavapipeWithValidation());
    {
        VkPhysicalDeviceProperties properties{};
        vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
        const std::uint32_t most =
            std::min(properties.limits.maxImageDimension2D,
                     std::min(properties.limits.maxFramebufferWidth, properties.limits.maxFramebufferHeight));
        for (const auto& [w, h] : {std::pair{most + 1, 10u}, std::pair{10u, most + 1},
                                   std::pair{100000u, 100000u}, std::pair{0u, 10u}}) {
            INFO(w << " x " << h);
            CHECK_THROWS_WITH(vk::ImageTarget(context, w, h),
                              Catch::Contains("the device draws") && Catch::Contains(std::to_string(most)));
        }
        vk::ImageTarget edge(context, most, 1);  // the limit itself is drawn
        CHECK(edge.draw(emptyScene()).width == most);
    }
    requireNoValidationMessages(context);
}

TEST_CASE("hardcopy: the PNG workstation writes its picture on update and on close", "[render][views]") {
    vk::Context context(lavapipeWithValidation());
    const auto file = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hardcopy" / "picture.png";
    std::filesystem::remove(file);
    {
        vk::HardcopyTarget hardcopy(context, 128, 96, file);
        DrawList list = emptyScene();
        list.background = {0.0f, 0.5f, 0.0f};
        hardcopy.update(list);
        REQUIRE(std::filesystem::exists(file));
        const Image first = readPng(file);
        CHECK(first.width == 128);
        CHECK(first.height == 96);
        CHECK(near(at(first, 5, 5), 0, 128, 0, 1));
        std::filesystem::remove(file);
        hardcopy.close();
        REQUIRE(std::filesystem::exists(file));
        CHECK_THROWS_WITH(hardcopy.update(list), Catch::Contains("closed"));
    }
    requireNoValidationMessages(context);
}

TEST_CASE("renderer: a draw item naming a missing view or light set is refused with its index",
          "[render][views]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 64, 64);
        DrawList list = emptyScene();
        DrawPolyline l;
        l.points = {{0, 0, 0}, {1, 1, 0}};
        list.items.push_back(item(l));
        list.items.push_back(item(l, 3));
        CHECK_THROWS_WITH(ws.draw(list), Catch::Contains("draw item 1") && Catch::Contains("view 3"));
        list.items.back().context.edit().viewIndex = 0;
        list.items.back().context.edit().lightSet = 2;
        CHECK_THROWS_WITH(ws.draw(list), Catch::Contains("draw item 1") && Catch::Contains("light set 2"));
        list.items.back().context.edit().lightSet = -1;
        CHECK_NOTHROW(ws.draw(list));
    }
    requireNoValidationMessages(context);
}

}  // namespace test_views
