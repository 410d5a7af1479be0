// acsynt: the ACSYNT-like design program. Replays a session script headless (pictures through
// the Vulkan offscreen workstation) or runs interactively in a GLFW window; either way the
// session can be recorded as a script. --export converts a model to IGES or STEP without a session.
#include "acsynt/DataFolders.h"
#include "acsynt/session/ModelExchange.h"
#include "acsynt/session/ModelStateFile.h"
#include "acsynt/session/Session.h"
#include "geom/exchange/ExchangeError.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/Outputs.h"
#include "phigs/vk/WorkstationDisplay.h"

#ifdef ACSYNT_HAVE_WINDOW
#include "acsynt/session/ViewNavigation.h"
#include "acsynt/session/WindowPresentation.h"
#include "phigs/window/GlfwInputSource.h"
#include "phigs/window/GlfwWindow.h"
#endif

#include <fcntl.h>
#include <getopt.h>
#include <malloc.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

// Exit codes: 0 every input line succeeded; 1 the session could not run (a script that does not
// parse, no Vulkan device, a file that cannot be written); 2 bad options; 3 some lines failed.
constexpr int kExitFatal = 1, kExitUsage = 2, kExitLinesFailed = 3;

/// The signal that asked the session to stop (SIGTERM, SIGINT, SIGHUP), or 0: the session stops
/// after the line it is on and writes its summary, log and recording before it exits.
volatile std::sig_atomic_t stopSignal = 0;

void catchStopSignals() {
    struct sigaction action {};
    action.sa_handler = [](int signal) { stopSignal = signal; };
    sigemptyset(&action.sa_mask);
    // A second signal stops the process at once (a line that does not end); calls the first
    // interrupts go on.
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    for (int signal : {SIGTERM, SIGINT, SIGHUP}) sigaction(signal, &action, nullptr);
}

/// finish()'s status, or 128 + the signal that stopped the session (its files written).
int stopped(int status) {
    if (stopSignal == 0) return status;
    std::cout << "stopped by signal " << int(stopSignal) << "\n";
    return 128 + int(stopSignal);
}

struct Options {
    std::string script;
    std::string exportFile;  ///< --export OUT: write MODEL as IGES or STEP and stop
    std::string model;       ///< the model file --export converts
    std::string importFile;  ///< --import IN: read an IGES or STEP file as the first model
    std::filesystem::path output = "out";
    std::string record;
    bool window = false;
    bool keepGoing = false;
    int width = 1024, height = 768;
};

void usage(std::ostream& out) {
    out << "usage: acsynt --script FILE [--import CAD] [--keep-going] [--output DIR] [--record FILE]\n"
           "                            [--size WxH]\n"
           "       acsynt --window [--import CAD] [--output DIR] [--record FILE] [--size WxH]\n"
           "       acsynt --export OUT.step|OUT.stp|OUT.igs|OUT.iges MODEL\n"
           "  --script FILE  replay a session script headless (lavapipe), writing its snapshots;\n"
           "                 it stops at the first line that fails\n"
           "  --keep-going   carry on after a failing line (the count is still reported)\n"
           "  --output DIR   where pictures, summary.txt, acsynt.log and saved files go (default out);\n"
           "                 files a script names stay inside it\n"
           "  --record FILE  write the session as a script that replays it\n"
           "  --window       interactive session in a GLFW window\n"
           "  --size WxH     screen size in pixels (default 1024x768); a script's must be 4:3 like the\n"
           "                 display surface, a window's any shape (it also follows the window's size)\n"
           "  --import CAD   read an IGES or STEP file as the first model before the session's input\n"
           "  --export OUT   write MODEL (an .acm lofted, or a saved model with its curves) as IGES or\n"
           "                 STEP, by OUT's extension, and stop;\n"
           "                 MODEL and CAD are looked up in the shipped data folder when not found\n"
           "in the window: the left button chooses a menu row or a pad button, picks the surface\n"
           "             (DEFINE POINT, SURF_REDN), drags a slider, live (U, W: the marker, the\n"
           "             component's parameters within the patch; ROTATE, ZOOM: the views)\n"
           "             left drag in a view: rotate the 3D view (across: azimuth, up/down: elevation)\n"
           "             wheel in a view: zoom; middle drag or Shift + left drag in a view: pan\n"
           "             F1 or H: the key and mouse help over the views (Escape hides it)\n"
           "             Ctrl+Z / Ctrl+Y: undo / redo (as MAIN > UNDO / REDO); F2..F12: menu item 2..12\n"
           "             typed characters fill a prompt, Enter accepts it, Backspace deletes,\n"
           "             Escape withdraws it; closing the window ends the session\n"
           "environment: PHIGS_VK_VALIDATION=1 turns the Vulkan validation layer on (off by default)\n"
           "             and prints every message; PHIGS_VK_DEVICE=lavapipe|hardware picks the device\n"
           "exit status: 0 every line succeeded, 1 the session could not run, 2 bad options,\n"
           "             3 some lines failed (the last line printed says how many)\n";
}

