// Pick latency where users pick: the ACSYNT transport as the design program stores it
// (ModelPicture: one structure and one NURBS surface item per patch, the boundary lines not
// pickable), three copies side by side (1,128 patches) and twenty-seven in a 3 x 3 x 3 block
// (10,152), in the session's oblique view with its pick filter and aperture. Random picks over
// the model's picture, by a Picker with its bounds tree and by one testing every item (the
// brute force it must agree with, hit for hit). Then the pick step of a session
// (the workstation's pick device, script input) on the unchanged picture, against the traversal each
// step made before. Second table: ten synthetic tubes (1,000 Bézier pieces in 10 items) against
// geom::intersectLine on every piece. Per-pick figures are thread CPU time (wall time beside).
// Prints the figures and ends with one JSON object.

#include "acsynt/Model.h"
#include "acsynt/session/ModelPicture.h"
#include "geom/BezierExtraction.h"
#include "geom/Intersect.h"
#include "geom/Tessellate.h"
#include "phigs/Phigs.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/pick/Picker.h"
#include "phigs/view/ViewMatrices.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

double seconds(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Thread CPU and wall time of one call, in microseconds.
struct Timed {
    double cpu = 0, wall = 0;
};
template <typename F>
Timed timed(F&& f) {
    const double c0 = seconds(CLOCK_THREAD_CPUTIME_ID), w0 = seconds(CLOCK_MONOTONIC);
    f();
    return {1e6 * (seconds(CLOCK_THREAD_CPUTIME_ID) - c0), 1e6 * (seconds(CLOCK_MONOTONIC) - w0)};
}

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

std::vector<double> uniformKnots(std::size_t n) {
    std::vector<double> k(4, 0.0);
    const std::size_t spans = n - 3;
    for (std::size_t i = 1; i < spans; ++i) k.push_back(static_cast<double>(i) / static_cast<double>(spans));
    k.insert(k.end(), 4, 1.0);
    return k;
}

/// A bumpy tube along x: 13 x 13 control points, 10 x 10 bicubic pieces.
std::shared_ptr<const geom::Surface> tube(double radius, double length, double phase) {
    const std::size_t n = 13;
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = length * static_cast<double>(i) / static_cast<double>(n - 1);
        for (std::size_t j = 0; j < n; ++j) {
            const double a = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(n - 1);
            const double r = radius * (1.0 + 0.15 * std::sin(3.0 * a + phase + static_cast<double>(i)));
            points.emplace_back(x, r * std::cos(a), r * std::sin(a));
        }
    }
    return std::make_shared<const geom::Surface>(3, 3, uniformKnots(n), uniformKnots(n), n, n, points);
}

struct BruteHit {
    std::size_t item = 0;
    double depth = 0.0;
    glm::dvec3 point{0.0};
};

/// Every Bézier patch of every item, intersected with no tree and no cache.
std::optional<BruteHit> bruteForce(const phigs::DrawList& list,
                                   const std::vector<std::vector<geom::BezierSurfacePiece>>& pieces,
                                   glm::dvec2 npc) {
    std::optional<BruteHit> best;
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const auto& item = list.items[i];
        const auto& view = list.views[static_cast<std::size_t>(item.viewIndex())];
        const glm::dmat4 m = view.mapping * view.orientation * item.modelTransform().get();
        const glm::dmat4 inv = glm::inverse(m);
        const glm::dvec4 f = inv * glm::dvec4(npc, 1.0, 1.0), b = inv * glm::dvec4(npc, 0.0, 1.0);
        const glm::dvec3 origin = glm::dvec3(f) / f.w;
        const glm::dvec3 direction = glm::dvec3(b) / b.w - origin;
        for (const auto& piece : pieces[i]) {
            for (const auto& h : geom::intersectLine(piece.surface, origin, direction)) {
                const glm::dvec4 p = m * glm::dvec4(h.point, 1.0);
                const double z = p.z / p.w;
                if (z < 0.0 || z > 1.0) continue;
                if (!best || z > best->depth) best = BruteHit{i, z, h.point};
            }
        }
    }
    return best;
}

