// Pick acceleration (PickBoundsTree): on random scenes of every primitive kind, random picks by
// the Picker with its tree give exactly the hits of the Picker testing every item, before and
// after random edits of the list; and a workstation's pick device re-traverses only on change.
#include "phigs/Phigs.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/pick/Picker.h"

#include "PickScenes.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <limits>
#include <random>

namespace test_pick_tree {

using namespace phigs;
using namespace phigs::test;

namespace {

std::vector<double> clampedKnots(std::size_t count) {
    std::vector<double> k(4, 0.0);
    for (std::size_t i = 1; i + 3 < count; ++i) k.push_back(double(i) / double(count - 3));
    k.insert(k.end(), 4, 1.0);
    return k;
}

/// A bicubic patch of n x n control points near `centre`, bumpy, sometimes rational.
std::shared_ptr<const geom::Surface> randomSurface(std::mt19937& rng, glm::dvec3 centre) {
    std::uniform_real_distribution<double> bump(-0.05, 0.05), size(0.05, 0.3), weight(0.5, 2.0);
    const std::size_t n = 4 + rng() % 3;
    const double s = size(rng);
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    const bool rational = rng() % 4 == 0;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            points.push_back(centre + glm::dvec3(s * (double(i) / double(n - 1) - 0.5) + bump(rng),
                                                 s * (double(j) / double(n - 1) - 0.5) + bump(rng),
                                                 2 * bump(rng)));
            if (rational) weights.push_back(weight(rng));
        }
    return std::make_shared<const geom::Surface>(3, 3, clampedKnots(n), clampedKnots(n), n, n, points,
                                                 weights);
}

/// A coarse tessellation of the surface (what traversal attaches), for the silhouette pass.
std::shared_ptr<const MeshData> meshOf(const geom::Surface& s) {
    auto mesh = std::make_shared<MeshData>();
    const int n = 6;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            // Bilinear through the corner control points: close to the surface, not on it.
            const double u = double(i) / n, v = double(j) / n;
            const glm::dvec3 p = (1 - u) * (1 - v) * s.point(0, 0) + u * (1 - v) * s.point(s.countU - 1, 0) +
                                 (1 - u) * v * s.point(0, s.countV - 1) +
                                 u * v * s.point(s.countU - 1, s.countV - 1);
            mesh->positions.emplace_back(p);
        }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const std::uint32_t a = std::uint32_t(i * (n + 1) + j), b = a + 1, c = a + std::uint32_t(n + 1),
                                d = c + 1;
            mesh->triangles.insert(mesh->triangles.end(), {a, c, b, b, c, d});
        }
    return mesh;
}

DrawItem randomItem(std::mt19937& rng, int index) {
    std::uniform_real_distribution<double> at(0.1, 0.9), depth(0.1, 0.9), small(-0.08, 0.08);
    const glm::dvec3 c(at(rng), at(rng), depth(rng));
    DrawPrimitive primitive;
    switch (rng() % 8) {
        case 0: {
            DrawPolyline line;
            std::vector<glm::dvec3> points;
            for (int k = 0; k < 4; ++k) points.push_back(c + glm::dvec3(small(rng), small(rng), small(rng)));
            line.points = points;
            if (rng() % 2)  // with vertex colours: a kind of its own, held out of line
                primitive = DrawColouredPolyline{line, {std::vector<glm::vec3>(4, glm::vec3(1, 0, 0)), true}};
            else
                primitive = line;
            break;
        }
        case 1: {
            DrawPolymarker markers;
            markers.points = {c, c + glm::dvec3(small(rng), small(rng), 0.0)};
            primitive = markers;
            break;
        }
        case 2:
            primitive = square(c.x - 0.05, c.x + 0.05, c.z);
            break;
        default: {
            DrawMesh mesh;
            mesh.interior.edit().style = InteriorStyle::Solid;
            mesh.surface = randomSurface(rng, c);
            if (rng() % 2) mesh.mesh = meshOf(*mesh.surface);
            primitive = mesh;
        }
    }
    DrawItem item = test::item(std::move(primitive), {{1, index + 1, index}});
    item.context.edit().pickable = rng() % 10 != 0;
    if (rng() % 3 == 0)  // a small rotation about the scene centre and a shift
        item.context.edit().modelTransform =
            glm::translate(glm::dmat4(1.0),
                           glm::dvec3(0.5, 0.5, 0.5) + 0.05 * glm::dvec3(small(rng), small(rng), 0)) *
            glm::rotate(glm::dmat4(1.0), small(rng), glm::dvec3(0, 0, 1)) *
            glm::translate(glm::dmat4(1.0), glm::dvec3(-0.5, -0.5, -0.5));
    item.context.edit().viewIndex = int(rng() % 2);
    return item;
}