bool parseSize(const char* text, int& width, int& height) {
    const char* end = text + std::strlen(text);
    const auto [afterWidth, ec1] = std::from_chars(text, end, width);
    if (ec1 != std::errc() || afterWidth == end || *afterWidth != 'x') return false;
    const auto [afterHeight, ec2] = std::from_chars(afterWidth + 1, end, height);
    return ec2 == std::errc() && afterHeight == end && width >= 160 && height >= 120 && width <= 4096 &&
           height <= 4096;
}

/// Why a file cannot be written at `path` (empty when it can): a directory, a folder that is
/// missing, or a file that does not open for writing. Permissions alone say yes to root, even
/// under /proc, so a new file is made to find out (exclusively, never through a link, and
/// removed again) and an existing regular file opened without a change; a pipe or a device is
/// only asked for permission (opening one could block).
std::string unwritable(const std::filesystem::path& path) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(status)) return "is a directory";
    if (std::filesystem::exists(status)) {
        if (!std::filesystem::is_regular_file(status))
            return access(path.c_str(), W_OK) == 0 ? "" : "is not writable";
        const int fd = open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) return "is not writable";
        close(fd);
        return "";
    }
    const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
    if (!std::filesystem::is_directory(folder, ec)) return "is in a folder that does not exist";
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) return errno == EEXIST ? "" : "cannot be written in its folder";  // EEXIST: a link
    close(fd);
    unlink(path.c_str());
    return "";
}

/// A file to read as given, else (a relative name) from the shipped data folders, as the
/// session's file names are found.
std::string resolveInput(const std::string& name) {
    std::error_code ec;
    if (std::filesystem::exists(name, ec) || !std::filesystem::path(name).is_relative()) return name;
    for (const std::filesystem::path& folder : acsynt::dataFolders())
        if (std::filesystem::exists(folder / name, ec)) return (folder / name).string();
    return name;
}

/// Why a file to read cannot be read at `path` (empty when it can).
std::string unreadable(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return "is a directory";
    if (access(path.c_str(), R_OK) != 0) return "cannot be read";
    // A device or a pipe (/dev/zero, a FIFO) could block the read or never end.
    return std::filesystem::is_regular_file(path, ec) ? "" : "is not a regular file";
}

