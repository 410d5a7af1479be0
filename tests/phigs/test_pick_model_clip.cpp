// The pick honours the model clipping volume (DrawItem::modelClipPlanes) as the renderer does:
// what is clipped away is neither hit nor hides what lies behind it.
#include "PickScenes.h"

#include "phigs/pick/Picker.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <random>

namespace test_pick_model_clip {

using namespace phigs;
using phigs::test::cylinder;
using phigs::test::item;
using phigs::test::square;
using phigs::test::surfaceItem;
using phigs::test::unitList;

TEST_CASE("pick model clip: a clipped-away part of a fill area is not hit and hides nothing", "[pick]") {
    DrawList list = unitList();
    list.items.push_back(item(square(0.1, 0.9, 0.2), {{1, 1, 1}}));  // behind, unclipped
    DrawItem front = item(square(0.2, 0.8, 0.6), {{2, 1, 2}});
    front.context.edit().modelClipPlanes = {{1, 0, 0, -0.5}};  // keep x >= 0.5
    list.items.push_back(front);
    const Picker picker;
    const auto kept = picker.nearest(list, {0.7, 0.5}, 0.001);
    REQUIRE(kept);
    CHECK(kept->item == 1);
    const auto through = picker.nearest(list, {0.3, 0.5}, 0.001);
    REQUIRE(through);
    CHECK(through->item == 0);  // the front square is clipped here: the one behind is picked
    // A second half space intersects: keep x >= 0.5 and y <= 0.4.
    {
        std::vector<glm::dvec4> planes = list.items[1].modelClipPlanes();
        planes.push_back({0, -1, 0, 0.4});
        list.items[1].context.edit().modelClipPlanes = planes;
    }
    CHECK(picker.nearest(list, {0.7, 0.5}, 0.001)->item == 0);
    CHECK(picker.nearest(list, {0.7, 0.3}, 0.001)->item == 1);
}

TEST_CASE("pick model clip: markers are clipped by their positions", "[pick]") {
    DrawList list = unitList();
    DrawPolymarker m;
    m.points = {{0.3, 0.3, 0.5}, {0.7, 0.7, 0.5}};
    DrawItem markers = item(m, {{3, 1, 0}});
    markers.context.edit().modelClipPlanes = {{1, 1, 0, -1.0}};  // keep x + y >= 1
    list.items.push_back(markers);
    const Picker picker;
    CHECK_FALSE(picker.nearest(list, {0.3, 0.3}, 0.001));
    CHECK(picker.nearest(list, {0.7, 0.7}, 0.001));
}

namespace {

/// Clips `list` to the NPC square [lo, hi]^2: by view 0's x/y limits, or by the workstation window.
void clipToSquare(DrawList& list, bool byWindow, double lo, double hi) {
    glm::dvec3& min = byWindow ? list.windowMin : list.views[0].clipMin;
    glm::dvec3& max = byWindow ? list.windowMax : list.views[0].clipMax;
    min = {lo, lo, 0.0};
    max = {hi, hi, 1.0};
}

}  // namespace

TEST_CASE("pick: a marker outside the view's clip limits or the window is not hit", "[pick]") {
    // Drawn, such a marker shows nothing (clipped by its position); a pick inside the clip
    // rectangle within its glyph's reach must not find it either.
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Picker picker;
    for (int trial = 0; trial < 200; ++trial) {
        DrawList list = unitList();
        const double lo = 0.2 + 0.1 * unit(random), hi = 0.7 + 0.1 * unit(random);
        clipToSquare(list, trial % 2 == 1, lo, hi);
        // 0.001 to 0.009 outside the left edge; the pick 0.001 inside it, within the marker's reach.
        const double y = 0.4 + 0.2 * unit(random);
        const double off = 0.001 + 0.008 * unit(random);
        const auto marker = [&](double x) {
            DrawPolymarker m;
            m.points = {{x, y, 0.5}};
            m.style.edit().scale = 4.0f;
            return item(m, {{1, 1, 0}});
        };
        list.items.push_back(marker(lo - off));
        CHECK_FALSE(picker.nearest(list, {lo + 0.001, y}, 0.001));
        // Just inside instead, it is hit there.
        list.items[0] = marker(lo + off);
        CHECK(picker.nearest(list, {lo + 0.001, y}, 0.001));
    }
}

TEST_CASE("pick: annotation text whose reference point is clipped is not hit", "[pick]") {
    // ISO 9592: a clipped reference point displays nothing, though the text's offset brings it
    // inside; with the reference point kept, the same text is hit. Each clip in turn: the view's
    // x/y limits, the workstation window, the view's back plane, the model clipping volume.
    std::mt19937 random(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Picker picker;
    for (int trial = 0; trial < 200; ++trial) {
        DrawList list = unitList();
        const int clip = trial % 4;
        const double lo = 0.2 + 0.1 * unit(random), hi = 0.7 + 0.1 * unit(random);
        if (clip <= 1) {
            clipToSquare(list, clip == 1, lo, hi);
        } else if (clip == 2) {
            list.views[0].clipMin = {0.0, 0.0, 0.4};
            list.views[0].clipBack = true;
        }
        const double y = 0.4 + 0.2 * unit(random), off = 0.001 + 0.05 * unit(random);
        // The reference point just left of lo (for the depth clip: behind z 0.4), or kept just
        // right of it; the text 0.1 to its right, inside every clip.
        const auto note = [&](bool kept) {
            DrawText t;
            t.text = "NOTE";
            t.annotation = true;
            t.position = {kept ? lo + off : lo - off, y, 0.5};
            if (clip == 2) t.position = {lo - off, y, kept ? 0.5 : 0.3};
            t.annotationOffset = {0.1, 0.0, 0.0};
            t.style.edit().height = 0.04;
            DrawItem i = item(t, {{1, 1, 0}});
            if (clip == 3) i.context.edit().modelClipPlanes = {{1, 0, 0, -lo}};  // keep x >= lo
            return i;
        };
        INFO("trial " << trial << ", clip " << clip);
        const glm::dvec2 inText(lo + 0.18, y + 0.02);  // inside the text's box either way
        list.items.push_back(note(false));
        CHECK_FALSE(picker.nearest(list, inText, 0.001));
        list.items[0] = note(true);
        CHECK(picker.nearest(list, inText, 0.001));
    }
}

TEST_CASE("pick model clip: an exact surface pick goes on to the first kept intersection", "[pick]") {
    DrawList list = unitList();
    const double r = 0.3;
    DrawItem i = surfaceItem(cylinder(r), {{1, 2, 3}});
    i.context.edit().modelTransform = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5));
    const Picker picker;
    list.items.push_back(i);
    const auto near = picker.nearest(list, {0.6, 0.4}, 0.001);
    REQUIRE(near);
    REQUIRE(near->surface);
    CHECK(near->surface->point.z > 0);  // the near side
    // Keep world z <= 0.5: the near half of the cylinder is gone, the far side is picked.
    list.items[0].context.edit().modelClipPlanes = {{0, 0, -1, 0.5}};
    const auto far = picker.nearest(list, {0.6, 0.4}, 0.001);
    REQUIRE(far);
    REQUIRE(far->surface);
    CHECK(far->surface->point.z == Approx(-std::sqrt(r * r - 0.01)).margin(1e-9));
    CHECK(far->depth == Approx(0.5 + far->surface->point.z).margin(1e-9));
    // Keep world x <= 0.4: the pick at x = 0.6 misses the cylinder altogether.
    list.items[0].context.edit().modelClipPlanes = {{-1, 0, 0, 0.4}};
    CHECK_FALSE(picker.nearest(list, {0.6, 0.4}, 0.001));
}

}  // namespace test_pick_model_clip
