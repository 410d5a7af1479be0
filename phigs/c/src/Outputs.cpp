// The drawing libraries libphigs links, registered for OPEN WORKSTATION.

#include "Binding.h"
#include "Input.h"

#include "phigs/hardcopy/VectorOutput.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/Outputs.h"
#ifdef PHIGS_C_HAVE_WINDOW
#include "phigs/window/WindowOutputs.h"
#endif

#include <cstdio>
#include <stdexcept>

namespace phigs::c {

void registerOutputs(OutputRegistry& registry) {
    vk::ContextSettings defaults;
    defaults.validation = false;  // speed; PHIGS_VK_VALIDATION=1 turns it on
    vk::ContextSettings context = defaults;
    try {
        context = vk::ContextSettings::fromEnvironment(defaults);
    } catch (const std::invalid_argument& e) {  // a bad PHIGS_VK_DEVICE must not end the program
        std::fprintf(stderr, "libphigs: %s; using the defaults\n", e.what());
    }
    context.printMessages = context.validation;
    vk::registerOutputs(registry, context);
#ifdef PHIGS_C_HAVE_WINDOW
    registerWindowOutputs(registry, context);
#endif
    hardcopy::registerOutputs(registry);
}

InputSource* windowInputSource(Workstation& ws) {
#ifdef PHIGS_C_HAVE_WINDOW
    return ownWindowInputSource(ws.output());
#else
    (void)ws;
    return nullptr;
#endif
}

}  // namespace phigs::c
