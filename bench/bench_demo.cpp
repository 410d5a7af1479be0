// bench_demo: README command 1's main job, the ACSYNT demo session replayed headless on
// lavapipe (the acsynt program on apps/acsynt/data/demo.session), run as its own process:
// CPU time (user + system, all threads) and peak resident memory per run. Baselines in the same
// run: the program on an empty session (start, Vulkan context, exit) and the demo without its
// PDF hardcopy line, which split the session's cost. The timed runs find the specialised shaders
// in the disk cache (PHIGS_SHADER_CACHE, a folder of the bench's own) that a first run filled.
// Usage: bench_demo [--runs N] [--program PATH] [--session PATH]. Ends with one JSON object.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

struct Run {
    double cpuSeconds = 0.0, wallSeconds = 0.0, peakRssMb = 0.0;
};

/// Runs the program on a script, output into a fresh folder, stdout to /dev/null.
Run runProgram(const std::string& program, const std::filesystem::path& script,
               const std::filesystem::path& output) {
    std::filesystem::remove_all(output);
    std::vector<std::string> args = {program, "--script", script.string(), "--output", output.string() + "/"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw std::runtime_error("cannot start " + program);
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid) throw std::runtime_error("wait4 failed for " + program);
    const auto t1 = std::chrono::steady_clock::now();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error(program + " on " + script.string() + " failed (status " +
                                 std::to_string(status) + ")");
    Run r;
    r.cpuSeconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                   1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    r.wallSeconds = std::chrono::duration<double>(t1 - t0).count();
    r.peakRssMb = double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
    return r;
}

/// The demo session without the lines starting with `prefix`, in the temporary folder (the
/// program finds the shipped models and curves in its data folder).
std::filesystem::path without(const std::filesystem::path& session, const std::string& prefix,
                              const std::string& name) {
    std::ifstream in(session);
    if (!in) throw std::runtime_error("cannot read " + session.string());
    const auto path = std::filesystem::temp_directory_path() / name;
    std::ofstream out(path);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) != 0) out << line << "\n";
    return path;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct Series {
    std::vector<double> cpu, wall, rss;
    void add(const Run& r) {
        cpu.push_back(r.cpuSeconds), wall.push_back(r.wallSeconds), rss.push_back(r.peakRssMb);
    }
    double peakRss() const { return *std::max_element(rss.begin(), rss.end()); }
};

}  // namespace

int main(int argc, char** argv) {
    int runs = 3;
    std::string program = ACSYNT_PROGRAM;
    std::filesystem::path session = ACSYNT_DEMO_SESSION;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string arg = argv[i];
        if (arg == "--runs")
            runs = std::max(1, std::atoi(argv[i + 1]));
        else if (arg == "--program")
            program = argv[i + 1];
        else if (arg == "--session")
            session = argv[i + 1];
    }
    try {
        const auto noPdf = without(session, "hardcopy", "bench_demo_no_pdf.session");
        const auto empty = std::filesystem::temp_directory_path() / "bench_demo_empty.session";
        std::ofstream(empty) << "choice EXIT\n";
        const auto output = std::filesystem::temp_directory_path() / "bench_demo_out";
        // The specialised shaders' disk cache in a folder of the bench's own, empty at first: the
        // first run fills it (a user's first session), the timed runs find it filled (every later one).
        const auto shaderCache = std::filesystem::temp_directory_path() / "bench_demo_shader_cache";
        std::filesystem::remove_all(shaderCache);
        setenv("PHIGS_SHADER_CACHE", shaderCache.c_str(), 1);
        const Run cold = runProgram(program, session, output);
        // Runs of the three kinds alternate, so the machine's load hits them alike.
        Series demo, startup, demoNoPdf;
        for (int r = 0; r < runs; ++r) {
            demo.add(runProgram(program, session, output));
            startup.add(runProgram(program, empty, output));
            demoNoPdf.add(runProgram(program, noPdf, output));
        }
        std::filesystem::remove_all(output);
        std::filesystem::remove_all(shaderCache);
        std::printf(
            "demo session: %.2f s CPU, %.2f s wall, peak RSS %.0f MB (median CPU of %d runs; target "
            "<= 0.8 s, <= 150 MB)\n",
            median(demo.cpu), median(demo.wall), demo.peakRss(), runs);
        std::printf("first demo session (shader cache empty): %.2f s CPU, peak RSS %.0f MB\n",
                    cold.cpuSeconds, cold.peakRssMb);
        std::printf("empty session (start, Vulkan, exit): %.2f s CPU, peak RSS %.0f MB\n",
                    median(startup.cpu), startup.peakRss());
        std::printf("demo without the PDF hardcopy: %.2f s CPU, peak RSS %.0f MB\n", median(demoNoPdf.cpu),
                    demoNoPdf.peakRss());
        std::printf(
            "{\"runs\": %d, \"demo_cpu_s\": %.3f, \"demo_wall_s\": %.3f, \"demo_peak_rss_mb\": %.1f, "
            "\"startup_cpu_s\": %.3f, \"startup_peak_rss_mb\": %.1f, \"demo_without_pdf_cpu_s\": %.3f, "
            "\"demo_without_pdf_peak_rss_mb\": %.1f, \"demo_cold_shader_cache_cpu_s\": %.3f}\n",
            runs, median(demo.cpu), median(demo.wall), demo.peakRss(), median(startup.cpu), startup.peakRss(),
            median(demoNoPdf.cpu), demoNoPdf.peakRss(), cold.cpuSeconds);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_demo: %s\n", e.what());
        return 1;
    }
    return 0;
}