/// Whether the name has an IGES or STEP extension (the exchange module's own test, which throws
/// for any other).
bool isCadFileName(const std::filesystem::path& path) {
    try {
        acsynt::exchangeCalls().checkFileName(path);
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

/// Whether `file` has an IGES or STEP name, else says why after `option`.
bool checkCadName(const std::string& option, const std::string& file) {
    try {
        acsynt::exchangeCalls().checkFileName(file);
        return true;
    } catch (const geom::exchange::ExchangeError& e) {
        std::cerr << "acsynt: " << option << " " << e.reason() << "\n";
    } catch (const std::runtime_error& e) {  // the exchange module cannot be loaded
        std::cerr << "acsynt: " << option << ": " << e.what() << "\n";
    }
    return false;
}

/// --export OUT MODEL: OUT an IGES or STEP name that can be written, MODEL readable.
bool checkExport(const Options& o) {
    if (!checkCadName("--export", o.exportFile)) return false;
    if (const std::string why = unwritable(o.exportFile); !why.empty()) {
        std::cerr << "acsynt: --export " << o.exportFile << " " << why << "\n";
        return false;
    }
    if (const std::string why = unreadable(o.model); !why.empty()) {
        std::cerr << "acsynt: model " << o.model << " " << why << "\n";
        return false;
    }
    // An IGES or STEP file given as the model: the conversion runs the other way.
    if (isCadFileName(o.model)) {
        std::cerr << "acsynt: model " << o.model
                  << " is an IGES or STEP file: --export takes an aircraft description (.acm) or a saved "
                     "model; --import reads a CAD file into a session\n";
        return false;
    }
    return true;
}

/// Refuses a recording that would overwrite what the run reads (its script, its CAD file) or the
/// summary and log the session writes into the output folder at its end.
bool checkRecordTarget(const Options& o) {
    if (o.record.empty()) return true;
    const auto same = [&](const std::filesystem::path& other) {
        std::error_code recordError, otherError;
        const auto record = std::filesystem::weakly_canonical(o.record, recordError);
        const auto path = std::filesystem::weakly_canonical(other, otherError);
        return !recordError && !otherError && record == path;
    };
    std::string clash;
    if (!o.script.empty() && same(o.script)) clash = "is the script it would replace";
    if (!o.importFile.empty() && same(o.importFile)) clash = "is the --import file";
    for (const char* written : {"summary.txt", "acsynt.log"})
        if (same(o.output / written))
            clash = std::string("is the ") + written + " the session writes into --output";
    if (clash.empty()) return true;
    std::cerr << "acsynt: --record " << o.record << " " << clash << "\n";
    return false;
}

/// Refuses, before anything runs, a script that is not a readable file and a record or output
/// path that cannot be written.
bool checkPaths(const Options& o) {
    std::error_code ec;
    if (!o.importFile.empty()) {
        if (const std::string why = unreadable(o.importFile); !why.empty()) {
            std::cerr << "acsynt: --import " << o.importFile << " " << why << "\n";
            return false;
        }
        if (!checkCadName("--import", o.importFile)) return false;
    }
    if (!o.script.empty())
        if (const std::string why = unreadable(o.script); !why.empty()) {
            std::cerr << "acsynt: --script " << o.script << " " << why << "\n";
            return false;
        }
    if (!o.record.empty())
        if (const std::string why = unwritable(o.record); !why.empty()) {
            std::cerr << "acsynt: --record " << o.record << " " << why << "\n";
            return false;
        }
    std::filesystem::create_directories(o.output, ec);
    if (!std::filesystem::is_directory(o.output) || access(o.output.c_str(), W_OK) != 0) {
        std::cerr << "acsynt: --output " << o.output.string()
                  << (std::filesystem::exists(o.output) && !std::filesystem::is_directory(o.output)
                          ? " is not a directory\n"
                          : " cannot be created or written\n");
        return false;
    }
    return checkRecordTarget(o);
}

std::optional<Options> parse(int argc, char** argv) {
    static const option longOptions[] = {
        {"script", required_argument, nullptr, 's'}, {"output", required_argument, nullptr, 'o'},
        {"record", required_argument, nullptr, 'r'}, {"window", no_argument, nullptr, 'w'},
        {"size", required_argument, nullptr, 'z'},   {"keep-going", no_argument, nullptr, 'k'},
        {"export", required_argument, nullptr, 'e'}, {"import", required_argument, nullptr, 'i'},
        {"help", no_argument, nullptr, 'h'},         {nullptr, 0, nullptr, 0}};
    Options o;
    int c;
    while ((c = getopt_long(argc, argv, "s:o:r:wz:ke:i:h", longOptions, nullptr)) != -1) {
        switch (c) {
            case 'e':
                o.exportFile = optarg;
                break;
            case 'i':
                o.importFile = resolveInput(optarg);
                break;
            case 's':
                o.script = optarg;
                break;
            case 'o':
                o.output = optarg;
                break;
            case 'r':
                o.record = optarg;
                break;
            case 'w':
                o.window = true;
                break;
            case 'z':
                if (!parseSize(optarg, o.width, o.height)) {
                    std::cerr << "acsynt: --size wants WxH within 160x120 .. 4096x4096, not '" << optarg
                              << "'\n";
                    return std::nullopt;
                }
                break;
            case 'k':
                o.keepGoing = true;
                break;
            case 'h':
                usage(std::cout);
                std::exit(0);
            default:
                usage(std::cerr);
                return std::nullopt;
        }
    }
    if (!o.exportFile.empty()) {
        // --export OUT MODEL stands alone: no session runs.
        if (optind + 1 != argc || !o.script.empty() || o.window || !o.importFile.empty() ||
            !o.record.empty()) {
            usage(std::cerr);
            return std::nullopt;
        }
        o.model = resolveInput(argv[optind]);
        if (!checkExport(o)) return std::nullopt;
        return o;
    }
    if (optind < argc) std::cerr << "acsynt: unexpected argument '" << argv[optind] << "'\n";
    if (optind < argc || (o.script.empty() && !o.window) || (!o.script.empty() && o.window)) {
        usage(std::cerr);
        return std::nullopt;
    }
    // A script's screen has the display surface's 4:3 shape, within a pixel (Session's rule).
    if (!o.window && std::abs(4.0 * o.height - 3.0 * o.width) > 4.0) {
        std::cerr << "acsynt: --size " << o.width << "x" << o.height
                  << ": a script's screen is 4:3 like the display surface (1024x768, 800x600, ...)\n";
        return std::nullopt;
    }
    if (!checkPaths(o)) return std::nullopt;
    return o;
}

/// Writes `text` to `path`; false (with a message) when it could not be written whole.
bool writeFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    if (!out || !(out << text) || !out.flush()) {
        std::cerr << "acsynt: cannot write " << path.string() << "\n";
        return false;
    }
    return true;
}

/// Writes the summary, the log and the recording, prints what was written and returns the exit
/// status: only a session whose every line succeeded, and whose files were all written, gets 0.
int finish(acsynt::Session& session, const Options& o) {
    std::filesystem::create_directories(o.output);
    const auto summary = o.output / "summary.txt";
    const auto log = o.output / "acsynt.log";
    std::string logText;
    for (const auto& line : session.log()) logText += line + "\n";
    bool written = writeFile(summary, session.summary()) && writeFile(log, logText);
    const bool recorded = !o.record.empty() && writeFile(o.record, session.recording());
    if (!o.record.empty()) written = recorded && written;
    for (const auto& p : session.pictures()) std::cout << p.string() << "\n";
    for (const auto& p : session.hardcopies()) std::cout << p.string() << "\n";
    // A script's `summary summary` wrote the file the run's own summary then replaces: listed once.
    for (const auto& p : session.savedFiles())
        if (p != summary && p != log) std::cout << p.string() << "\n";
    std::cout << summary.string() << "\n" << log.string() << "\n";
    if (recorded) std::cout << o.record << "\n";  // only what was written
    if (!written) return kExitFatal;
    if (session.failedLines() == 0) return 0;
    const std::string source = o.window ? std::string("the window session") : o.script;
    std::cout << session.failedLines() << (session.failedLines() == 1 ? " error in " : " errors in ")
              << source << "\n";
    return o.window ? 0 : kExitLinesFailed;
}

/// --export: the model lofted from its description and written as IGES or STEP.
int exportModel(const Options& o) {
    try {
        // An aircraft description, or a model SAVE_MODEL wrote with its mapped curves.
        acsynt::ModelState state;
        if (acsynt::isModelStateFile(o.model))
            state = acsynt::readModelState(o.model);
        else
            state.model = acsynt::loadModel(o.model);
        acsynt::exchangeCalls().exportModel(state.model, state.mappings, o.exportFile);
        std::cout << o.exportFile << "\n";
        return 0;
    } catch (const std::exception& e) {  // a model file that does not parse, a file that cannot be written
        std::cerr << "acsynt: " << e.what() << "\n";
        return kExitFatal;
    }
}

/// --import: the CAD file read as the first model; false (with the reason) when it is refused.
bool importFirst(acsynt::Session& session, const Options& o) {
    if (o.importFile.empty() || session.importCadFile(o.importFile)) return true;
    std::cerr << "acsynt: --import " << session.message() << "\n";
    return false;
}

/// Keeps freed heap memory in the process rather than handing it back to the kernel at once. A
/// session allocates and frees picture-sized blocks all the time (read-backs, tessellations,
/// lavapipe's vertex and command memory); with glibc's defaults each came back as fresh pages
/// and page faults. One arena for all threads: lavapipe's queue thread then reuses what the
/// session freed (and the other way round) instead of growing an arena of its own; the threads
/// take turns (a picture is waited for), so they hardly contend.
void keepFreedHeap() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    mallopt(M_ARENA_MAX, 1);
}

