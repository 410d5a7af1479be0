#include "acsynt/session/ModelExchange.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace acsynt {
namespace {

/// Opens the module once and keeps it open (its code backs the models it returns).
const ExchangeCalls& loadCalls() {
#ifdef ACSYNT_EXCHANGE_LINKED
    // A build with the module's code linked in (the fuzz targets): no file to open.
    return *acsynt_exchange_calls();
#else
    const char* path = ACSYNT_EXCHANGE_MODULE;
    void* module = dlopen(path, RTLD_NOW | RTLD_LOCAL);
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
