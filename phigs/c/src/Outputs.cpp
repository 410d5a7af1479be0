// The drawing libraries libphigs links, registered for OPEN WORKSTATION.

#include "Binding.h"

#include "phigs/hardcopy/VectorOutput.h"
#include "phigs/vk/Outputs.h"
#ifdef PHIGS_C_HAVE_WINDOW
#include "phigs/window/WindowOutputs.h"
#endif

namespace phigs::c {

void registerOutputs(OutputRegistry& registry) {
    vk::ContextSettings defaults;
    defaults.validation = false;  // speed; PHIGS_VK_VALIDATION=1 turns it on
    vk::ContextSettings context = vk::ContextSettings::fromEnvironment(defaults);
    context.printMessages = context.validation;
    vk::registerOutputs(registry, context);
#ifdef PHIGS_C_HAVE_WINDOW
    registerWindowOutputs(registry, context);
#endif
    hardcopy::registerOutputs(registry);
}

}  // namespace phigs::c