/// Points the Vulkan loader at lavapipe's driver manifest alone when the session will use
/// lavapipe anyway (headless, PHIGS_VK_DEVICE not "hardware") and the user named no drivers: the
/// loader then neither loads nor initialises the hardware drivers and their memory. Nothing
/// changes when no manifest for this machine is found.
void onlyLavapipeDriver(const phigs::vk::ContextSettings& context) {
    if (context.device != phigs::vk::DevicePreference::Lavapipe || std::getenv("VK_DRIVER_FILES") ||
        std::getenv("VK_ICD_FILENAMES"))
        return;
    utsname machine{};
    if (uname(&machine) != 0) return;
    // The loader's search folders for driver manifests (XDG_DATA_DIRS, then /etc).
    std::string dataDirs = std::getenv("XDG_DATA_DIRS") ? std::getenv("XDG_DATA_DIRS") : "";
    if (dataDirs.empty()) dataDirs = "/usr/local/share:/usr/share";
    std::vector<std::filesystem::path> folders;
    for (std::size_t from = 0; from <= dataDirs.size();) {
        const std::size_t to = std::min(dataDirs.find(':', from), dataDirs.size());
        if (to > from)
            folders.push_back(std::filesystem::path(dataDirs.substr(from, to - from)) / "vulkan/icd.d");
        from = to + 1;
    }
    folders.emplace_back("/etc/vulkan/icd.d");
    const std::string names[] = {"lvp_icd." + std::string(machine.machine) + ".json", "lvp_icd.json"};
    for (const auto& folder : folders)
        for (const std::string& name : names) {
            std::error_code error;
            if (std::filesystem::is_regular_file(folder / name, error)) {
                setenv("VK_DRIVER_FILES", (folder / name).c_str(), 0);
                return;
            }
        }
}

}  // namespace

