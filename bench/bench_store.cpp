// Structure store benchmark: one root executing leaves of 100 elements each (one NURBS surface,
// attributes, polylines), posted on an offscreen workstation. Per size: inserts per second,
// full traversal ns per element against a visit of the same elements kept in plain vectors
// (the baseline, same run, made and freed before the store), incremental traversal with nothing
// changed, peak resident bytes per element (the whole process above its start: store,
// workstation, draw lists, caches), and one edit of a posted leaf up to the next draw list.
// `bench_store` runs 10k, 100k, 1M and 4M elements, each in its own process, and prints the 1M
// figures plus `scaling` (each size's figures, and how the traversal's cost per element grows
// with size beside the plain-vector visit's); `bench_store --elements N` runs one size. Process CPU time.
// Ends with one JSON object.

#include "phigs/Phigs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

using namespace phigs;

namespace {

/// Process CPU seconds: the machine is shared, so wall time says more about the neighbours.
double cpuNow() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

/// A field of /proc/self/status in bytes (VmRSS, VmHWM).
long statusBytes(const char* field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(field, 0) == 0) return std::atol(line.c_str() + std::strlen(field) + 1) * 1024;
    return 0;
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

/// The baseline: the same leaves in plain vectors (one type code, one integer and a point range
/// per element), visited with the same attribute state and one plain record per polyline.
struct PlainLeaf {
    std::vector<unsigned char> kinds;  ///< k % 10 of the element, 10: the surface
    std::vector<int> values;
    std::vector<std::uint32_t> firstPoint;
    std::vector<glm::dvec3> points;
};
struct PlainItem {
    const glm::dvec3* points;
    std::uint32_t count;
    int colour, linetype, leaf, element, pickId;
    const glm::dmat4* transform;
};

std::vector<PlainLeaf> plainLeaves(int leaves, int perLeaf) {
    std::vector<PlainLeaf> out(static_cast<std::size_t>(leaves));
    for (int leaf = 0; leaf < leaves; ++leaf) {
        PlainLeaf& p = out[static_cast<std::size_t>(leaf)];
        p.kinds.push_back(10), p.values.push_back(0), p.firstPoint.push_back(0);
        for (int k = 1; k < perLeaf; ++k) {
            p.kinds.push_back(static_cast<unsigned char>(k % 10));
            p.values.push_back(k % 10 == 0 ? 1 + k % 7 : k % 10 == 1 ? 1 + k % 4 : k);
            p.firstPoint.push_back(static_cast<std::uint32_t>(p.points.size()));
            if (k % 10 >= 4)
                for (glm::dvec3 q : {glm::dvec3(leaf, k, 0), {leaf + 1, k, 0}, {leaf + 1, k + 1, 0}})
                    p.points.push_back(q);
        }
        p.firstPoint.push_back(static_cast<std::uint32_t>(p.points.size()));
    }
    return out;
}

std::size_t plainVisit(const std::vector<PlainLeaf>& leaves, std::vector<PlainItem>& out) {
    out.clear();
    const glm::dmat4 identity(1.0);
    std::size_t visited = 0;
    for (std::size_t leaf = 0; leaf < leaves.size(); ++leaf) {
        const PlainLeaf& p = leaves[leaf];
        int colour = 1, linetype = 1, pick = 0;  // pushed per execute, as traversal does
        for (std::size_t i = 0; i < p.kinds.size(); ++i, ++visited) {
            switch (p.kinds[i]) {
                case 0:
                    colour = p.values[i];
                    break;
                case 1:
                    linetype = p.values[i];
                    break;
                case 2:
                    break;
                case 3:
                    pick = p.values[i];
                    break;
                case 10:
                    break;
                default:
                    out.push_back({p.points.data() + p.firstPoint[i], p.firstPoint[i + 1] - p.firstPoint[i],
                                   colour, linetype, static_cast<int>(leaf), static_cast<int>(i), pick,
                                   &identity});
            }
        }
    }
    return visited + leaves.size();  // the root's executes
}

struct Figures {
    std::size_t elements = 0, structures = 0, items = 0;
    double insertsPerS = 0, traversalNs = 0, rawVisitNs = 0, unchangedNs = 0, firstTraversalS = 0;
    double peakRssPerElement = 0, residentAfterInsertPerElement = 0, payloadPerElement = 0;
    double editPolylineMs = 0, editSurfaceMs = 0;
    std::uint64_t surfacesFirst = 0, editRetraversed = 0, editRetessellated = 0, reused = 0;
};

/// The median CPU time of `passes` calls of pass, in nanoseconds.
template <class Pass>
double medianNs(int passes, Pass&& pass) {
    std::vector<double> ns;
    for (int r = 0; r < passes; ++r) {
        const double start = cpuNow();
        pass();
        ns.push_back((cpuNow() - start) * 1e9);
    }
    std::nth_element(ns.begin(), ns.begin() + passes / 2, ns.end());
    return ns[static_cast<std::size_t>(passes / 2)];
}

/// Replaces element `at` of `structure` and times the store edit up to the next draw list.
double editMs(Phigs& phigs, Workstation& ws, int structure, int at, Element element) {
    double start = cpuNow();
    StructureStore& store = phigs.store();
    store.openStructure(structure);
    store.setEditMode(EditMode::Replace);
    store.setElementPointer(at);
    store.insert(std::move(element));
    store.closeStructure();
    ws.display();
    return (cpuNow() - start) * 1e3;
}

Figures run(int leaves, long rssAtStart) {
    const int perLeaf = 100;
    // Each figure is the median of at least three timed passes, and at the small sizes of as many
    // as visit about 3M elements in all, so that their passes (10k elements: a millisecond) are
    // not single readings of a noisy clock.
    const int repeats = std::clamp(3'000'000 / (leaves * (perLeaf + 1)), 3, 301);
    Figures f;
    {
        // The baseline in the same run: plain vectors of the same leaves, made and freed before
        // the store, so that the peak below is the store's and not the baseline's.
        auto plain = plainLeaves(leaves, perLeaf);
        std::vector<PlainItem> plainItems;
        plainVisit(plain, plainItems);
        std::size_t visited = 0;
        f.rawVisitNs = medianNs(repeats, [&] { visited = plainVisit(plain, plainItems); }) /
                       static_cast<double>(visited);
    }
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    double start = cpuNow();
    store.openStructure(1);
    for (int leaf = 0; leaf < leaves; ++leaf) store.insert(executeStructure(leaf + 2));
    store.insert(label(0));
    store.closeStructure();
    for (int leaf = 0; leaf < leaves; ++leaf) {
        store.openStructure(leaf + 2);
        store.insert(leafSurface(leaf));
        for (int k = 1; k < perLeaf; ++k) store.insert(leafElement(leaf, k));
        store.closeStructure();
    }
    f.elements = static_cast<std::size_t>(leaves) * (perLeaf + 1) + 1;
    f.insertsPerS = static_cast<double>(f.elements) / (cpuNow() - start);
    f.residentAfterInsertPerElement =
        static_cast<double>(statusBytes("VmRSS:") - rssAtStart) / static_cast<double>(f.elements);
    std::size_t payload = 0;
    for (int id : store.structureIds())
        for (int n = 1; n <= store.elementCount(id); ++n) payload += store.elementSizeAt(id, n);
    f.payloadPerElement = static_cast<double>(payload) / static_cast<double>(f.elements);
    f.structures = store.structureIds().size();

    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    ws.postStructure(1, 0.5);
    start = cpuNow();
    f.items = ws.display().items.size();
    f.firstTraversalS = cpuNow() - start;
    auto& counters = ws.traverser().cache().counters();
    f.surfacesFirst = counters.surfacesTessellated;

    // Full traversals (every element walked, every draw item made) and incremental ones.
    ws.traverser().setIncremental(false);
    f.traversalNs = medianNs(repeats, [&] { ws.redrawAllStructures(); }) /
                    static_cast<double>(ws.traverser().elementsTraversed());
    ws.traverser().setIncremental(true);
    ws.redrawAllStructures();
    f.unchangedNs = medianNs(repeats, [&] { ws.redrawAllStructures(); }) / static_cast<double>(f.elements);
    f.reused = ws.traverser().elementsReused();

    // One edit of one posted leaf: a polyline, then the surface.
    const int leaf = leaves / 2 + 2;
    f.editPolylineMs = editMs(phigs, ws, leaf, 50, polyline3({{0, 0, 0}, {2, 2, 2}}));
    std::uint64_t before = counters.surfacesTessellated;
    f.editSurfaceMs = editMs(phigs, ws, leaf + 1, 1, leafSurface(12345));
    f.editRetessellated = counters.surfacesTessellated - before;
    f.editRetraversed = ws.traverser().elementsTraversed();
    f.peakRssPerElement =
        static_cast<double>(statusBytes("VmHWM:") - rssAtStart) / static_cast<double>(f.elements);
    return f;
}

std::string json(const Figures& f, const std::string& prefix) {
    char buffer[1200];
    std::snprintf(
        buffer, sizeof buffer,
        "\"%selements\": %zu, \"%sstructures\": %zu, \"%sdraw_items\": %zu, \"%sinserts_per_s\": %.0f, "
        "\"%straversal_ns_per_element\": %.2f, \"%sraw_visit_ns_per_element\": %.2f, "
        "\"%straversal_over_raw\": %.2f, "
        "\"%sincremental_unchanged_ns_per_element\": %.1f, \"%speak_rss_bytes_per_element\": %.1f, "
        "\"%sresident_after_insert_bytes_per_element\": %.1f, \"%spayload_bytes_per_element\": %.1f, "
        "\"%sfirst_traversal_cpu_s\": %.3f, \"%ssurfaces_tessellated_first\": %llu, "
        "\"%sedit_to_drawlist_ms\": %.2f, \"%sedit_polyline_to_drawlist_ms\": %.2f, "
        "\"%sedit_surface_to_drawlist_ms\": %.2f, \"%sedit_retraversed_elements\": %llu, "
        "\"%sedit_retessellated_surfaces\": %llu",
        prefix.c_str(), f.elements, prefix.c_str(), f.structures, prefix.c_str(), f.items, prefix.c_str(),
        f.insertsPerS, prefix.c_str(), f.traversalNs, prefix.c_str(), f.rawVisitNs, prefix.c_str(),
        f.traversalNs / f.rawVisitNs, prefix.c_str(), f.unchangedNs, prefix.c_str(), f.peakRssPerElement,
        prefix.c_str(), f.residentAfterInsertPerElement, prefix.c_str(), f.payloadPerElement, prefix.c_str(),
        f.firstTraversalS, prefix.c_str(), (unsigned long long)f.surfacesFirst, prefix.c_str(),
        std::max(f.editPolylineMs, f.editSurfaceMs), prefix.c_str(), f.editPolylineMs, prefix.c_str(),
        f.editSurfaceMs, prefix.c_str(), (unsigned long long)f.editRetraversed, prefix.c_str(),
        (unsigned long long)f.editRetessellated);
    return buffer;
}

void print(const Figures& f) {
    std::printf("elements %zu in %zu structures, draw items %zu\n", f.elements, f.structures, f.items);
    std::printf("insert: %.0f elements/s; resident after insert %.1f B/element, payload %.1f B/element\n",
                f.insertsPerS, f.residentAfterInsertPerElement, f.payloadPerElement);
    std::printf("first traversal (%llu surfaces tessellated): %.3f s\n", (unsigned long long)f.surfacesFirst,
                f.firstTraversalS);
    std::printf("full traversal %.1f ns/element; plain vectors %.1f ns/element; unchanged %.1f ns/element\n",
                f.traversalNs, f.rawVisitNs, f.unchangedNs);
    std::printf(
        "edit to draw list: polyline %.2f ms, surface %.2f ms (%llu re-traversed, %llu re-tessellated)\n",
        f.editPolylineMs, f.editSurfaceMs, (unsigned long long)f.editRetraversed,
        (unsigned long long)f.editRetessellated);
    std::printf("peak resident %.1f B/element (whole process above its start)\n", f.peakRssPerElement);
}

/// Runs `--elements n` in a child process (its own peak RSS) and returns its JSON line.
std::string child(const char* self, std::size_t elements) {
    std::string command = std::string(self) + " --elements " + std::to_string(elements);
    std::string last;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char line[4096];
        while (std::fgets(line, sizeof line, pipe)) {
            std::fputs(line, stderr);
            if (line[0] == '{') last = line;
        }
        pclose(pipe);
    }
    while (!last.empty() && (last.back() == '\n' || last.back() == '}')) last.pop_back();
    return last.empty() ? "" : last.substr(1);
}

