#include "acsynt/session/ModelExchange.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace acsynt {
namespace {

#ifndef ACSYNT_EXCHANGE_LINKED
/// The folder of the running program (empty when the system cannot say).
std::filesystem::path programFolder() {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : program.parent_path();
}

/// The first of the module's places that holds a file: next to the program (a build tree, or a
/// copy moved with it), the installed layout relative to the program's folder, the build tree's
/// path. A file found is the module, whether or not it loads.
std::filesystem::path modulePath() {
    const std::filesystem::path folder = programFolder();
    std::vector<std::filesystem::path> places;
    if (!folder.empty()) {
        places.push_back(folder / ACSYNT_EXCHANGE_MODULE_NAME);
        places.push_back(
            (folder / ACSYNT_EXCHANGE_INSTALL_DIR / ACSYNT_EXCHANGE_MODULE_NAME).lexically_normal());
    }
    places.emplace_back(ACSYNT_EXCHANGE_MODULE);
    for (const auto& place : places) {
        std::error_code error;
        if (std::filesystem::is_regular_file(place, error)) return place;
    }
    return places.back();
}
#endif

/// Opens the module once and keeps it open (its code backs the models it returns).
const ExchangeCalls& loadCalls() {
#ifdef ACSYNT_EXCHANGE_LINKED
    // A build with the module's code linked in (the fuzz targets): no file to open.
    return *acsynt_exchange_calls();
#else
    const std::string path = modulePath().string();
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    const char* why = module ? nullptr : dlerror();
    void* entry = module ? dlsym(module, "acsynt_exchange_calls") : nullptr;
    if (module && !entry) why = dlerror();
    if (!entry)
        throw std::runtime_error(std::string("IGES/STEP exchange module ") + path +
                                 " cannot be loaded: " + (why ? why : "no entry point"));
    using Entry = const ExchangeCalls* (*)();
    return *reinterpret_cast<Entry>(entry)();
#endif
}

}  // namespace

const ExchangeCalls& exchangeCalls() {
    static std::mutex mutex;
    static const ExchangeCalls* calls = nullptr;
    const std::lock_guard lock(mutex);
    if (!calls) calls = &loadCalls();  // a failed load throws and is tried again next time
    return *calls;
}

}  // namespace acsynt