/// `count` copies of the model's components, in a row along y (3) or a 3 x 3 x 3 block (27),
/// each moved by whole model sizes (affine invariance: the control points move).
acsynt::Model copies(const acsynt::Model& base, int count) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto& c : base.components)
        for (const glm::dvec3& p : c.surface.points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    const glm::dvec3 size = hi - lo;
    acsynt::Model model;
    model.name = base.name + " x" + std::to_string(count);
    for (int k = 0; k < count; ++k) {
        const glm::dvec3 offset(1.2 * size.x * ((k / 3) % 3), 1.1 * size.y * (k % 3), 1.5 * size.z * (k / 9));
        for (acsynt::Component c : base.components) {
            for (glm::dvec3& p : c.surface.points) p += offset;
            c.name += "#" + std::to_string(k + 1);
            c.updatePatches();
            model.components.push_back(std::move(c));
        }
    }
    return model;
}

/// The session's single oblique view (azimuth -135, elevation 25 degrees, parallel) on the model.
phigs::ViewRepresentation sessionView(const acsynt::Model& model) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto& c : model.components)
        for (const glm::dvec3& p : c.surface.points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    const double radius = glm::length(hi - lo) / 2;
    const double az = glm::radians(-135.0), el = glm::radians(25.0);
    phigs::ViewMapping mapping;
    mapping.windowMin = glm::dvec2(-0.75 * radius);
    mapping.windowMax = glm::dvec2(0.75 * radius);
    mapping.viewportMin = {0.05, 0.05, 0.0};
    mapping.viewportMax = {0.95, 0.95, 1.0};
    mapping.projectionReferencePoint = {0, 0, 4 * radius};
    mapping.backPlaneDistance = -2 * radius;
    mapping.frontPlaneDistance = 2 * radius;
    phigs::ViewRepresentation view;
    view.orientation = phigs::evaluateViewOrientationMatrix(
        (lo + hi) / 2.0, {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)}, {0, 0, 1});
    view.mapping = phigs::evaluateViewMappingMatrix(mapping);
    view.clipMin = mapping.viewportMin;
    view.clipMax = mapping.viewportMax;
    return view;
}

/// The model on a workstation as the session shows it: ModelPicture's structures under the
/// geometry root in view 1, the session's pick filter.
struct Scene {
    phigs::Phigs phigs;
    phigs::Workstation* ws = nullptr;
    glm::dvec2 npcMin{0.0}, npcMax{0.0};  ///< the model's picture in NPC

    explicit Scene(const acsynt::Model& model) {
        using namespace acsynt;
        phigs.open();
        auto& store = phigs.store();
        ModelPicture(store).build(model, DisplayStyle{});
        rewriteStructure(store, structures::geometry,
                         {phigs::viewIndex(1), phigs::executeStructure(structures::modelRoot)});
        ws = &phigs.openWorkstation(1, phigs::WorkstationType::Window);
        ws->setPickFilter(phigs::NameSetFilter{{structures::pickableName, structures::buttonName}, {}});
        ws->input().setPickFilter(1, {structures::pickableName, structures::buttonName}, {});
        const phigs::ViewRepresentation view = sessionView(model);
        ws->setViewRepresentation(1, view);
        ws->postStructure(structures::geometry, 0.5);
        npcMin = glm::dvec2(1e300);
        npcMax = glm::dvec2(-1e300);
        for (const auto& c : model.components)
            for (const glm::dvec3& p : c.surface.points) {
                const glm::dvec4 h = view.mapping * view.orientation * glm::dvec4(p, 1.0);
                npcMin = glm::min(npcMin, glm::dvec2(h) / h.w);
                npcMax = glm::max(npcMax, glm::dvec2(h) / h.w);
            }
    }
};

bool sameHit(const std::optional<phigs::PickHit>& a, const std::optional<phigs::PickHit>& b) {
    if (!a || !b) return !a && !b;
    if (a->item != b->item || a->depth != b->depth || a->surface.has_value() != b->surface.has_value())
        return false;
    return !a->surface || glm::length(a->surface->point - b->surface->point) <= 1e-12;
}

struct AircraftRun {
    std::size_t patches = 0, items = 0;
    int picks = 0, hits = 0, compared = 0, agree = 0;
    double median = 0, p99 = 0, wallMedian = 0, bruteMedian = 0, bruteP99 = 0, treeMs = 0;
    double hitMedian = 0, missMedian = 0;
};