/// Runs the session on its one display (vk::WorkstationDisplay on the workstation's target):
/// headless, the script's snapshots; in a window, a picture whenever the workstation's picture
/// changed or the window lost it, the layout following the window's size. Between events the
/// window blocks in the input source's wait.
int runSession(const Options& options, acsynt::SessionSettings settings) {
    phigs::vk::ContextSettings defaults;
    defaults.validation = false;  // speed; PHIGS_VK_VALIDATION=1 turns it on
    const auto width = std::uint32_t(settings.width), height = std::uint32_t(settings.height);
    std::unique_ptr<phigs::InputSource> source;
#ifdef ACSYNT_HAVE_WINDOW
    std::unique_ptr<phigs::GlfwWindow> window;
#endif
    if (options.window) {
#ifdef ACSYNT_HAVE_WINDOW
        window = std::make_unique<phigs::GlfwWindow>(width, height, "ACSYNT B-SPLINE MODULE");
        source = std::make_unique<phigs::GlfwInputSource>(*window);
        settings.workstationType = phigs::WorkstationType::Window;
        defaults.device = phigs::vk::DevicePreference::Hardware;
#else
        std::cerr << "acsynt: built without the GLFW window source\n";
        return kExitUsage;
#endif
    } else {
        // lavapipe draws in this thread rather than its own pool (the user's LP_NUM_THREADS
        // wins): a script waits for each picture anyway, and the pool's per-thread tile bins
        // cost about 35 MB of peak memory and their hand-offs system time; the pictures are
        // the same, as the rasteriser's result does not depend on how it divides the work.
        setenv("LP_NUM_THREADS", "0", 0);
        source = std::make_unique<phigs::ScriptInputSource>(
            phigs::ScriptInputSource::fromFile(options.script, acsynt::Session::directives()));
    }
    phigs::vk::ContextSettings context = phigs::vk::ContextSettings::fromEnvironment(defaults);
    if (!options.window) onlyLavapipeDriver(context);
    context.printMessages = context.validation;
    // OPEN WORKSTATION makes the output (the one presentation path): an offscreen image, or
    // the window target in the program's window.
    settings.registerOutputs = [&](phigs::OutputRegistry& outputs) {
        phigs::vk::registerOutputs(outputs, context);
    };
    settings.connection.width = width;
    settings.connection.height = height;
#ifdef ACSYNT_HAVE_WINDOW
    if (window) settings.connection.settings = static_cast<phigs::vk::WindowSurface*>(window.get());
#endif
    acsynt::Session session(settings, *source);
    phigs::vk::WorkstationDisplay& display = phigs::vk::WorkstationDisplay::of(session.workstation());
    session.setSnapshot([&](const std::filesystem::path& file) { phigs::writePng(display.capture(), file); });
    // A script draws only for its snapshots: a vector hardcopy's describe step gets the images'
    // room (about 12.6 MB at 1024 x 768); the next snapshot makes them again.
    if (!options.window) session.setBeforeHardcopy([&] { display.releaseImages(); });
    if (!importFirst(session, options)) return kExitFatal;
    if (!options.window) {
        while (stopSignal == 0 && session.step(std::chrono::milliseconds(100))) {
        }
        return stopped(finish(session, options));
    }
#ifdef ACSYNT_HAVE_WINDOW
    acsynt::WindowPresentation presentation(session, *window, display);
    // The views' mouse and key navigation sees the window's events before the input devices.
    auto& events = static_cast<phigs::GlfwInputSource&>(*source);
    acsynt::ViewNavigation navigation(session, [&](const phigs::WindowEvent& e) { events.deliver(e); });
    events.setEventFilter([&](const phigs::WindowEvent& e) { return navigation.handle(e); });
    try {
        while (stopSignal == 0 && presentation.step(std::chrono::seconds(1))) {
        }
    } catch (const std::exception& e) {
        // The operator's work so far is kept: the summary, the log and the recording.
        std::cerr << "acsynt: " << e.what() << "\n";
        events.setEventFilter({});
        finish(session, options);
        return kExitFatal;
    }
    events.setEventFilter({});
#endif
    return stopped(finish(session, options));
}

int main(int argc, char** argv) {
    keepFreedHeap();
    const auto options = parse(argc, argv);
    if (!options) return kExitUsage;
    if (!options->exportFile.empty()) return exportModel(*options);
    acsynt::SessionSettings settings;
    settings.width = options->width;
    settings.height = options->height;
    settings.outputDirectory = options->output;
    settings.stopAtFirstError = !options->window && !options->keepGoing;
    catchStopSignals();
    try {
        return runSession(*options, settings);
    } catch (const std::exception& e) {
        std::cerr << "acsynt: " << e.what() << "\n";
        return kExitFatal;
    }
}