/// Two views: 0 the identity, 1 a slight tilt with clip limits on the left three quarters.
DrawList randomScene(std::mt19937& rng, int items) {
    DrawList list = unitList();
    DrawView tilted;
    tilted.orientation = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) *
                         glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(1, 1, 0)) *
                         glm::translate(glm::dmat4(1.0), glm::dvec3(-0.5));
    tilted.clipMax = {0.75, 1.0, 1.0};
    list.views.push_back(tilted);
    for (int i = 0; i < items; ++i) list.items.push_back(randomItem(rng, i));
    return list;
}

void requireSameHits(const DrawList& list, const Picker& fast, const Picker& every, std::mt19937& rng,
                     int picks) {
    std::uniform_real_distribution<double> at(0.0, 1.0);
    for (int i = 0; i < picks; ++i) {
        const glm::dvec2 npc(at(rng), at(rng));
        const double aperture = (rng() % 2) ? 0.001 : 0.02;
        const auto a = fast.nearest(list, npc, aperture), b = every.nearest(list, npc, aperture);
        INFO("pick " << i << " at " << npc.x << ", " << npc.y << " aperture " << aperture);
        REQUIRE(a.has_value() == b.has_value());
        if (a) {
            REQUIRE(a->item == b->item);
            REQUIRE(a->depth == b->depth);
            REQUIRE(a->surface.has_value() == b->surface.has_value());
            if (a->surface) REQUIRE(a->surface->point == b->surface->point);
        }
        const auto all = fast.hits(list, npc, aperture), reference = every.hits(list, npc, aperture);
        REQUIRE(all.size() == reference.size());
        for (std::size_t k = 0; k < all.size(); ++k) {
            REQUIRE(all[k].item == reference[k].item);
            REQUIRE(all[k].depth == reference[k].depth);
        }
    }
}

}  // namespace

TEST_CASE("pick tree: random picks hit what testing every item hits", "[pick][tree]") {
    std::mt19937 rng(20);
    for (int scene = 0; scene < 6; ++scene) {
        DrawList list = randomScene(rng, 60 + scene * 40);
        list.generation = 1;
        const Picker fast;
        Picker every;
        every.setAccelerated(false);
        requireSameHits(list, fast, every, rng, 150);
        REQUIRE(fast.boundsTree().stats().rebuilds == 1);
        // A few items move or change (a new generation): refitted, not rebuilt, and still exact.
        for (int k = 0; k < 3; ++k) {
            DrawItem& item = list.items[rng() % list.items.size()];
            item.context.edit().modelTransform =
                glm::translate(glm::dmat4(1.0), glm::dvec3(0.05 * k, -0.03, 0.02)) *
                item.modelTransform().get();
        }
        list.items[rng() % list.items.size()] = randomItem(rng, 999);
        list.generation = 2;
        requireSameHits(list, fast, every, rng, 100);
        // Items added and the view moved: rebuilt.
        for (int k = 0; k < 10; ++k) list.items.push_back(randomItem(rng, 1000 + k));
        list.views[1].orientation =
            glm::rotate(glm::dmat4(1.0), 0.05, glm::dvec3(0, 1, 0)) * list.views[1].orientation;
        list.generation = 3;
        requireSameHits(list, fast, every, rng, 100);
        CHECK(fast.boundsTree().stats().updates == 3);
    }
}

TEST_CASE("pick tree: a perspective view and items behind the eye stay exact", "[pick][tree]") {
    std::mt19937 rng(21);
    DrawList list = randomScene(rng, 120);
    // View 1 in perspective, its eye inside the scene: some boxes reach behind it.
    list.views[1].mapping = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5)) *
                            glm::perspective(1.2, 1.0, 0.05, 2.0) *
                            glm::translate(glm::dmat4(1.0), glm::dvec3(-0.5, -0.5, -0.6));
    list.views[1].clipXY = list.views[1].clipBack = list.views[1].clipFront = false;
    const Picker fast;
    Picker every;
    every.setAccelerated(false);
    requireSameHits(list, fast, every, rng, 300);  // generation 0: checked item by item each pick
}

TEST_CASE("pick tree: an unchanged list costs no update, an item edited in place with generation 0 is seen",
          "[pick][tree]") {
    std::mt19937 rng(22);
    DrawList list = randomScene(rng, 40);
    list.generation = 7;
    const Picker picker;
    picker.nearest(list, {0.5, 0.5}, 0.01);
    picker.nearest(list, {0.4, 0.5}, 0.01);
    CHECK(picker.boundsTree().stats().updates == 1);
    // Generation 0 is unversioned: a surface swapped in place is found at the next pick.
    list.generation = 0;
    list.items = {item(square(0.0, 0.2, 0.5), {{1, 1, 1}})};
    picker.nearest(list, {0.5, 0.5}, 0.01);
    list.items[0] = item(square(0.4, 0.6, 0.5), {{1, 1, 2}});
    const auto hit = picker.nearest(list, {0.5, 0.5}, 0.001);
    REQUIRE(hit);
    CHECK(list.items[hit->item].source.path().back().pickId == 2);
}