/// `picks` random picks over the picture by the tree, the first `brutePicks` of them also by
/// the brute force, compared hit for hit.
AircraftRun pickAircraft(const acsynt::Model& model, int picks, int brutePicks) {
    Scene scene(model);
    const phigs::DrawList& list = scene.ws->display();
    const phigs::WorkstationMapping mapping(list);
    const double aperture = 0.004;  // the session's pick aperture
    AircraftRun r;
    r.patches = model.patchCount();
    r.items = list.items.size();
    r.picks = picks;
    phigs::Picker fast, brute;
    brute.setAccelerated(false);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> x(scene.npcMin.x, scene.npcMax.x),
        y(scene.npcMin.y, scene.npcMax.y);
    // The first pick builds the tree.
    r.treeMs =
        timed([&] { fast.nearest(list, mapping, (scene.npcMin + scene.npcMax) / 2.0, aperture); }).cpu / 1e3;
    std::vector<double> cpu, wall, bruteCpu, hitCpu, missCpu;
    for (int i = 0; i < picks; ++i) {
        const glm::dvec2 at(x(random), y(random));
        std::optional<phigs::PickHit> hit, reference;
        const Timed t = timed([&] { hit = fast.nearest(list, mapping, at, aperture); });
        cpu.push_back(t.cpu);
        wall.push_back(t.wall);
        (hit ? hitCpu : missCpu).push_back(t.cpu);
        if (hit) ++r.hits;
        if (i >= brutePicks) continue;
        bruteCpu.push_back(timed([&] { reference = brute.nearest(list, mapping, at, aperture); }).cpu);
        ++r.compared;
        if (sameHit(hit, reference)) ++r.agree;
    }
    r.median = quantile(cpu, 0.5);
    r.p99 = quantile(cpu, 0.99);
    r.hitMedian = quantile(hitCpu, 0.5);
    r.missMedian = quantile(missCpu, 0.5);
    r.wallMedian = quantile(wall, 0.5);
    r.bruteMedian = quantile(bruteCpu, 0.5);
    r.bruteP99 = quantile(bruteCpu, 0.99);
    return r;
}

struct SessionRun {
    double stepMs = 0, stepP99Ms = 0, firstStepMs = 0, traversalMs = 0;
    std::uint64_t traversals = 0;
};

/// Pick steps through the workstation's pick device (script input, the session's device setup) on
/// the unchanged picture; the traversal each step made before, timed on the same workstation.
SessionRun sessionPicks(const acsynt::Model& model, int steps) {
    Scene scene(model);
    const phigs::DrawList& shown = scene.ws->display();
    const glm::dvec2 display = scene.ws->displaySize();
    const phigs::WorkstationMapping pixels(shown, std::uint32_t(display.x), std::uint32_t(display.y));
    std::mt19937 random(5);
    std::uniform_real_distribution<double> x(scene.npcMin.x, scene.npcMax.x),
        y(scene.npcMin.y, scene.npcMax.y);
    std::ostringstream script;
    for (int i = 0; i < steps; ++i) {
        const glm::dvec2 p = pixels.toPixels(glm::dvec3(x(random), y(random), 0.0));
        script << "pick " << p.x << " " << p.y << "\n";
    }
    phigs::ScriptInputSource source(script.str(), "picks");
    phigs::InputQueue queue;
    scene.ws->connectInput(source, queue);
    phigs::DeviceInitialisation setup;
    setup.initial = phigs::PickMeasure{};
    setup.pickAperture = 0.004;
    scene.ws->input().initialise(phigs::InputClass::Pick, 1, setup);
    SessionRun r;
    std::vector<double> ms;
    for (int i = 0; i < steps; ++i) {
        const Timed t = timed([&] { scene.ws->input().request(phigs::InputClass::Pick, 1); });
        if (i == 0)
            r.firstStepMs = t.cpu / 1e3;
        else
            ms.push_back(t.cpu / 1e3);
    }
    r.stepMs = quantile(ms, 0.5);
    r.stepP99Ms = quantile(ms, 0.99);
    r.traversals = scene.ws->pickTraversals();
    scene.ws->disconnectInput();
    std::vector<double> traversal;
    for (int i = 0; i < 5; ++i)
        traversal.push_back(timed([&] { (void)scene.ws->traverse(scene.ws->filters()); }).cpu / 1e3);
    r.traversalMs = quantile(traversal, 0.5);
    return r;
}

struct TubeRun {
    int hits = 0, agree = 0;
    double median = 0, p99 = 0, bruteMedian = 0, bruteP99 = 0;  // microseconds
};