/// The number after "key": in a JSON object's text (NaN where it is missing).
double numberIn(const std::string& object, const std::string& key) {
    const std::size_t at = object.find("\"" + key + "\": ");
    return at == std::string::npos ? std::nan("") : std::atof(object.c_str() + at + key.size() + 4);
}

/// Linear cost, read against the baseline: how much the per-element traversal time grows from
/// the smallest size and from 1M to the largest, beside the same growth of the plain-vector
/// visit (what the memory hierarchy alone adds). objects: the sizes' figures, ascending (1M third).
std::string scalingFigures(const std::vector<std::string>& objects) {
    auto growth = [&](const char* name, const char* key, std::size_t from) {
        const double g = numberIn(objects.back(), key) / numberIn(objects[from], key);
        char text[96];
        if (std::isfinite(g))
            std::snprintf(text, sizeof text, "\"%s\": %.3f", name, g);
        else
            std::snprintf(text, sizeof text, "\"%s\": null", name);
        return std::string(text);
    };
    return growth("traversal_growth_10k_to_4M", "traversal_ns_per_element", 0) + ", " +
           growth("raw_visit_growth_10k_to_4M", "raw_visit_ns_per_element", 0) + ", " +
           growth("traversal_growth_1M_to_4M", "traversal_ns_per_element", 2) + ", " +
           growth("raw_visit_growth_1M_to_4M", "raw_visit_ns_per_element", 2);
}