TEST_CASE("pick tree: a workstation's pick device traverses again only when something changed",
          "[pick][tree][wiring]") {
    Phigs phigs;
    phigs.open();
    auto& store = phigs.store();
    store.openStructure(1);
    store.insert(IndexAttribute{ElementType::InteriorStyle, 1});
    store.insert(addNamesToSet({1}));
    store.insert(pickId(3));
    store.insert(fillArea3({{0.1, 0.1, 0}, {0.5, 0.1, 0}, {0.5, 0.5, 0}, {0.1, 0.5, 0}}));
    store.closeStructure();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
    ws.postStructure(1, 0.5);
    ws.input().setPickFilter(1, {1}, {});
    // NPC (0.25, 0.25) and (0.75, 0.75) on the 1024 x 768 display (768 pixels per NPC unit).
    ScriptInputSource script("pick 192 576\npick 192 576\npick 576 192\npick 576 192\n", "picks");
    InputQueue queue;
    ws.connectInput(script, queue);
    auto pick = [&] { return std::get<PickMeasure>(ws.input().request(InputClass::Pick, 1).second); };
    CHECK(pick().status == InputStatus::Ok);
    CHECK(pick().status == InputStatus::Ok);
    CHECK(ws.pickTraversals() == 1);
    // An edit of a posted structure: the next pick sees it, through one new traversal.
    store.openStructure(1);
    store.insert(pickId(4));
    store.insert(fillArea3({{0.6, 0.6, 0}, {0.9, 0.6, 0}, {0.9, 0.9, 0}, {0.6, 0.9, 0}}));
    store.closeStructure();
    const PickMeasure m = pick();
    REQUIRE(m.status == InputStatus::Ok);
    CHECK(m.path.back().pickId == 4);
    CHECK(pick().status == InputStatus::Ok);
    CHECK(ws.pickTraversals() == 2);
}

TEST_CASE("pick tree: two workstations' pictures copied over one list are never taken for each other",
          "[pick][tree][wiring]") {
    // A list assigned another workstation's picture keeps its storage and count; the two pictures
    // must still differ in generation, or the tree kept per list would answer from stale boxes.
    std::mt19937 rng(20261205);
    std::uniform_real_distribution<double> corner(0.05, 0.7);
    for (int round = 0; round < 20; ++round) {
        Phigs phigs;
        phigs.open();
        auto& store = phigs.store();
        std::vector<glm::dvec2> centres;
        for (int id = 1; id <= 2; ++id) {
            const double x = corner(rng), y = corner(rng);
            centres.push_back({x + 0.1, y + 0.1});
            store.openStructure(id);
            store.insert(IndexAttribute{ElementType::InteriorStyle, 1});
            store.insert(fillArea3({{x, y, 0}, {x + 0.2, y, 0}, {x + 0.2, y + 0.2, 0}, {x, y + 0.2, 0}}));
            store.closeStructure();
            Workstation& ws = phigs.openWorkstation(id, WorkstationType::Window);
            ws.postStructure(id, 0.5);
        }
        const Picker picker;
        Picker every;
        every.setAccelerated(false);
        DrawList x;
        for (int k = 0; k < 4; ++k) {
            const int id = 1 + k % 2;
            x = phigs.workstation(id).display();
            const glm::dvec2 at = centres[std::size_t(id - 1)];
            CHECK(picker.hits(x, at, 0.001).size() == every.hits(x, at, 0.001).size());
            CHECK(picker.nearest(x, at, 0.001).has_value());
        }
    }
}