/// Times `picks` random picks with a fresh Picker (its first picks build the patch trees)
/// against the brute force, and counts the picks where both give the same hit.
TubeRun pickTubes(const phigs::DrawList& list,
                  const std::vector<std::vector<geom::BezierSurfacePiece>>& pieces, int picks) {
    phigs::Picker picker;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(0.05, 0.95);
    std::vector<double> pickUs, bruteUs;
    TubeRun r;
    for (int i = 0; i < picks; ++i) {
        const glm::dvec2 at(coordinate(random), coordinate(random));
        std::optional<phigs::PickHit> hit;
        std::optional<BruteHit> brute;
        pickUs.push_back(timed([&] { hit = picker.nearest(list, at, 0.001); }).cpu);
        bruteUs.push_back(timed([&] { brute = bruteForce(list, pieces, at); }).cpu);
        if (hit) ++r.hits;
        const bool same = (!hit && !brute) || (hit && brute && hit->surface && hit->item == brute->item &&
                                               glm::length(hit->surface->point - brute->point) < 1e-7);
        if (same) ++r.agree;
    }
    r.median = quantile(pickUs, 0.5);
    r.p99 = quantile(pickUs, 0.99);
    r.bruteMedian = quantile(bruteUs, 0.5);
    r.bruteP99 = quantile(bruteUs, 0.99);
    return r;
}

/// Ten tubes of 10 x 10 bicubic pieces each, seen from above and to the side, SOLID (a HOLLOW
/// surface, the default, is detectable on its outline only).
phigs::DrawList tubeList(std::vector<std::vector<geom::BezierSurfacePiece>>& pieces) {
    phigs::DrawList list;
    phigs::DrawView view;
    view.orientation = glm::rotate(glm::dmat4(1.0), 0.5, glm::dvec3(1, 0, 0)) *
                       glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(0, 1, 0));
    view.mapping = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5)) *
                   glm::scale(glm::dmat4(1.0), glm::dvec3(0.09, 0.09, 0.04));
    list.views.push_back(view);
    list.viewportMax = glm::dvec3(1000, 1000, 1);
    list.displaySize = {1000.0, 1000.0};
    for (int k = 0; k < 10; ++k) {
        phigs::DrawMesh mesh;
        mesh.surface = tube(0.6 + 0.05 * k, 8.0, 0.7 * k);
        phigs::InteriorStyleSet solid;
        solid.style = phigs::InteriorStyle::Solid;
        mesh.interior = solid;
        phigs::DrawItem item;
        item.primitive = mesh;
        item.context.edit().modelTransform = glm::translate(
            glm::dmat4(1.0), glm::dvec3(-4.0 + 0.3 * (k % 3), -4.5 + 1.0 * k, -2.0 + 0.4 * (k % 4)));
        item.source = phigs::DrawSource({{1, k + 1, k}});
        list.items.push_back(item);
        pieces.push_back(geom::extractBezier(*mesh.surface));
    }
    return list;
}

}  // namespace

