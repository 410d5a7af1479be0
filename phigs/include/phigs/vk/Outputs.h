#pragma once

#include "phigs/vk/Context.h"
#include "phigs/ws/OutputRegistry.h"

namespace phigs::vk {

/// Adds the Vulkan outputs (a WorkstationDisplay each) to `registry`:
/// - OffscreenImage: an image target; the connection identifier, when given, names a PNG
///   written at every presentation and on close;
/// - Hardcopy: the PNG hardcopy target; the identifier names the PNG (required: error 50);
/// - Window: the window target on the vk::WindowSurface* in the connection's settings (a window
///   the program made; phigs/window's registerOutputs opens one itself from a display name).
/// The offscreen and hardcopy outputs share one Context made from `context` at the first open;
/// a window has its own (the surface extensions).
void registerOutputs(OutputRegistry& registry, const ContextSettings& context);

}  // namespace phigs::vk