TEST_CASE("pick tree: a deferred view change is picked as shown, before and after it is shown",
          "[pick][tree][wiring]") {
    // While a change waits (ASTI or WAIT, NIVE), pick sees the picture on the display; once UPDATE
    // WORKSTATION, REDRAW or the switch to ASAP shows it, pick sees the new picture.
    std::mt19937 rng(5122026);
    std::uniform_real_distribution<double> corner(0.05, 0.35), shift(0.3, 0.5);
    for (int round = 0; round < 30; ++round) {
        Phigs phigs;
        phigs.open();
        auto& store = phigs.store();
        const double a = corner(rng), b = a + 0.2;
        store.openStructure(1);
        store.insert(viewIndex(1));
        store.insert(IndexAttribute{ElementType::InteriorStyle, 1});
        store.insert(addNamesToSet({1}));
        store.insert(pickId(5));
        store.insert(fillArea3({{a, a, 0}, {b, a, 0}, {b, b, 0}, {a, b, 0}}));
        store.closeStructure();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
        ws.setViewRepresentation(1, ViewRepresentation{});
        ws.postStructure(1, 0.5);
        ws.setDeferralState(rng() % 2 == 0 ? DeferralMode::Asti : DeferralMode::Wait, ModificationMode::Nive);
        ws.display();
        ws.input().setPickFilter(1, {1}, {});
        const glm::dvec2 t(shift(rng), shift(rng));
        // The centres of the square before and after the move, as pixels of the 1024 x 768 display
        // (768 per NPC unit, y down).
        auto pixel = [](glm::dvec2 npc) {
            return std::to_string(npc.x * 768.0) + " " + std::to_string(768.0 - npc.y * 768.0);
        };
        const std::string before = "pick " + pixel(glm::dvec2(a + 0.1)) + "\n";
        const std::string after = "pick " + pixel(glm::dvec2(a + 0.1) + t) + "\n";
        ScriptInputSource script(before + before + after + before + after, "picks");
        InputQueue queue;
        ws.connectInput(script, queue);
        auto picked = [&] { return ws.input().request(InputClass::Pick, 1).first == InputStatus::Ok; };
        const int show = static_cast<int>(rng() % 3);
        INFO("round " << round << ": corner " << a << ", move " << t.x << " " << t.y << ", shown by "
                      << show);
        CHECK(picked());
        ViewRepresentation moved;
        moved.orientation = glm::translate(glm::dmat4(1.0), glm::dvec3(t, 0.0));
        ws.setViewRepresentation(1, moved);
        CHECK(picked());  // the old picture is still shown
        CHECK_FALSE(picked());
        if (show == 0) ws.update(Regeneration::Perform);
        if (show == 1) ws.redrawAllStructures();
        if (show == 2) ws.setDeferralState(DeferralMode::Asap, ModificationMode::Nive);
        ws.display();
        CHECK_FALSE(picked());
        CHECK(picked());
    }
}

TEST_CASE(
    "pick: surfaces under flattening transforms are hit by their tessellation, tree and every item alike",
    "[pick][tree][bad-input]") {
    std::mt19937 rng(23);
    for (double flat : {0.0, 1e-300, 1e-200}) {
        DrawList list = randomScene(rng, 80);
        list.generation = 1;
        // A third of the items flattened along a random axis about the scene centre.
        for (DrawItem& item : list.items)
            if (rng() % 3 == 0) {
                glm::dvec3 scale(1.0);
                scale[int(rng() % 3)] = flat;
                item.context.edit().modelTransform =
                    glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) * glm::scale(glm::dmat4(1.0), scale) *
                    glm::translate(glm::dmat4(1.0), glm::dvec3(-0.5)) * item.modelTransform().get();
            }
        const Picker fast;
        Picker every;
        every.setAccelerated(false);
        INFO("flattened by " << flat);
        requireSameHits(list, fast, every, rng, 200);
    }
    // A surface flattened onto the plane z = 0.9 (seen face on, in front) over one left as it is
    // (near z = 0.5): the front one is hit, by its tessellation under the aperture, without
    // (u, v), as the picture shows it; the one behind does not win by its exact hit.
    std::mt19937 one(24);
    DrawList list = unitList();
    for (int k = 0; k < 2; ++k) {
        DrawMesh mesh;
        mesh.interior.edit().style = InteriorStyle::Solid;
        mesh.surface = randomSurface(one, {0.5, 0.5, 0.5});
        mesh.mesh = meshOf(*mesh.surface);
        list.items.push_back(test::item(mesh, {{1, k + 1, k}}));
    }
    for (double flat : {0.0, 1e-100, 1e-300}) {
        list.items[0].context.edit().modelTransform =
            glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 0.9)) *
            glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 1.0, flat)) *
            glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -0.9));
        for (bool accelerated : {true, false}) {
            INFO("flattened by " << flat << (accelerated ? ", tree" : ", every item"));
            Picker picker;
            picker.setAccelerated(accelerated);
            const auto hit = picker.nearest(list, {0.5, 0.5}, 0.01);
            REQUIRE(hit);
            CHECK(hit->item == 0);
            CHECK_FALSE(hit->surface);
            CHECK(hit->depth == Approx(0.9).margin(1e-6));
        }
    }
    for (bool accelerated : {true, false}) {
        Picker picker;
        picker.setAccelerated(accelerated);
        // A position or aperture that is NaN or infinite hits nothing, and throws nothing.
        const double nan = std::numeric_limits<double>::quiet_NaN();
        CHECK_FALSE(picker.nearest(list, {nan, 0.5}, 0.01));
        CHECK_FALSE(picker.nearest(list, {0.5, std::numeric_limits<double>::infinity()}, 0.01));
        CHECK_FALSE(picker.nearest(list, {0.5, 0.5}, nan));
        CHECK(picker.hits(list, {0.5, 0.5}, nan).empty());
    }
}

}  // namespace test_pick_tree
