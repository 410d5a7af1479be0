// Structure store benchmark: 1,000,000 elements in 10,000 structures (one root executing
// 9,999 leaves of 100 elements each, one NURBS surface per leaf). Prints inserts per second,
// traversal ns per element, bytes per element, and what one edit of a posted network costs:
// how many elements are re-traversed and how many surfaces re-tessellated. Ends with one JSON object.

#include "phigs/Phigs.h"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>

using namespace phigs;

namespace {

/// Process CPU seconds: the machine is shared, so wall time says more about the neighbours.
double cpuNow() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

long residentBytes() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * 4096;
}

NurbsSurfaceElement leafSurface(int leaf) {
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) points.push_back({i + leaf * 4.0, j, (i * j) % 3});
    return {geom::Surface(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, points), {}};
}

Element leafElement(int leaf, int k) {
    switch (k % 10) {
        case 0:
            return polylineColourIndex(1 + k % 7);
        case 1:
            return IndexAttribute{ElementType::Linetype, 1 + k % 4};
        case 2:
            return label(k);
        case 3:
            return pickId(k);
        default:
            return polyline3({{leaf, k, 0}, {leaf + 1, k, 0}, {leaf + 1, k + 1, 0}});
    }
}

}  // namespace

int main() {
    const int leaves = 9999, perLeaf = 100;
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    long rssBefore = residentBytes();

    double start = cpuNow();
    std::size_t inserted = 0;
    store.openStructure(1);
    for (int leaf = 0; leaf < leaves; ++leaf) store.insert(executeStructure(leaf + 2));
    store.insert(label(0));
    store.closeStructure();
    inserted += leaves + 1;
    for (int leaf = 0; leaf < leaves; ++leaf) {
        store.openStructure(leaf + 2);
        store.insert(leafSurface(leaf));
        for (int k = 1; k < perLeaf; ++k) store.insert(leafElement(leaf, k));
        store.closeStructure();
        inserted += perLeaf;
    }
    double insertSeconds = (cpuNow() - start);
    long rssAfter = residentBytes();
    std::size_t payloadBytes = 0;
    for (int id : store.structureIds())
        for (int n = 1; n <= store.elementCount(id); ++n) payloadBytes += store.elementSizeAt(id, n);

    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    ws.postStructure(1, 0.5);
    start = cpuNow();
    std::size_t items = ws.display().items.size();
    double firstTraversal = (cpuNow() - start);
    auto& counters = ws.traverser().cache().counters();
    std::uint64_t surfacesFirst = counters.surfacesTessellated;

    // Full traversals (every element walked) and incremental ones (unchanged subtrees reused).
    const int repeats = 3;
    ws.traverser().setIncremental(false);
    start = cpuNow();
    for (int r = 0; r < repeats; ++r) ws.redrawAllStructures();
    double traversalSeconds = (cpuNow() - start) / repeats;
    std::uint64_t traversed = ws.traverser().elementsTraversed();
    ws.traverser().setIncremental(true);
    ws.redrawAllStructures();
    start = cpuNow();
    for (int r = 0; r < repeats; ++r) ws.redrawAllStructures();
    double reuseSeconds = (cpuNow() - start) / repeats;
    std::uint64_t reusedElements = ws.traverser().elementsReused();

    // Edit one polyline of one posted leaf.
    store.openStructure(5000);
    store.setEditMode(EditMode::Replace);
    store.setElementPointer(50);
    store.insert(polyline3({{0, 0, 0}, {2, 2, 2}}));
    store.closeStructure();
    std::uint64_t before = counters.surfacesTessellated;
    start = cpuNow();
    ws.display();
    double editPolylineSeconds = (cpuNow() - start);
    std::uint64_t retraversedPolyline = ws.traverser().elementsTraversed();
    std::uint64_t surfacesPolylineEdit = counters.surfacesTessellated - before;

    // Replace the surface of one leaf.
    store.openStructure(6000);
    store.setEditMode(EditMode::Replace);
    store.setElementPointer(1);
    store.insert(leafSurface(12345));
    store.closeStructure();
    before = counters.surfacesTessellated;
    start = cpuNow();
    ws.display();
    double editSurfaceSeconds = (cpuNow() - start);
    std::uint64_t surfacesSurfaceEdit = counters.surfacesTessellated - before;
    std::uint64_t retraversedSurface = ws.traverser().elementsTraversed();

    double insertsPerSecond = inserted / insertSeconds;
    double nsPerElement = traversalSeconds * 1e9 / static_cast<double>(traversed);
    double rssPerElement = static_cast<double>(rssAfter - rssBefore) / static_cast<double>(inserted);
    double payloadPerElement = static_cast<double>(payloadBytes) / static_cast<double>(inserted);

    std::printf("structures %zu, elements %zu, draw items %zu\n", store.structureIds().size(), inserted,
                items);
    std::printf("insert: %.3f s, %.0f elements/s\n", insertSeconds, insertsPerSecond);
    std::printf("memory: %.1f bytes/element resident, %.1f bytes/element payload (elementSize)\n",
                rssPerElement, payloadPerElement);
    std::printf("first traversal with %llu surface tessellations: %.3f s\n",
                (unsigned long long)surfacesFirst, firstTraversal);
    std::printf("traversal (cache warm): %.3f s, %.1f ns/element over %llu elements\n", traversalSeconds,
                nsPerElement, (unsigned long long)traversed);
    std::printf("incremental traversal, nothing changed: %.3f s, %.1f ns/element, %llu elements reused\n",
                reuseSeconds, reuseSeconds * 1e9 / static_cast<double>(inserted),
                (unsigned long long)reusedElements);
    std::printf("edit one polyline: %.3f s, %llu elements re-traversed, %llu surfaces re-tessellated\n",
                editPolylineSeconds, (unsigned long long)retraversedPolyline,
                (unsigned long long)surfacesPolylineEdit);
    std::printf("edit one surface: %.3f s, %llu elements re-traversed, %llu surfaces re-tessellated\n",
                editSurfaceSeconds, (unsigned long long)retraversedSurface,
                (unsigned long long)surfacesSurfaceEdit);
    std::printf(
        "{\"structures\": %zu, \"elements\": %zu, \"inserts_per_s\": %.0f, \"traversal_ns_per_element\": "
        "%.1f, "
        "\"incremental_unchanged_ns_per_element\": %.1f, \"resident_bytes_per_element\": %.1f, "
        "\"payload_bytes_per_element\": %.1f, "
        "\"first_traversal_cpu_s\": %.3f, \"surfaces_tessellated_first\": %llu, "
        "\"edit_polyline_retraversed_elements\": %llu, \"edit_polyline_retessellated_surfaces\": %llu, "
        "\"edit_surface_retraversed_elements\": %llu, \"edit_surface_retessellated_surfaces\": %llu, "
        "\"edit_polyline_update_cpu_s\": %.3f, \"edit_surface_update_cpu_s\": %.3f}\n",
        store.structureIds().size(), inserted, insertsPerSecond, nsPerElement,
        reuseSeconds * 1e9 / static_cast<double>(inserted), rssPerElement, payloadPerElement, firstTraversal,
        (unsigned long long)surfacesFirst, (unsigned long long)retraversedPolyline,
        (unsigned long long)surfacesPolylineEdit, (unsigned long long)retraversedSurface,
        (unsigned long long)surfacesSurfaceEdit, editPolylineSeconds, editSurfaceSeconds);
    return 0;
}
