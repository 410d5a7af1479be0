// Load and loft the shipped ACSYNT models: parse the description, build the sections, interpolate
// every component surface and build its patch list. Prints per-model figures and ends with one
// JSON object.
#include "acsynt/Model.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

int main() {
    const char* names[] = {"transport", "fighter"};
    std::string json = "{";
    for (const char* name : names) {
        const std::string path = std::string(ACSYNT_DATA_DIR) + "/" + name + ".acm";
        const int repeats = 50;
        double best = 1e30, total = 0.0;
        std::size_t patches = 0, components = 0, controls = 0;
        for (int r = 0; r < repeats; ++r) {
            const auto start = std::chrono::steady_clock::now();
            const acsynt::Model m = acsynt::loadModel(path);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            best = std::min(best, ms);
            total += ms;
            patches = m.patchCount();
            components = m.components.size();
            controls = 0;
            for (const auto& c : m.components) controls += c.surface.points.size();
        }
        std::printf(
            "%-10s %zu components, %zu patches, %zu control points: load+loft best %.3f ms, mean %.3f ms\n",
            name, components, patches, controls, best, total / repeats);
        char buffer[256];
        std::snprintf(buffer, sizeof buffer, "%s\"%s_load_loft_ms\": %.4f, \"%s_patches\": %zu",
                      json.size() > 1 ? ", " : "", name, best, name, patches);
        json += buffer;
    }
    json += "}";
    std::printf("%s\n", json.c_str());
    return 0;
}