int main(int argc, char** argv) {
    const int picks = argc > 1 ? std::max(10, std::atoi(argv[1])) : 2000;
    const double cpu0 = seconds(CLOCK_PROCESS_CPUTIME_ID), wall0 = seconds(CLOCK_MONOTONIC);
    const acsynt::Model transport = acsynt::loadModel(std::string(ACSYNT_DATA_DIR) + "/transport.acm");
    const AircraftRun small = pickAircraft(copies(transport, 3), picks, picks);
    // The brute force costs tens of milliseconds a pick at 10k patches: compared on a fifth.
    const AircraftRun large = pickAircraft(copies(transport, 27), picks, std::max(10, picks / 5));
    const SessionRun session = sessionPicks(copies(transport, 3), 200);
    const SessionRun sessionLarge = sessionPicks(copies(transport, 27), 200);

    std::vector<std::vector<geom::BezierSurfacePiece>> pieces;
    const phigs::DrawList tubes = tubeList(pieces);
    std::size_t tubePatches = 0;
    for (const auto& p : pieces) tubePatches += p.size();
    const TubeRun exact = pickTubes(tubes, pieces, picks);

    for (const auto* r : {&small, &large})
        std::printf(
            "aircraft %zu patches (%zu items): %d picks, %d hit; tree built in %.2f ms; pick median %.1f us, "
            "p99 %.1f us CPU (wall median %.1f us; hits %.1f us, misses %.1f us); every item: median %.1f "
            "us, p99 %.1f us; same hit "
            "%d of %d\n",
            r->patches, r->items, r->picks, r->hits, r->treeMs, r->median, r->p99, r->wallMedian,
            r->hitMedian, r->missMedian, r->bruteMedian, r->bruteP99, r->agree, r->compared);
    for (const auto* s : {&session, &sessionLarge})
        std::printf(
            "session pick step: median %.3f ms, p99 %.3f ms CPU (first %.2f ms), %llu traversal(s); "
            "the traversal each step made before: %.2f ms\n",
            s->stepMs, s->stepP99Ms, s->firstStepMs, static_cast<unsigned long long>(s->traversals),
            s->traversalMs);
    std::printf(
        "tubes %zu patches: pick median %.1f us, p99 %.1f us; geom::intersectLine on every piece: median "
        "%.1f us, p99 %.1f us; same hit %d of %d\n",
        tubePatches, exact.median, exact.p99, exact.bruteMedian, exact.bruteP99, exact.agree, picks);
    const int compared = small.compared + large.compared;
    const double same = double(small.agree + large.agree) / double(compared);
    std::printf(
        "{\"aircraft_1k_patches\": %zu, \"aircraft_1k_picks\": %d, \"aircraft_1k_hits\": %d, "
        "\"aircraft_1k_median_us\": %.2f, \"aircraft_1k_p99_us\": %.2f, \"aircraft_1k_wall_median_us\": "
        "%.2f, "
        "\"aircraft_1k_brute_median_us\": %.1f, \"aircraft_1k_brute_p99_us\": %.1f, "
        "\"aircraft_1k_same_hit\": %.4f, "
        "\"aircraft_1k_tree_build_ms\": %.3f, \"aircraft_1k_hit_median_us\": %.2f, "
        "\"aircraft_1k_miss_median_us\": %.2f, "
        "\"aircraft_10k_patches\": %zu, \"aircraft_10k_picks\": %d, \"aircraft_10k_hits\": %d, "
        "\"aircraft_10k_median_us\": %.2f, \"aircraft_10k_p99_us\": %.2f, \"aircraft_10k_wall_median_us\": "
        "%.2f, "
        "\"aircraft_10k_brute_median_us\": %.1f, \"aircraft_10k_brute_p99_us\": %.1f, "
        "\"aircraft_10k_same_hit\": %.4f, \"aircraft_10k_tree_build_ms\": %.3f, "
        "\"aircraft_10k_hit_median_us\": %.2f, "
        "\"aircraft_10k_miss_median_us\": %.2f, "
        "\"same_hit_as_brute_force\": %.4f, \"compared_picks\": %d, "
        "\"session_pick_ms\": %.4f, \"session_pick_p99_ms\": %.4f, \"session_first_pick_ms\": %.3f, "
        "\"session_traversal_ms\": %.3f, \"session_10k_pick_ms\": %.4f, \"session_10k_traversal_ms\": %.3f, "
        "\"tubes_patches\": %zu, \"tubes_picks\": %d, \"tubes_hits\": %d, \"tubes_same_hit\": %.4f, "
        "\"tubes_median_us\": %.2f, \"tubes_p99_us\": %.2f, \"tubes_brute_median_us\": %.1f, "
        "\"tubes_brute_p99_us\": %.1f, \"cpu_seconds\": %.1f, \"wall_seconds\": %.1f}\n",
        small.patches, small.picks, small.hits, small.median, small.p99, small.wallMedian, small.bruteMedian,
        small.bruteP99, double(small.agree) / small.compared, small.treeMs, small.hitMedian, small.missMedian,
        large.patches, large.picks, large.hits, large.median, large.p99, large.wallMedian, large.bruteMedian,
        large.bruteP99, double(large.agree) / large.compared, large.treeMs, large.hitMedian, large.missMedian,
        same, compared, session.stepMs, session.stepP99Ms, session.firstStepMs, session.traversalMs,
        sessionLarge.stepMs, sessionLarge.traversalMs, tubePatches, picks, exact.hits,
        double(exact.agree) / picks, exact.median, exact.p99, exact.bruteMedian, exact.bruteP99,
        seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0, seconds(CLOCK_MONOTONIC) - wall0);
    return same == 1.0 && exact.agree == picks ? 0 : 1;
}
