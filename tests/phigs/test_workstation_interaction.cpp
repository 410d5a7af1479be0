// WorkstationInteraction: the logical input devices of a model workstation, measured on its
// picture (no GPU: the pixels are the workstation's device coordinates unless told otherwise).
#include "phigs/Phigs.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/pick/WorkstationInteraction.h"

#include "InputFakes.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

using namespace phigs;

namespace {

/// Workstation 1 (display 1024 x 768, viewport the whole display, window the unit square: 768
/// pixels per NPC unit) with view 1 on the left half of NPC showing world scaled by 1/2, and
/// structure 1 holding a square in view 1 (pick id 3) and one in view 0 (pick id 4).
struct Rig {
    Phigs phigs;
    Workstation* ws = nullptr;
    Rig() {
        phigs.open();
        auto& store = phigs.store();
        store.openStructure(1);
        store.insert(IndexAttribute{ElementType::InteriorStyle, 1});
        store.insert(viewIndex(1));
        store.insert(pickId(3));
        store.insert(fillArea3({{0.1, 0.1, 0}, {0.5, 0.1, 0}, {0.5, 0.5, 0}, {0.1, 0.5, 0}}));
        store.insert(viewIndex(0));
        store.insert(pickId(4));
        store.insert(fillArea3({{0.7, 0.1, 0}, {0.9, 0.1, 0}, {0.9, 0.3, 0}, {0.7, 0.3, 0}}));
        store.closeStructure();
        ws = &phigs.openWorkstation(1, WorkstationType::Window);
        ViewRepresentation left;
        left.mapping = glm::scale(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 1.0));
        left.clipMax = {0.5, 1.0, 1.0};
        ws->setViewRepresentation(1, left);
        ws->postStructure(1, 0.5);
    }
};

}  // namespace

TEST_CASE("workstation interaction: the locator honours the view table's input priority", "[input][wiring]") {
    Rig rig;
    // NPC (0.2, 0.25) is pixel (153.6, 768 - 192) = (153.6, 576) from the top left.
    ScriptInputSource script("locator 153.6 576\nlocator 153.6 576\nlocator 691.2 576\n", "loc.txt");
    InputQueue queue;
    WorkstationInteraction interaction(*rig.ws, script, queue);
    auto locate = [&] {
        auto [status, measure] = interaction.input().request(InputClass::Locator, 1);
        REQUIRE(status == InputStatus::Ok);
        return std::get<LocatorMeasure>(measure);
    };
    // View 0 comes first initially and holds every point.
    LocatorMeasure a = locate();
    CHECK(a.viewIndex == 0);
    CHECK(a.position.x == Approx(0.2));
    CHECK(a.position.y == Approx(0.25));
    // SET VIEW TRANSFORMATION INPUT PRIORITY on the workstation reaches the measurer.
    rig.ws->setViewTransformationInputPriority(1, 0, true);
    a = locate();
    CHECK(a.viewIndex == 1);
    CHECK(a.position.x == Approx(0.4));
    CHECK(a.position.y == Approx(0.5));
    a = locate();  // NPC x 0.9 is outside view 1's clip limits
    CHECK(a.viewIndex == 0);
    CHECK(a.position.x == Approx(0.9));
}

TEST_CASE("workstation interaction: picks see the current structures and the surface size",
          "[input][wiring]") {
    Rig rig;
    // Square 1 is drawn at NPC (0.05 .. 0.25); square 2 at NPC (0.7 .. 0.9) x (0.1 .. 0.3).
    ScriptInputSource script("pick 115.2 652.8\npick 614.4 614.4\npick 115.2 652.8\npick 300 400\n",
                             "pick.txt");
    InputQueue queue;
    WorkstationInteraction interaction(*rig.ws, script, queue);
    auto pick = [&] {
        auto [status, measure] = interaction.input().request(InputClass::Pick, 1);
        return status == InputStatus::Ok ? std::get<PickMeasure>(measure).path : std::vector<PickPathItem>{};
    };
    CHECK(pick() == std::vector<PickPathItem>{{1, 4, 3}});
    CHECK(pick() == std::vector<PickPathItem>{{1, 7, 4}});
    // Delete the first square: the next pick at its place finds nothing.
    auto& store = rig.phigs.store();
    store.openStructure(1);
    store.setElementPointer(4);
    store.deleteElement();
    store.closeStructure();
    CHECK(pick().empty());
    // On a surface of half the size (512 x 384 pixels, half a pixel per device unit), pixel
    // (300, 400) lies below the bottom edge; pixel (200, 300) is device (400, 168).
    interaction.setSurfaceSize(512, 384);
    CHECK(pick().empty());
    CHECK(interaction.measurer().toNpc({200, 300}).x == Approx(400.0 / 768.0));
    CHECK(interaction.measurer().toNpc({200, 300}).y == Approx(168.0 / 768.0));
    // A surface that changes (a resized window) is asked at each measure.
    std::uint32_t width = 1024, height = 768;
    interaction.followSurface([&] { return std::pair{width, height}; });
    CHECK(interaction.measurer().toNpc({400, 368}).y == Approx(400.0 / 768.0));
    width = 2048, height = 1536;
    CHECK(interaction.measurer().toNpc({400, 368}).y == Approx((1536.0 - 368.0) / 2.0 / 768.0));
}

TEST_CASE("workstation output seam: the picture with the echo, input through the drawable's size",
          "[ws][wiring]") {
    /// An output in memory: keeps the last picture, reports the drawable it is told.
    struct MemoryOutput : WorkstationOutput {
        DrawList last;
        int presents = 0;
        DrawableSize size{512, 384};
        bool present(const DrawList& picture) override {
            last = picture;
            ++presents;
            return true;
        }
        DrawableSize drawableSize() const override { return size; }
    };
    Rig rig;
    Workstation& ws = *rig.ws;
    CHECK_FALSE(ws.present());  // nothing attached
    CHECK(ws.drawableSize() == DrawableSize{1024, 768});
    MemoryOutput out;
    ws.attachOutput(&out);
    REQUIRE(ws.present());
    REQUIRE(out.last.items.size() == 2);
    CHECK_FALSE(out.last.items[1].highlighted);
    ws.setEcho({out.last.items[1].source.path});
    REQUIRE(ws.present());
    CHECK(out.presents == 2);
    CHECK_FALSE(out.last.items[0].highlighted);
    CHECK(out.last.items[1].highlighted);
    CHECK_FALSE(ws.display().items[1].highlighted);  // the workstation's own picture is untouched
    // Input maps through the output's drawable: 512 x 384 pixels, half a pixel per device unit.
    test::IdleSource source;
    InputQueue queue;
    WorkstationInteraction interaction(ws, source, queue);
    CHECK(interaction.measurer().toNpc({200, 300}).x == Approx(400.0 / 768.0));
    out.size = {2048, 1536};  // resized: asked at each measure
    CHECK(interaction.measurer().toNpc({400, 368}).y == Approx((1536.0 - 368.0) / 2.0 / 768.0));
    out.size = {0, 0};  // minimised: one pixel per device unit meanwhile
    CHECK(interaction.measurer().toNpc({400, 368}).y == Approx(400.0 / 768.0));
    ws.attachOutput(nullptr);
    CHECK_FALSE(ws.present());
}