std::string renamed(std::string object, const std::string& prefix) {
    for (std::size_t at = object.find('"'); at != std::string::npos; at = object.find(", \"", at)) {
        at += at == 0 ? 1 : 3;
        object.insert(at, prefix);
    }
    return object;
}

}  // namespace

int main(int argc, char** argv) {
    const long rssAtStart = statusBytes("VmRSS:");
    if (argc == 3 && std::strcmp(argv[1], "--elements") == 0) {
        int leaves = std::max(1, std::atoi(argv[2]) / 101);
        Figures f = run(leaves, rssAtStart);
        print(f);
        std::printf("{%s}\n", json(f, "").c_str());
        return 0;
    }
    const std::pair<const char*, std::size_t> sizes[] = {
        {"e10k_", 10'000}, {"e100k_", 100'000}, {"e4M_", 4'000'000}};
    std::string scaling = "\"sizes\": \"10k 100k 1M 4M\"";
    std::vector<std::string> objects;  // by size, ascending
    for (auto [prefix, n] : sizes) {
        std::string object = child(argv[0], n);
        if (object.empty()) return std::fprintf(stderr, "bench_store: the %zu-element run failed\n", n), 1;
        scaling += ", " + renamed(object, prefix);
        objects.push_back(object);
    }
    Figures f = run(9'999, rssAtStart);
    print(f);
    std::string main = json(f, "");
    scaling += ", " + json(f, "e1M_");
    objects.insert(objects.end() - 1, main);
    std::printf("{%s, \"scaling\": {%s, %s}}\n", main.c_str(), scaling.c_str(),
                scalingFigures(objects).c_str());
    return 0;
}
